// The Kalman filter equations, once, for any Eigen matrix types (fixed-size in Kalman, dynamic in KalmanX).
//
// The covariance update uses the Joseph form P = (I - KH) P (I - KH)^T + K R K^T followed by symmetrisation
// 0.5 (P + P^T): unlike P = (I - KH) P it stays symmetric positive (semi)definite under rounding, for any gain.
#pragma once

#include <Eigen/Dense>

namespace rtl::kalman_equations
{
    //! x = A x + B u;  P = A P A^T + Q.
    template<class Vec, class Cov, class MatA, class MatB, class VecU, class MatQ>
    void predict(Vec &x, Cov &P, const MatA &A, const MatB &B, const VecU &u, const MatQ &Q)
    {
        x = (A * x + B * u).eval();
        P = (A * P * A.transpose() + Q).eval();
        P = (typename Cov::Scalar(0.5) * (P + P.transpose())).eval();
    }

    //! x = x + dx;  P = G P G^T + Q (G: Jacobian of the motion model at x).
    template<class Vec, class Cov, class VecD, class MatG, class MatQ>
    void extendedPredict(Vec &x, Cov &P, const VecD &dx, const MatG &G, const MatQ &Q)
    {
        x += dx;
        P = (G * P * G.transpose() + Q).eval();
        P = (typename Cov::Scalar(0.5) * (P + P.transpose())).eval();
    }

    //! K = P H^T (H P H^T + R)^-1;  x = x + K innovation;  P in Joseph form. Precondition: H P H^T + R invertible.
    template<class Vec, class Cov, class Gain, class MatH, class MatR, class VecZ>
    void correctWithInnovation(Vec &x, Cov &P, Gain &K, const MatH &H, const MatR &R, const VecZ &innovation)
    {
        const auto S = (H * P * H.transpose() + R).eval();
        // K^T = S^-1 H P (S and P symmetric); an LDLT solve avoids forming S^-1 (zero pivots give a zero gain).
        const auto K_transposed = S.ldlt().solve((H * P).eval()).eval();
        K = K_transposed.transpose();
        x = (x + K * innovation).eval();
        const auto I_KH = (Cov::Identity(P.rows(), P.cols()) - K * H).eval();
        P = (I_KH * P * I_KH.transpose() + K * R * K.transpose()).eval();
        P = (typename Cov::Scalar(0.5) * (P + P.transpose())).eval();
    }

    //! Linear correction: innovation z - H x.
    template<class Vec, class Cov, class Gain, class MatH, class MatR, class VecZ>
    void correct(Vec &x, Cov &P, Gain &K, const MatH &H, const MatR &R, const VecZ &z)
    {
        const auto innovation = (z - H * x).eval();
        correctWithInnovation(x, P, K, H, R, innovation);
    }
}
