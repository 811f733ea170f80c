// Legacy stand-alone 3D rigid transformation (docs/reference.md, "Legacy Transformation2D and
// Transformation3D"). Not included by any umbrella header; new code should
// use RigidTfND<3, E>. Kept for source compatibility: v -> R v + shift, R stored as a unit quaternion.
#pragma once

#include <cmath>
#include <type_traits>

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include "rtl/core/Matrix.h"
#include "rtl/core/Quaternion.h"
#include "rtl/core/VectorND.h"
#include "rtl/tf/UnitDirection.h"

namespace rtl
{
    template<typename Element>
    class Transformation3D
    {
        typedef Eigen::Matrix<Element, 3, 1> EV;
        typedef Eigen::Quaternion<Element> EQ;
    public:
        typedef Element ElementType;
        typedef Element DistanceType;
        typedef VectorND<3, Element> VectorType;

        //! Identity.
        Transformation3D() = default;
        Transformation3D(const Transformation3D &tf) = default;
        //! Rotation by `angle` about `axis` (normalised; a zero axis gives no rotation), then `shift`.
        Transformation3D(Element angle, const VectorType &axis, const VectorType &shift) : int_tr(shift.data())
        {
            setAngleAxis(angle, axis);
        }
        Transformation3D(const Quaternion<Element> &quat, const VectorType &shift) : int_tr(shift.data())
        {
            typename EQ::Coefficients c;
            int_q = detail::unitDirection(quat.data().coeffs(), c) ? EQ(c) : EQ::Identity();
        }
        //! Rx(roll) Ry(pitch) Rz(yaw), then `shift`.
        Transformation3D(ElementType roll, ElementType pitch, ElementType yaw, const VectorType &shift)
                : int_q(Eigen::AngleAxis<Element>(roll, EV::UnitX()) * Eigen::AngleAxis<Element>(pitch, EV::UnitY())
                        * Eigen::AngleAxis<Element>(yaw, EV::UnitZ())),
                  int_tr(shift.data()) {}
        Transformation3D &operator=(const Transformation3D &tf) = default;

        [[nodiscard]] VectorType tr() const { return VectorType(int_tr); }
        [[nodiscard]] Element trX() const { return int_tr[0]; }
        [[nodiscard]] Element trY() const { return int_tr[1]; }
        [[nodiscard]] Element trZ() const { return int_tr[2]; }
        [[nodiscard]] Element rotAngle() const { return Eigen::AngleAxis<Element>(int_q).angle(); }
        [[nodiscard]] VectorType rotAxis() const { return VectorType(EV(Eigen::AngleAxis<Element>(int_q).axis())); }
        [[nodiscard]] Matrix<3, 3, Element> rotMat() const { return Matrix<3, 3, Element>(int_q.toRotationMatrix()); }
        [[nodiscard]] Quaternion<Element> rotQuaternion() const { return Quaternion<Element>(int_q); }
        //! R = Rx(roll) Ry(pitch) Rz(yaw) (one of the equivalent triples).
        void rpy(Element &roll, Element &pitch, Element &yaw) const
        {
            const EV e = int_q.toRotationMatrix().eulerAngles(0, 1, 2);
            roll = e[0];
            pitch = e[1];
            yaw = e[2];
        }

        void setAngle(Element angle) { setAngleAxis(angle, rotAxis()); }
        void setAxis(const VectorType &axis) { setAngleAxis(rotAngle(), axis); }
        void setAngleAxis(Element angle, const VectorType &axis)
        {
            EV unit;
            int_q = detail::unitDirection(axis.data(), unit) ? EQ(Eigen::AngleAxis<Element>(angle, unit)) : EQ::Identity();
        }
        void setTranslation(const VectorType &shift) { int_tr = shift.data(); }
        void setTranslationX(Element x) { int_tr[0] = x; }
        void setTranslationY(Element y) { int_tr[1] = y; }
        void setTranslationZ(Element z) { int_tr[2] = z; }

        //! v -> R^T v - R^T t.
        void invert()
        {
            int_q = int_q.conjugate();
            int_tr = -(int_q * int_tr);
        }
        [[nodiscard]] Transformation3D inverted() const
        {
            Transformation3D r(*this);
            r.invert();
            return r;
        }

        //! Applies the transformation to a 3D vector, a segment (beg()/end()), or composes with another Transformation3D
        //! (`first` applied first).
        template<class T>
        T operator()(const T &t) const
        {
            if constexpr (std::is_same_v<T, Transformation3D>)
                return compose(t);
            else if constexpr (IsSegment<T>::value)
                return T((*this)(t.beg()), (*this)(t.end()));
            else
                return T(typename T::EigenType(int_q * t.data() + int_tr));
        }
        Transformation3D operator()(const Transformation3D &first) const { return compose(first); }

        //! c_rot * angle(R1^T R2)^2 + c_tr * |t1 - t2|^2.
        static DistanceType distance(const Transformation3D &tf1, const Transformation3D &tf2, Element c_tr, Element c_rot)
        {
            const Element d_ang = tf1.int_q.angularDistance(tf2.int_q);
            return c_rot * d_ang * d_ang + c_tr * (tf1.int_tr - tf2.int_tr).squaredNorm();
        }

        //! Angle from ang_rnd_gen(); axis, then translation, from el_rnd_gen() (three calls each).
        template<class AngRndSrc, class ElRndSrc>
        static Transformation3D random(const AngRndSrc &ang_rnd_gen, const ElRndSrc &el_rnd_gen)
        {
            const auto a = static_cast<Element>(ang_rnd_gen());
            EV axis, tr;
            for (int i = 0; i < 3; ++i)
                axis[i] = static_cast<Element>(el_rnd_gen());
            for (int i = 0; i < 3; ++i)
                tr[i] = static_cast<Element>(el_rnd_gen());
            return Transformation3D(a, VectorType(axis), VectorType(tr));
        }

    private:
        EQ int_q{EQ::Identity()};
        EV int_tr{EV::Zero()};

        template<typename T, typename = void> struct IsSegment : std::false_type {};
        template<typename T> struct IsSegment<T, std::void_t<decltype(std::declval<const T &>().beg())>> : std::true_type {};

        Transformation3D compose(const Transformation3D &first) const
        {
            Transformation3D r;
            r.int_q = (int_q * first.int_q).normalized();
            r.int_tr = int_q * first.int_tr + int_tr;
            return r;
        }
    };
}
