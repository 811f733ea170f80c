// Legacy stand-alone 2D rigid transformation (docs/reference.md, "Legacy Transformation2D and
// Transformation3D"). Not included by any umbrella header; new code should
// use RigidTfND<2, E>. Kept for source compatibility: v -> R(angle) v + shift.
#pragma once

#include <cmath>
#include <type_traits>

#include <Eigen/Dense>

#include "rtl/core/Constants.h"
#include "rtl/core/Matrix.h"
#include "rtl/core/VectorND.h"

namespace rtl
{
    template<typename Element>
    class Transformation2D
    {
    public:
        typedef Element ElementType;
        typedef Element DistanceType;
        typedef VectorND<2, Element> VectorType;

        //! Identity.
        Transformation2D() = default;
        Transformation2D(const Transformation2D &tf) = default;
        Transformation2D(Element angle, Element x_shift, Element y_shift)
                : int_sin(std::sin(angle)), int_cos(std::cos(angle)), int_tr(x_shift, y_shift) {}
        Transformation2D(Element angle, const VectorType &shift) : int_sin(std::sin(angle)), int_cos(std::cos(angle)), int_tr(shift.data()) {}
        Transformation2D &operator=(const Transformation2D &tf) = default;

        [[nodiscard]] VectorType tr() const { return VectorType(int_tr); }
        [[nodiscard]] Element trX() const { return int_tr[0]; }
        [[nodiscard]] Element trY() const { return int_tr[1]; }
        [[nodiscard]] Element rotA() const { return std::atan2(int_sin, int_cos); }
        [[nodiscard]] Element rotCos() const { return int_cos; }
        [[nodiscard]] Element rotSin() const { return int_sin; }
        [[nodiscard]] Matrix<2, 2, Element> rotMat() const
        {
            typename Matrix<2, 2, Element>::EigenType m;
            m << int_cos, -int_sin, int_sin, int_cos;
            return Matrix<2, 2, Element>(m);
        }

        void setAngle(Element angle)
        {
            int_sin = std::sin(angle);
            int_cos = std::cos(angle);
        }
        void setTranslation(VectorType shift) { int_tr = shift.data(); }
        void setTranslationX(Element x) { int_tr[0] = x; }
        void setTranslationY(Element y) { int_tr[1] = y; }

        //! v -> R^T v - R^T t.
        [[nodiscard]] Transformation2D inverted() const
        {
            const Eigen::Matrix<Element, 2, 1> t = -rotate(int_tr, -int_sin, int_cos);
            return Transformation2D(-int_sin, int_cos, t[0], t[1]);
        }

        //! *this applied after `first`.
        Transformation2D operator*(const Transformation2D &first) const
        {
            const Eigen::Matrix<Element, 2, 1> t = rotate(first.int_tr, int_sin, int_cos) + int_tr;
            return Transformation2D(int_sin * first.int_cos + int_cos * first.int_sin, int_cos * first.int_cos - int_sin * first.int_sin,
                                    t[0], t[1]);
        }

        //! Applies the transformation to a 2D vector (any type with a 2-element EigenType data()), or to a 2D line
        //! segment (anything with beg()/end() and a (beg, end) constructor).
        template<class T>
        T operator()(const T &t) const
        {
            if constexpr (std::is_same_v<T, Transformation2D>)
                return *this * t;
            else if constexpr (IsSegment<T>::value)
                return T((*this)(t.beg()), (*this)(t.end()));
            else
                return T(typename T::EigenType(rotate(t.data(), int_sin, int_cos) + int_tr));
        }
        Transformation2D operator()(const Transformation2D &tf) const { return *this * tf; }

        static VectorType rotated(const VectorType &v, Element s, Element c) { return VectorType(rotate(v.data(), s, c)); }
        static VectorType rotated(const VectorType &v, Element angle) { return rotated(v, std::sin(angle), std::cos(angle)); }

        //! c_rot * (angle difference in (-pi, pi])^2 + c_tr * |translation difference|^2.
        static DistanceType distance(const Transformation2D &tf1, const Transformation2D &tf2, DistanceType c_tr, DistanceType c_rot)
        {
            const Element d_ang = std::atan2(tf1.int_sin * tf2.int_cos - tf1.int_cos * tf2.int_sin,
                                             tf1.int_cos * tf2.int_cos + tf1.int_sin * tf2.int_sin);
            return c_rot * d_ang * d_ang + c_tr * (tf1.int_tr - tf2.int_tr).squaredNorm();
        }

        //! Angle from ang_rnd_gen(), then x and y from el_rnd_gen().
        template<class AngRndSrc, class ElRndSrc>
        static Transformation2D random(const AngRndSrc &ang_rnd_gen, const ElRndSrc &el_rnd_gen)
        {
            const auto a = static_cast<Element>(ang_rnd_gen());
            const auto x = static_cast<Element>(el_rnd_gen());
            const auto y = static_cast<Element>(el_rnd_gen());
            return Transformation2D(a, x, y);
        }

    private:
        Element int_sin{0}, int_cos{1};
        Eigen::Matrix<Element, 2, 1> int_tr{Eigen::Matrix<Element, 2, 1>::Zero()};

        Transformation2D(Element sin, Element cos, Element x, Element y) : int_sin(sin), int_cos(cos), int_tr(x, y) {}

        template<typename T, typename = void> struct IsSegment : std::false_type {};
        template<typename T> struct IsSegment<T, std::void_t<decltype(std::declval<const T &>().beg())>> : std::true_type {};

        static Eigen::Matrix<Element, 2, 1> rotate(const Eigen::Matrix<Element, 2, 1> &v, Element s, Element c)
        {
            return Eigen::Matrix<Element, 2, 1>(c * v[0] - s * v[1], s * v[0] + c * v[1]);
        }
    };
}
