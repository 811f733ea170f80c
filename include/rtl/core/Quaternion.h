// Quaternion: w + x i + y j + z k on top of Eigen::Quaternion, mainly used as a 3D rotation representation.
//
// Roll-pitch-yaw convention: q(roll, pitch, yaw) = Rx(roll) Ry(pitch) Rz(yaw) (intrinsic X-Y-Z), and rpy() returns
// roll, yaw in (-pi, pi] and pitch in [-pi/2, pi/2] (yaw = 0 at the gimbal lock |pitch| = pi/2).
// The default constructor zero-initialises all four coefficients, like the other core types (it is NOT the identity).
//
// Complexity: O(1), no allocation. Arithmetic (+, -, scalar * and /) acts on the four coefficients as a 4-vector;
// * is the Hamilton product. Preconditions: rotMat(), slerp() and rpy() treat the quaternion as a rotation and
// need a unit quaternion; inverted() needs a non-zero one (it is the conjugate over the squared norm, exact for
// any norm). The (v_from, v_to) constructor needs two non-zero vectors.
#pragma once

#include <cmath>
#include <limits>
#include <type_traits>

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include "rtl/core/VectorND.h"
#include "rtl/core/Matrix.h"

namespace rtl
{
    template<typename Element>
    class Quaternion
    {
    public:
        typedef Element ElementType;
        typedef VectorND<3, Element> VectorType;
        typedef Eigen::Quaternion<ElementType> EigenType;

        Quaternion() : quat(ElementType(0), ElementType(0), ElementType(0), ElementType(0)) {}
        explicit Quaternion(const EigenType &eq) : quat(eq) {}
        Quaternion(ElementType w, ElementType x, ElementType y, ElementType z) : quat(w, x, y, z) {}
        Quaternion(const Quaternion &q) = default;
        //! Rotation by `angle` (radians, right-handed) about `axis`; the axis need not be unit length (precondition: non-zero).
        Quaternion(ElementType angle, const VectorType &axis)
                : quat(Eigen::AngleAxis<ElementType>(angle, typename VectorType::EigenType(axis.data().normalized()))) {}
        //! The shortest rotation taking the direction of v_from to that of v_to.
        Quaternion(const VectorType &v_from, const VectorType &v_to) : quat(EigenType::FromTwoVectors(v_from.data(), v_to.data())) {}
        //! Rx(roll) Ry(pitch) Rz(yaw).
        Quaternion(ElementType roll, ElementType pitch, ElementType yaw)
                : quat(Eigen::AngleAxis<ElementType>(roll, Eigen::Matrix<ElementType, 3, 1>::UnitX())
                       * Eigen::AngleAxis<ElementType>(pitch, Eigen::Matrix<ElementType, 3, 1>::UnitY())
                       * Eigen::AngleAxis<ElementType>(yaw, Eigen::Matrix<ElementType, 3, 1>::UnitZ())) {}
        ~Quaternion() = default;

        [[nodiscard]] EigenType &data() { return quat; }
        [[nodiscard]] const EigenType &data() const { return quat; }

        [[nodiscard]] ElementType w() const { return quat.w(); }
        [[nodiscard]] ElementType x() const { return quat.x(); }
        [[nodiscard]] ElementType y() const { return quat.y(); }
        [[nodiscard]] ElementType z() const { return quat.z(); }
        [[nodiscard]] ElementType scalar() const { return quat.w(); }
        [[nodiscard]] VectorType vector() const { return VectorType(quat.x(), quat.y(), quat.z()); }

        //! Decomposes the rotation of this (unit) quaternion as Rx(roll) Ry(pitch) Rz(yaw); see the header comment for ranges.
        void rpy(ElementType &roll, ElementType &pitch, ElementType &yaw) const
        {
            const Eigen::Matrix<ElementType, 3, 3> r = quat.normalized().toRotationMatrix();
            // R = Rx Ry Rz: R02 = sin p, R12 = -sin r cos p, R22 = cos r cos p, R01 = -cos p sin y, R00 = cos p cos y.
            const ElementType cp = std::hypot(r(0, 0), r(0, 1));
            pitch = std::atan2(r(0, 2), cp);
            if (cp > ElementType(16) * std::numeric_limits<ElementType>::epsilon())
            {
                roll = std::atan2(-r(1, 2), r(2, 2));
                yaw = std::atan2(-r(0, 1), r(0, 0));
            }
            else
            {   // gimbal lock: only roll +- yaw is defined; put it all in roll (then R21 = sin r, R11 = cos r)
                roll = std::atan2(r(2, 1), r(1, 1));
                yaw = ElementType(0);
            }
        }

        void setW(ElementType w) { quat.w() = w; }
        void setX(ElementType x) { quat.x() = x; }
        void setY(ElementType y) { quat.y() = y; }
        void setZ(ElementType z) { quat.z() = z; }
        void setScalar(ElementType s) { quat.w() = s; }
        void setVector(const VectorType &v) { quat.vec() = v.data(); }

        //! Spherical linear interpolation from *this (scale 0) to q (scale 1), as Eigen's slerp.
        [[nodiscard]] Quaternion slerp(const Quaternion &q, ElementType scale) const { return Quaternion(quat.slerp(scale, q.quat)); }

        Quaternion &operator=(const Quaternion &q) = default;
        Quaternion &operator=(const EigenType &eq) { quat = eq; return *this; }

        // Addition, subtraction and scaling act on the four coefficients.
        Quaternion operator+(const Quaternion &q) const { return fromCoeffs(quat.coeffs() + q.quat.coeffs()); }
        Quaternion &operator+=(const Quaternion &q) { quat.coeffs() += q.quat.coeffs(); return *this; }
        Quaternion operator-(const Quaternion &q) const { return fromCoeffs(quat.coeffs() - q.quat.coeffs()); }
        Quaternion &operator-=(const Quaternion &q) { quat.coeffs() -= q.quat.coeffs(); return *this; }
        Quaternion operator-() const { return fromCoeffs(-quat.coeffs()); }
        //! Hamilton product.
        Quaternion operator*(const Quaternion &q) const { return Quaternion(EigenType(quat * q.quat)); }
        Quaternion &operator*=(const Quaternion &q) { quat = quat * q.quat; return *this; }
        Quaternion operator*(ElementType s) const { return fromCoeffs(quat.coeffs() * s); }
        Quaternion &operator*=(ElementType s) { quat.coeffs() *= s; return *this; }
        Quaternion operator/(ElementType s) const { return fromCoeffs(quat.coeffs() / s); }
        Quaternion &operator/=(ElementType s) { quat.coeffs() /= s; return *this; }

        [[nodiscard]] ElementType norm() const { return quat.norm(); }
        [[nodiscard]] ElementType normSquared() const { return quat.squaredNorm(); }
        void normalize() { quat.normalize(); }
        [[nodiscard]] Quaternion normalized() const { return Quaternion(EigenType(quat.normalized())); }
        //! The multiplicative inverse conjugate / |q|^2 (precondition: non-zero).
        void invert() { quat = quat.inverse(); }
        [[nodiscard]] Quaternion inverted() const { return Quaternion(EigenType(quat.inverse())); }
        void conjugate() { quat = quat.conjugate(); }
        [[nodiscard]] Quaternion conjugated() const { return Quaternion(EigenType(quat.conjugate())); }

        //! The rotation matrix of this quaternion (precondition: unit length; identity gives an exact identity matrix).
        [[nodiscard]] Matrix<3, 3, ElementType> rotMat() const
        {
            return Matrix<3, 3, ElementType>(typename Matrix<3, 3, ElementType>::EigenType(quat.toRotationMatrix()));
        }

        //! Euclidean distance of the coefficient vectors.
        static ElementType distance(const Quaternion &q1, const Quaternion &q2) { return (q2.quat.coeffs() - q1.quat.coeffs()).norm(); }
        static ElementType distanceSquared(const Quaternion &q1, const Quaternion &q2) { return (q2.quat.coeffs() - q1.quat.coeffs()).squaredNorm(); }
        static ElementType dotProduct(const Quaternion &q1, const Quaternion &q2) { return q1.quat.dot(q2.quat); }

        static Quaternion identity() { return Quaternion(ElementType(1), ElementType(0), ElementType(0), ElementType(0)); }

        //! Four coefficients static_cast<Element>(el_rnd_gen()), drawn in the order w, x, y, z.
        template<class ElRndSrc, typename = std::enable_if_t<std::is_invocable_v<const ElRndSrc &>>>
        static Quaternion random(const ElRndSrc &el_rnd_gen)
        {
            const auto w = static_cast<ElementType>(el_rnd_gen());
            const auto x = static_cast<ElementType>(el_rnd_gen());
            const auto y = static_cast<ElementType>(el_rnd_gen());
            const auto z = static_cast<ElementType>(el_rnd_gen());
            return Quaternion(w, x, y, z);
        }
        //! Unit rotation quaternion: angle ang(), axis from three el() draws (x, y, z); a zero axis becomes the X axis.
        template<class AngRndSrc, class ElRndSrc,
                 typename = std::enable_if_t<std::is_invocable_v<const AngRndSrc &> && std::is_invocable_v<const ElRndSrc &>>>
        static Quaternion random(const AngRndSrc &ang_rnd_gen, const ElRndSrc &el_rnd_gen)
        {
            const auto angle = static_cast<ElementType>(ang_rnd_gen());
            const auto x = static_cast<ElementType>(el_rnd_gen());
            const auto y = static_cast<ElementType>(el_rnd_gen());
            const auto z = static_cast<ElementType>(el_rnd_gen());
            VectorType axis(x, y, z);
            if (!(axis.lengthSquared() > ElementType(0)))
                axis = VectorType::baseX();
            return Quaternion(angle, axis);
        }

    private:
        EigenType quat;

        template<typename Coeffs>
        static Quaternion fromCoeffs(const Coeffs &c)
        {
            Quaternion q;
            q.quat.coeffs() = c;
            return q;
        }
    };

    template<typename Element>
    Quaternion<Element> operator*(Element s, const Quaternion<Element> &q) { return q * s; }
}
