// KalmanX: the Kalman filter of Kalman.h with its dimensions given at run time (Eigen dynamic matrices) instead of as
// template arguments. Same defaults, method names and equations (KalmanEquations.h).
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

#include "rtl/alg/kalman/KalmanEquations.h"

namespace rtl
{
    template<typename dtype>
    class KalmanX
    {
    public:
        using MatrixX = Eigen::Matrix<dtype, Eigen::Dynamic, Eigen::Dynamic>;
        using VectorX = Eigen::Matrix<dtype, Eigen::Dynamic, 1>;

        //! x = 0, A = I, B = 0, P = I, H = 0, Q = I * process_noise, R = I * observation_noise.
        //! \throws std::invalid_argument when state_dim or measurement_dim is 0 (control_dim may be 0).
        KalmanX(size_t state_dim, size_t measurement_dim, size_t control_dim, dtype process_noise, dtype observation_noise)
            : n(checkedDim(state_dim, "state_dim")), m(checkedDim(measurement_dim, "measurement_dim")),
              c(static_cast<Eigen::Index>(control_dim)), x(VectorX::Zero(n)), A(MatrixX::Identity(n, n)),
              B(MatrixX::Zero(n, c)), P(MatrixX::Identity(n, n)), H(MatrixX::Zero(m, n)),
              Q(MatrixX::Identity(n, n) * process_noise), R(MatrixX::Identity(m, m) * observation_noise),
              K(MatrixX::Zero(n, m))
        {
        }

        size_t state_dim() const { return static_cast<size_t>(n); }
        size_t measurement_dim() const { return static_cast<size_t>(m); }
        size_t control_dim() const { return static_cast<size_t>(c); }

        //! x = A x + B u;  P = A P A^T + Q.  \throws std::invalid_argument unless u has control_dim rows.
        void predict(const VectorX &control_input)
        {
            check(control_input, c, 1, "predict", "control_input");
            kalman_equations::predict(x, P, A, B, control_input, Q);
        }
        //! x = x + x_diff;  P = G P G^T + Q.  \throws std::invalid_argument on a dimension mismatch.
        void extended_predict(const VectorX &x_diff, const MatrixX &G_motion_jacobian)
        {
            check(x_diff, n, 1, "extended_predict", "x_diff");
            check(G_motion_jacobian, n, n, "extended_predict", "G_motion_jacobian");
            kalman_equations::extendedPredict(x, P, x_diff, G_motion_jacobian, Q);
        }
        //! Standard correction with H (Joseph-form covariance).  \throws std::invalid_argument on a dimension mismatch.
        void correct(const VectorX &z_measurement)
        {
            check(z_measurement, m, 1, "correct", "z_measurement");
            kalman_equations::correct(x, P, K, H, R, z_measurement);
        }
        //! Correction with the innovation z - h(x) and the measurement Jacobian.  \throws std::invalid_argument on a mismatch.
        void extended_correct(const VectorX &z_diff, const MatrixX &H_measurement_jacobian)
        {
            check(z_diff, m, 1, "extended_correct", "z_diff");
            check(H_measurement_jacobian, m, n, "extended_correct", "H_measurement_jacobian");
            kalman_equations::correctWithInnovation(x, P, K, H_measurement_jacobian, R, z_diff);
        }

        const VectorX &states() const { return x; }
        const MatrixX &covariance() const { return P; }
        //! The gain of the last correction (zero before any).
        const MatrixX &kalman_gain() { return K; }

        // Setters: \throws std::invalid_argument unless the argument has the documented size.
        void set_states(const VectorX &states) { x = checked(states, n, 1, "set_states"); }
        void set_transision_matrix(const MatrixX &transition) { A = checked(transition, n, n, "set_transision_matrix"); }   // sic, as in RTL
        void set_control_matrix(const MatrixX &control) { B = checked(control, n, c, "set_control_matrix"); }
        void set_covariance_matrix(const MatrixX &covariance) { P = checked(covariance, n, n, "set_covariance_matrix"); }
        void set_measurement_matrix(const MatrixX &measurement) { H = checked(measurement, m, n, "set_measurement_matrix"); }
        void set_process_noise_covariance_matrix(const MatrixX &noise) { Q = checked(noise, n, n, "set_process_noise_covariance_matrix"); }
        void set_measurement_noise_covariance_matrix(const MatrixX &noise) { R = checked(noise, m, m, "set_measurement_noise_covariance_matrix"); }

    private:
        static Eigen::Index checkedDim(size_t d, const char *name)
        {
            if (d == 0)
                throw std::invalid_argument(std::string("KalmanX: ") + name + " must be positive");
            return static_cast<Eigen::Index>(d);
        }
        template<class Mat>
        static void check(const Mat &mat, Eigen::Index rows, Eigen::Index cols, const char *method, const char *arg)
        {
            if (mat.rows() != rows || mat.cols() != cols)
                throw std::invalid_argument("KalmanX::" + std::string(method) + ": " + arg + " is " + std::to_string(mat.rows()) +
                                            " x " + std::to_string(mat.cols()) + ", expected " + std::to_string(rows) + " x " +
                                            std::to_string(cols));
        }
        template<class Mat>
        static const Mat &checked(const Mat &mat, Eigen::Index rows, Eigen::Index cols, const char *method)
        {
            check(mat, rows, cols, method, "argument");
            return mat;
        }

        Eigen::Index n, m, c;
        VectorX x;
        MatrixX A, B, P, H, Q, R, K;
    };
}
