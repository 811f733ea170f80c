// Kalman and KalmanX: against an independent textbook implementation of the equations (explicit inverse,
// P = (I - KH) P) on constant-velocity and constant-acceleration tracks, the extended variants, the default
// H = 0 keeping the state exactly 0, covariance symmetric positive definite over 1e5 steps, and KalmanX errors.
#include <cmath>
#include <random>
#include <stdexcept>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "rtl/Algorithms.h"

namespace
{
    // The textbook filter, written out independently of KalmanEquations.h.
    struct ReferenceKalman
    {
        Eigen::VectorXd x;
        Eigen::MatrixXd A, B, P, H, Q, R;

        void predict(const Eigen::VectorXd &u)
        {
            x = A * x + B * u;
            P = A * P * A.transpose() + Q;
        }
        void correctInnovation(const Eigen::VectorXd &innovation, const Eigen::MatrixXd &Hj)
        {
            const Eigen::MatrixXd K = P * Hj.transpose() * Eigen::MatrixXd((Hj * P * Hj.transpose() + R).fullPivLu().inverse());
            x = x + K * innovation;
            P = (Eigen::MatrixXd::Identity(P.rows(), P.cols()) - K * Hj) * P;
        }
        void correct(const Eigen::VectorXd &z) { correctInnovation(z - H * x, H); }
    };

    template<int R, int C>
    rtl::Matrix<R, C, double> fromEigen(const Eigen::MatrixXd &m)
    {
        return rtl::Matrix<R, C, double>(typename rtl::Matrix<R, C, double>::EigenType(m));
    }

    template<class MatA, class MatB>
    double maxAbsDiff(const MatA &a, const MatB &b)
    {
        return (a.template cast<double>() - b).cwiseAbs().maxCoeff();
    }

    // Constant-acceleration model with position measurements and dt = 0.1.
    Eigen::MatrixXd caTransition(double dt)
    {
        Eigen::MatrixXd A(3, 3);
        A << 1, dt, dt * dt / 2, 0, 1, dt, 0, 0, 1;
        return A;
    }
}

TEST(Kalman, DefaultMeasurementMatrixKeepsStateExactlyZero)
{
    rtl::Kalman<double, 2, 1, 1> kf(0.1, 0.5);
    rtl::Kalman<float, 3, 2, 0> kf3(1.0f, 2.0f);
    rtl::KalmanX<double> kx(2, 1, 1, 0.1, 0.5);
    for (int i = 0; i < 50; ++i)
    {
        rtl::Matrix<1, 1, double> u, z;
        u(0, 0) = 1.0 + i;
        z(0, 0) = 10.0 * i - 3;
        kf.predict(u);
        kf.correct(z);
        kf3.predict(rtl::Matrix<0, 1, float>());
        kf3.correct(rtl::Matrix<2, 1, float>::ones() * 7.0f);
        kx.predict(u.data());
        kx.correct(z.data());
    }
    for (size_t r = 0; r < 2; ++r)
    {
        EXPECT_EQ(kf.states()(r, 0), 0.0);
        EXPECT_EQ(kx.states()(static_cast<Eigen::Index>(r)), 0.0);
    }
    for (size_t r = 0; r < 3; ++r)
        EXPECT_EQ(kf3.states()(r, 0), 0.0f);
    EXPECT_EQ(kf.kalman_gain(), (rtl::Matrix<2, 1, double>::zeros()));
    // P grows by Q each step: 1 + 50 * 0.1 on the diagonal, nothing off it (A = I, H = 0).
    EXPECT_NEAR(kf.covariance()(0, 0), 6.0, 1e-12);
    EXPECT_EQ(kf.covariance()(0, 1), 0.0);
}

TEST(Kalman, ConstantVelocityTrackMatchesReferenceAndConverges)
{
    const double dt = 0.1, v = 2.0, x0 = -4.0, sigma = 0.5;
    Eigen::MatrixXd A(2, 2), B(2, 1), H(1, 2);
    A << 1, dt, 0, 1;
    B << dt * dt / 2, dt;       // the control is an acceleration (zero here, non-zero in the next test)
    H << 1, 0;
    rtl::Kalman<double, 2, 1, 1> kf(1e-4, sigma * sigma);
    kf.set_transision_matrix(fromEigen<2, 2>(A));
    kf.set_control_matrix(fromEigen<2, 1>(B));
    kf.set_measurement_matrix(fromEigen<1, 2>(H));
    kf.set_covariance_matrix(fromEigen<2, 2>(Eigen::MatrixXd::Identity(2, 2) * 100.0));
    ReferenceKalman ref{Eigen::VectorXd::Zero(2), A, B, Eigen::MatrixXd::Identity(2, 2) * 100.0, H,
                        Eigen::MatrixXd::Identity(2, 2) * 1e-4, Eigen::MatrixXd::Identity(1, 1) * sigma * sigma};
    std::mt19937 rng(3);
    std::normal_distribution<double> noise(0.0, sigma);
    double worst = 0;
    for (int k = 1; k <= 400; ++k)
    {
        const Eigen::VectorXd u = Eigen::VectorXd::Zero(1);
        const Eigen::VectorXd z = Eigen::VectorXd::Constant(1, x0 + v * dt * k + noise(rng));
        kf.predict(fromEigen<1, 1>(u));
        kf.correct(fromEigen<1, 1>(z));
        ref.predict(u);
        ref.correct(z);
        worst = std::max({worst, maxAbsDiff(kf.states().data(), ref.x), maxAbsDiff(kf.covariance().data(), ref.P)});
    }
    EXPECT_LT(worst, 1e-10);
    EXPECT_NEAR(kf.states()(0, 0), x0 + v * dt * 400, 0.3);
    EXPECT_NEAR(kf.states()(1, 0), v, 0.1);
    // The steady-state position variance is below the measurement's.
    EXPECT_LT(kf.covariance()(0, 0), sigma * sigma);
    EXPECT_GT(kf.covariance()(0, 0), 0.0);
}

TEST(Kalman, ConstantAccelerationTrackMatchesReference)
{
    // Model 1: a 3-state constant-acceleration filter. Model 2: a constant-velocity filter driven by the known
    // acceleration as control input. Both follow x(t) = 1 + 0.5 t + 0.15 t^2 measured with noise.
    const double dt = 0.1, a = 0.3, sigma = 0.2;
    auto truth = [&](double t) { return 1.0 + 0.5 * t + 0.5 * a * t * t; };
    Eigen::MatrixXd H3(1, 3), H2(1, 2), A2(2, 2), B2(2, 1);
    H3 << 1, 0, 0;
    H2 << 1, 0;
    A2 << 1, dt, 0, 1;
    B2 << dt * dt / 2, dt;
    rtl::Kalman<double, 3, 1, 0> ca(1e-6, sigma * sigma);
    ca.set_transision_matrix(fromEigen<3, 3>(caTransition(dt)));
    ca.set_measurement_matrix(fromEigen<1, 3>(H3));
    rtl::KalmanX<double> cv(2, 1, 1, 1e-6, sigma * sigma);
    cv.set_transision_matrix(A2);
    cv.set_control_matrix(B2);
    cv.set_measurement_matrix(H2);
    ReferenceKalman ref3{Eigen::VectorXd::Zero(3), caTransition(dt), Eigen::MatrixXd::Zero(3, 0), Eigen::MatrixXd::Identity(3, 3),
                         H3, Eigen::MatrixXd::Identity(3, 3) * 1e-6, Eigen::MatrixXd::Identity(1, 1) * sigma * sigma};
    ReferenceKalman ref2{Eigen::VectorXd::Zero(2), A2, B2, Eigen::MatrixXd::Identity(2, 2), H2,
                         Eigen::MatrixXd::Identity(2, 2) * 1e-6, Eigen::MatrixXd::Identity(1, 1) * sigma * sigma};
    std::mt19937 rng(5);
    std::normal_distribution<double> noise(0.0, sigma);
    double worst = 0;
    const int steps = 300;
    for (int k = 1; k <= steps; ++k)
    {
        const Eigen::VectorXd z = Eigen::VectorXd::Constant(1, truth(dt * k) + noise(rng));
        const Eigen::VectorXd u = Eigen::VectorXd::Constant(1, a);
        ca.predict(rtl::Matrix<0, 1, double>());
        ca.correct(fromEigen<1, 1>(z));
        ref3.predict(Eigen::VectorXd::Zero(0));
        ref3.correct(z);
        cv.predict(u);
        cv.correct(z);
        ref2.predict(u);
        ref2.correct(z);
        worst = std::max({worst, maxAbsDiff(ca.states().data(), ref3.x), maxAbsDiff(ca.covariance().data(), ref3.P),
                          maxAbsDiff(cv.states(), ref2.x), maxAbsDiff(cv.covariance(), ref2.P)});
    }
    EXPECT_LT(worst, 1e-9);
    const double t = dt * steps;
    EXPECT_NEAR(ca.states()(0, 0), truth(t), 0.2);
    EXPECT_NEAR(ca.states()(1, 0), 0.5 + a * t, 0.3);
    EXPECT_NEAR(ca.states()(2, 0), a, 0.1);
    EXPECT_NEAR(cv.states()(1), 0.5 + a * t, 0.1);
    EXPECT_EQ(cv.kalman_gain().rows(), 2);
    EXPECT_NEAR(cv.kalman_gain()(0), (ref2.P * H2.transpose() / sigma / sigma)(0), 1e-9);    // K = P+ H^T R^-1
}

TEST(Kalman, ExtendedMatchesReferenceOnRangeMeasurements)
{
    // 2-D constant-velocity target [px, py, vx, vy] seen by its range from the origin (h(x) = |p|) and,
    // every other step, by its bearing-free position x only. The motion is nonlinear-free, so extended_predict
    // gets dx = (A - I) x and G = A: the same numbers as predict().
    const double dt = 0.5, sigma = 0.1;
    Eigen::MatrixXd A = Eigen::MatrixXd::Identity(4, 4);
    A(0, 2) = dt;
    A(1, 3) = dt;
    rtl::Kalman<double, 4, 1, 0> ekf(1e-3, sigma * sigma);
    rtl::KalmanX<double> ekx(4, 1, 0, 1e-3, sigma * sigma);
    Eigen::VectorXd x0(4);
    x0 << 8, 1, 0.5, 1.2;      // the initial guess, off the truth (10, 0, 0.4, 1)
    ekf.set_states(fromEigen<4, 1>(x0));
    ekx.set_states(x0);
    ReferenceKalman ref{x0, A, Eigen::MatrixXd::Zero(4, 0), Eigen::MatrixXd::Identity(4, 4), Eigen::MatrixXd::Zero(1, 4),
                        Eigen::MatrixXd::Identity(4, 4) * 1e-3, Eigen::MatrixXd::Identity(1, 1) * sigma * sigma};
    std::mt19937 rng(7);
    std::normal_distribution<double> noise(0.0, sigma);
    double worst = 0;
    Eigen::Vector2d p(10, 0), vel(0.4, 1);
    for (int k = 1; k <= 200; ++k)
    {
        p += vel * dt;
        Eigen::VectorXd dx = (A - Eigen::MatrixXd::Identity(4, 4)) * ekf.states().data();
        rtl::Matrix<4, 1, double> dxm = fromEigen<4, 1>(dx);
        rtl::Matrix<4, 4, double> G = fromEigen<4, 4>(A);
        ekf.extended_predict(dxm, G);
        ekx.extended_predict((A - Eigen::MatrixXd::Identity(4, 4)) * ekx.states(), A);
        ref.predict(Eigen::VectorXd::Zero(0));
        // Linearise h at the predicted state of each filter.
        auto jacobian = [](const Eigen::VectorXd &s) {
            Eigen::MatrixXd J = Eigen::MatrixXd::Zero(1, 4);
            const double r = std::hypot(s(0), s(1));
            J(0, 0) = s(0) / r;
            J(0, 1) = s(1) / r;
            return J;
        };
        const double z = p.norm() + noise(rng);
        const Eigen::VectorXd sf = ekf.states().data(), sx = ekx.states(), sr = ref.x;
        ekf.extended_correct(fromEigen<1, 1>(Eigen::VectorXd::Constant(1, z - std::hypot(sf(0), sf(1)))), fromEigen<1, 4>(jacobian(sf)));
        ekx.extended_correct(Eigen::VectorXd::Constant(1, z - std::hypot(sx(0), sx(1))), jacobian(sx));
        ref.correctInnovation(Eigen::VectorXd::Constant(1, z - std::hypot(sr(0), sr(1))), jacobian(sr));
        worst = std::max({worst, maxAbsDiff(ekf.states().data(), ref.x), maxAbsDiff(ekx.states(), ref.x),
                          maxAbsDiff(ekf.covariance().data(), ref.P)});
    }
    EXPECT_LT(worst, 1e-8);
    // The range alone cannot separate some motions, but the range itself is tracked closely.
    EXPECT_NEAR(std::hypot(ekf.states()(0, 0), ekf.states()(1, 0)), p.norm(), 0.1);
}

TEST(Kalman, CovarianceStaysSymmetricPositiveDefiniteOver1e5Steps)
{
    // Float, tiny process noise, precise measurements of position only: the setting where P = (I - KH) P drifts
    // out of symmetry and definiteness; Joseph form plus symmetrisation must keep it SPD at every step.
    const float dt = 0.01f;
    rtl::Matrix<3, 3, float> A = fromEigen<3, 3>(caTransition(dt)).cast<float>();
    rtl::Matrix<1, 3, float> H;
    H(0, 0) = 1;
    rtl::Kalman<float, 3, 1, 0> kf(1e-9f, 1e-4f);
    kf.set_transision_matrix(A);
    kf.set_measurement_matrix(H);
    kf.set_covariance_matrix(rtl::Matrix<3, 3, float>::identity() * 1e4f);
    rtl::KalmanX<double> kx(3, 1, 0, 1e-12, 1e-6);
    kx.set_transision_matrix(caTransition(0.01));
    Eigen::MatrixXd Hx = Eigen::MatrixXd::Zero(1, 3);
    Hx(0, 0) = 1;
    kx.set_measurement_matrix(Hx);
    std::mt19937 rng(11);
    std::normal_distribution<float> noise(0.0f, 0.01f);
    int asymmetric = 0, indefinite = 0;
    for (int k = 0; k < 100000; ++k)
    {
        const float t = dt * static_cast<float>(k);
        rtl::Matrix<1, 1, float> z;
        z(0, 0) = 0.5f * t * t + noise(rng);
        kf.predict(rtl::Matrix<0, 1, float>());
        kf.correct(z);
        kx.predict(Eigen::VectorXd::Zero(0));
        kx.correct(z.data().cast<double>());
        const Eigen::Matrix3f P = kf.covariance().data();
        if (P != P.transpose() || kx.covariance() != kx.covariance().transpose())
            ++asymmetric;
        if (P.llt().info() != Eigen::Success || kx.covariance().llt().info() != Eigen::Success)
            ++indefinite;
    }
    EXPECT_EQ(asymmetric, 0);
    EXPECT_EQ(indefinite, 0);
    EXPECT_FALSE(kf.covariance().hasNaN());
    // Float cannot resolve 0.01 at 0.5 t^2 = 5e5 (its spacing there is 0.03): the position to 1e-5 relative,
    // the acceleration from the double filter.
    const double t_end = 0.01 * 99999;
    EXPECT_NEAR(kf.states()(0, 0), 0.5 * t_end * t_end, 0.5 * t_end * t_end * 1e-5);
    EXPECT_NEAR(kx.states()(2), 1.0, 1e-3);
}

TEST(Kalman, KalmanXDimensionsAreChecked)
{
    EXPECT_THROW(rtl::KalmanX<double>(0, 1, 0, 1, 1), std::invalid_argument);
    EXPECT_THROW(rtl::KalmanX<double>(2, 0, 0, 1, 1), std::invalid_argument);
    rtl::KalmanX<double> k(2, 1, 1, 0.5, 2.0);
    EXPECT_EQ(k.state_dim(), 2u);
    EXPECT_EQ(k.covariance(), Eigen::MatrixXd::Identity(2, 2));
    EXPECT_THROW(k.predict(Eigen::VectorXd::Zero(2)), std::invalid_argument);
    EXPECT_THROW(k.correct(Eigen::VectorXd::Zero(2)), std::invalid_argument);
    EXPECT_THROW(k.extended_predict(Eigen::VectorXd::Zero(2), Eigen::MatrixXd::Zero(2, 3)), std::invalid_argument);
    EXPECT_THROW(k.extended_correct(Eigen::VectorXd::Zero(1), Eigen::MatrixXd::Zero(2, 2)), std::invalid_argument);
    EXPECT_THROW(k.set_states(Eigen::VectorXd::Zero(3)), std::invalid_argument);
    EXPECT_THROW(k.set_transision_matrix(Eigen::MatrixXd::Zero(2, 1)), std::invalid_argument);
    EXPECT_THROW(k.set_control_matrix(Eigen::MatrixXd::Zero(2, 2)), std::invalid_argument);
    EXPECT_THROW(k.set_covariance_matrix(Eigen::MatrixXd::Zero(1, 1)), std::invalid_argument);
    EXPECT_THROW(k.set_measurement_matrix(Eigen::MatrixXd::Zero(2, 1)), std::invalid_argument);
    EXPECT_THROW(k.set_process_noise_covariance_matrix(Eigen::MatrixXd::Zero(3, 3)), std::invalid_argument);
    EXPECT_THROW(k.set_measurement_noise_covariance_matrix(Eigen::MatrixXd::Zero(2, 2)), std::invalid_argument);
    // A rejected call changes nothing.
    EXPECT_EQ(k.states(), Eigen::VectorXd::Zero(2));
    EXPECT_EQ(k.covariance(), Eigen::MatrixXd::Identity(2, 2));
}
