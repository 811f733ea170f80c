// Kalman: estimate position and velocity of a constant-velocity target from noisy positions,
// with the compile-time Kalman and the same filter in the runtime-size KalmanX.
#include <cmath>
#include <iostream>
#include <random>

#include "rtl/Algorithms.h"

int main()
{
    const double dt = 0.1, sigma = 0.5;
    rtl::Kalman<double, 2, 1, 1> kf(1e-4, sigma * sigma);      // process noise Q = 1e-4 I, measurement noise R = sigma^2
    rtl::Matrix<2, 2, double> A = rtl::Matrix<2, 2, double>::identity();
    A(0, 1) = dt;                                               // x += v dt
    rtl::Matrix<1, 2, double> H;
    H(0, 0) = 1;                                                // only the position is measured
    kf.set_transision_matrix(A);
    kf.set_measurement_matrix(H);
    kf.set_covariance_matrix(rtl::Matrix<2, 2, double>::identity() * 100.0);   // unsure start

    rtl::KalmanX<double> kx(2, 1, 1, 1e-4, sigma * sigma);
    kx.set_transision_matrix(A.data());
    kx.set_measurement_matrix(H.data());
    kx.set_covariance_matrix(Eigen::MatrixXd::Identity(2, 2) * 100.0);

    std::mt19937 rng(3);
    std::normal_distribution<double> noise(0.0, sigma);
    const double v = 1.5;
    for (int k = 1; k <= 200; ++k)
    {
        rtl::Matrix<1, 1, double> z;
        z(0, 0) = v * dt * k + noise(rng);
        kf.predict(rtl::Matrix<1, 1, double>());
        kf.correct(z);
        kx.predict(Eigen::VectorXd::Zero(1));
        kx.correct(z.data());
        if (k % 50 == 0)
            std::cout << "t " << dt * k << ": position " << kf.states()(0, 0) << " (true " << v * dt * k << "), velocity "
                      << kf.states()(1, 0) << " (true " << v << "), position sd " << std::sqrt(kf.covariance()(0, 0)) << "\n";
    }
    const bool same = std::abs(kx.states()(0) - kf.states()(0, 0)) < 1e-9;
    return same && std::abs(kf.states()(1, 0) - v) < 0.1 ? 0 : 1;
}
