// Kalman: a linear (and extended) Kalman filter with compile-time dimensions on rtl::Matrix.
// The equations are in KalmanEquations.h, shared with the runtime-size KalmanX.
//
// Complexity: predict and correct are O(S^3 + M^3) for S states and M measurements (matrix products and one M x M
// inversion); fixed sizes, no allocation. Invariant: the covariance stays symmetric (Joseph-form update).
// Precondition for correct: H P H^T + R is invertible (R positive definite suffices).
#pragma once

#include <cstddef>

#include "rtl/alg/kalman/KalmanEquations.h"
#include "rtl/core/Matrix.h"

namespace rtl
{
    template<typename dtype, size_t state_dim, size_t measurement_dim, size_t control_dim>
    class Kalman
    {
        static constexpr int S = static_cast<int>(state_dim);
        static constexpr int M = static_cast<int>(measurement_dim);
        static constexpr int C = static_cast<int>(control_dim);

    public:
        //! x = 0, A = I, B = 0, P = I, H = 0, Q = I * process_noise, R = I * observation_noise.
        //! With the default H = 0 the gain is exactly 0, so corrections leave the state unchanged.
        Kalman(dtype process_noise, dtype observation_noise)
            : x(Matrix<S, 1, dtype>::zeros()), A(Matrix<S, S, dtype>::identity()), B(Matrix<S, C, dtype>::zeros()),
              P(Matrix<S, S, dtype>::identity()), H(Matrix<M, S, dtype>::zeros()),
              Q(Matrix<S, S, dtype>::identity() * process_noise), R(Matrix<M, M, dtype>::identity() * observation_noise),
              K(Matrix<S, M, dtype>::zeros())
        {
        }

        //! x = A x + B u;  P = A P A^T + Q.
        void predict(Matrix<C, 1, dtype> control_input)
        {
            kalman_equations::predict(x.data(), P.data(), A.data(), B.data(), control_input.data(), Q.data());
        }
        //! x = x + x_diff;  P = G P G^T + Q.
        void extended_predict(Matrix<S, 1, dtype> &x_diff, Matrix<S, S, dtype> &G_motion_jacobian)
        {
            kalman_equations::extendedPredict(x.data(), P.data(), x_diff.data(), G_motion_jacobian.data(), Q.data());
        }
        //! K = P H^T (H P H^T + R)^-1;  x = x + K (z - H x);  P = (I - K H) P (Joseph form).
        void correct(Matrix<M, 1, dtype> z_measurement)
        {
            kalman_equations::correct(x.data(), P.data(), K.data(), H.data(), R.data(), z_measurement.data());
        }
        //! As correct(), with the innovation z_diff = z - h(x) and the measurement Jacobian in place of H.
        void extended_correct(Matrix<M, 1, dtype> z_diff, Matrix<M, S, dtype> H_measurement_jacobian)
        {
            kalman_equations::correctWithInnovation(x.data(), P.data(), K.data(), H_measurement_jacobian.data(), R.data(),
                                                    z_diff.data());
        }

        const Matrix<S, 1, dtype> &states() const { return x; }
        const Matrix<S, S, dtype> &covariance() const { return P; }
        //! The gain of the last correction (zero before any).
        const Matrix<S, M, dtype> &kalman_gain() { return K; }

        void set_states(const Matrix<S, 1, dtype> &states) { x = states; }
        void set_transision_matrix(const Matrix<S, S, dtype> &transition) { A = transition; }    // sic, as in RTL
        void set_control_matrix(const Matrix<S, C, dtype> &control) { B = control; }
        void set_covariance_matrix(const Matrix<S, S, dtype> &covariance) { P = covariance; }
        void set_measurement_matrix(const Matrix<M, S, dtype> &measurement) { H = measurement; }
        void set_process_noise_covariance_matrix(const Matrix<S, S, dtype> &process_noise) { Q = process_noise; }
        void set_measurement_noise_covariance_matrix(const Matrix<M, M, dtype> &measurement_noise) { R = measurement_noise; }

    private:
        Matrix<S, 1, dtype> x;
        Matrix<S, S, dtype> A;
        Matrix<S, C, dtype> B;
        Matrix<S, S, dtype> P;
        Matrix<M, S, dtype> H;
        Matrix<S, S, dtype> Q;
        Matrix<M, M, dtype> R;
        Matrix<S, M, dtype> K;
    };
}
