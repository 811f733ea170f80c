// RotationND: a rotation v -> R v about the origin in `dimensions` dimensions (R orthonormal, det R = 1).
//
// The rotation matrix is the stored representation (rotMat() hands out a reference to it). The 3D specialisation
// also caches the equivalent angle-axis; every operation that changes the matrix calls the private hook
// rotMatUpdated() of the child class, so that cache can never go stale
// (docs/reference.md, "RotationND").
//
// Invariant: R is orthonormal with det R = 1 up to rounding, for every rotation built through the public interface
// (the inputs of the two-vector and angle-axis forms are normalised first; random() draws directions, so the scale
// of its elements does not matter). Complexity: applying O(d^2), composing O(d^3), inverting (the transpose) O(d^2);
// no allocation. Default construction gives the identity.
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include "rtl/core/VectorND.h"
#include "rtl/core/Matrix.h"
#include "rtl/core/Quaternion.h"
#include "rtl/tf/UnitDirection.h"

namespace rtl
{
    template<int, typename> class TranslationND;
    template<int, typename> class RotationND;
    template<int, typename> class RigidTfND;

    //! Shared implementation of RotationND and its 2D/3D specialisations (CRTP over the child template).
    template<int dimensions, typename Element, template<int, typename> class ChildTemplate>
    class RotationND_common
    {
        static_assert(dimensions > 1, "A rotation needs at least two dimensions.");
        typedef ChildTemplate<dimensions, Element> ChildType;

        // cast() builds a rotation of another element type through its protected setRotMatInternal().
        template<int, typename, template<int, typename> class> friend class RotationND_common;

    public:
        typedef Element ElementType;
        typedef Element DistanceType;
        typedef VectorND<dimensions, Element> VectorType;
        typedef Matrix<dimensions, dimensions, ElementType> MatrixType;

        ~RotationND_common() = default;

        //! The rotation matrix R of v -> R v.
        [[nodiscard]] const MatrixType &rotMat() const { return int_rot_mat; }

        /*! General N-D construction: the rotation in the plane spanned by v1 and v2 that turns v1's direction into v2's
         *  (identity in the orthogonal complement). Preconditions: v1 and v2 non-zero and finite; a zero vector gives the
         *  identity. Antiparallel vectors give a rotation by pi in a plane containing v1 (any such plane is a valid answer).
         *  The 2D and 3D specialisations hide this with their own versions; it stays reachable through the qualified name
         *  RotationND_common<d, E, RotationND>::setRot and then also refreshes the 3D angle-axis cache. */
        void setRot(const VectorType &v1, const VectorType &v2)
        {
            int_rot_mat = MatrixType(planeRotation(v1.data(), v2.data()));
            updated();
        }

        //! The inverse rotation is the transpose.
        void invert()
        {
            int_rot_mat.data().transposeInPlace();
            updated();
        }
        [[nodiscard]] ChildType inverted() const
        {
            ChildType r(child());
            r.invert();
            return r;
        }

        template<typename NewElement>
        [[nodiscard]] ChildTemplate<dimensions, NewElement> cast() const
        {
            ChildTemplate<dimensions, NewElement> r;
            r.setRotMatInternal(Matrix<dimensions, dimensions, NewElement>(
                    typename Matrix<dimensions, dimensions, NewElement>::EigenType(int_rot_mat.data().template cast<NewElement>())));
            return r;
        }

        //! Applies this rotation to t, i.e. returns t.transformed(*this).
        template<class T>
        auto operator()(const T &t) const { return t.transformed(child()); }

        //! This rotation followed by `tr`: v -> R v + t.
        [[nodiscard]] RigidTfND<dimensions, Element> transformed(const TranslationND<dimensions, Element> &tr) const
        {
            return RigidTfND<dimensions, Element>(child(), tr);
        }

        //! This rotation followed by `rot`: R' = rot.R * R.
        [[nodiscard]] ChildType transformed(const RotationND<dimensions, Element> &rot) const
        {
            ChildType r(child());
            r.transform(rot);
            return r;
        }
        void transform(const RotationND<dimensions, Element> &rot)
        {
            int_rot_mat.data() = (rot.rotMat().data() * int_rot_mat.data()).eval();
            updated();
        }

        //! This rotation followed by `tf`: v -> R' R v + t'.
        [[nodiscard]] RigidTfND<dimensions, Element> transformed(const RigidTfND<dimensions, Element> &tf) const
        {
            return RigidTfND<dimensions, Element>(transformed(tf.rot()), tf.tr());
        }

        static ChildType identity() { return ChildType(); }

        //! The rotation taking one random vector's direction to another's; each vector element is
        //! static_cast<Element>(el_rnd_gen()), first vector first.
        template<class ElRndSrc, typename = std::enable_if_t<std::is_invocable_v<const ElRndSrc &>>>
        static ChildType random(const ElRndSrc &el_rnd_gen)
        {
            typename VectorType::EigenType e1, e2;
            for (int i = 0; i < dimensions; ++i)
                e1[i] = static_cast<Element>(el_rnd_gen());
            for (int i = 0; i < dimensions; ++i)
                e2[i] = static_cast<Element>(el_rnd_gen());
            return ChildType(VectorType(e1), VectorType(e2));
        }

        static constexpr int dimensionality() { return dimensions; }

    protected:
        MatrixType int_rot_mat{typename MatrixType::EigenType(MatrixType::EigenType::Identity())};

        RotationND_common() = default;
        RotationND_common(const RotationND_common &rot) = default;
        RotationND_common &operator=(const RotationND_common &rot) = default;
        explicit RotationND_common(const ChildType &rot) : int_rot_mat(rot.int_rot_mat) {}
        //! General N-D construction (see setRot). Children with cached state refresh it in their own constructor.
        RotationND_common(const VectorType &v1, const VectorType &v2)
                : int_rot_mat(typename MatrixType::EigenType(planeRotation(v1.data(), v2.data()))) {}

        operator ChildType() const { return child(); }

        //! Replaces the matrix (precondition: orthonormal with det 1) and refreshes the child's cached state.
        void setRotMatInternal(const MatrixType &m)
        {
            int_rot_mat = m;
            updated();
        }

        //! Rotation in the plane of a and b taking a's direction to b's (see setRot for the degenerate cases).
        static typename MatrixType::EigenType planeRotation(const typename VectorType::EigenType &a,
                                                            const typename VectorType::EigenType &b)
        {
            using EV = typename VectorType::EigenType;
            using EM = typename MatrixType::EigenType;
            const Element eps = std::numeric_limits<Element>::epsilon();
            EV u1, bh;   // unit directions, computed without overflow for elements near the type's limits
            if (!detail::unitDirection(a, u1) || !detail::unitDirection(b, bh))
                return EM::Identity();
            EV w = bh - u1.dot(bh) * u1;
            w -= u1.dot(w) * u1;                 // second Gram-Schmidt pass keeps u2 orthogonal to u1 for tiny angles
            Element nw = w.norm();
            Element c, s;
            EV u2;
            if (nw <= Element(16) * eps)
            {
                if (u1.dot(bh) > Element(0))
                    return EM::Identity();       // parallel: the angle is below 16 eps, identity is exact to that level
                // Antiparallel: turn by pi in the plane of u1 and the axis least aligned with it.
                Eigen::Index k;
                u1.cwiseAbs().minCoeff(&k);
                u2 = EV::Unit(k) - u1[k] * u1;
                u2 -= u1.dot(u2) * u1;
                u2.normalize();
                c = Element(-1);
                s = Element(0);
            }
            else
            {
                u2 = w / nw;
                // cos/sin of the same angle, so that c^2 + s^2 = 1 to rounding and R stays orthonormal.
                const Element angle = std::atan2(u2.dot(bh), u1.dot(bh));
                c = std::cos(angle);
                s = std::sin(angle);
            }
            EM r = EM::Identity();
            r += s * (u2 * u1.transpose() - u1 * u2.transpose());
            r += (c - Element(1)) * (u1 * u1.transpose() + u2 * u2.transpose());
            return r;
        }

    private:
        // Hook for children with cached state (the 3D angle-axis); the general and 2D children have none.
        void rotMatUpdated() {}
        void updated() { static_cast<ChildType *>(this)->rotMatUpdated(); }

        // Every RotationND_common object is the base sub-object of a ChildType (constructors are protected).
        const ChildType &child() const { return static_cast<const ChildType &>(*this); }
    };

    //! General N-D rotation.
    template<int dimensions, typename Element>
    class RotationND : public RotationND_common<dimensions, Element, RotationND>
    {
        typedef RotationND_common<dimensions, Element, RotationND> base;
    public:
        typedef typename base::ElementType ElementType;
        typedef typename base::VectorType VectorType;
        typedef typename base::MatrixType MatrixType;

        //! Identity.
        RotationND() = default;
        RotationND(const RotationND &rot) = default;
        //! The rotation in the plane of v1 and v2 taking v1's direction to v2's (see RotationND_common::setRot).
        RotationND(const VectorType &v1, const VectorType &v2) : base(v1, v2) {}
        RotationND &operator=(const RotationND &rot) = default;
    };

    //! 2D rotation, counter-clockwise by an angle in radians.
    template<typename Element>
    class RotationND<2, Element> : public RotationND_common<2, Element, RotationND>
    {
        typedef RotationND_common<2, Element, RotationND> base;
    public:
        typedef typename base::ElementType ElementType;
        typedef typename base::VectorType VectorType;
        typedef typename base::MatrixType MatrixType;

        //! Identity.
        RotationND() = default;
        RotationND(const RotationND &rot) = default;
        //! The rotation taking v1's direction to v2's (zero vectors give the identity).
        RotationND(const VectorType &v1, const VectorType &v2) { setRot(v1, v2); }
        explicit RotationND(ElementType angle) { setAngle(angle); }
        RotationND &operator=(const RotationND &rot) = default;

        void setRot(const VectorType &v1, const VectorType &v2)
        {
            // Unit directions first: the cross and dot products of raw elements near 1e30 (float) overflow to inf
            // and atan2(inf - inf, ...) is NaN.
            typename VectorType::EigenType a, b;
            if (!detail::unitDirection(v1.data(), a) || !detail::unitDirection(v2.data(), b))
            {
                setAngle(Element(0));
                return;
            }
            setAngle(std::atan2(a[0] * b[1] - a[1] * b[0], a.dot(b)));
        }

        [[nodiscard]] Element rotCos() const { return this->int_rot_mat.data()(0, 0); }
        [[nodiscard]] Element rotSin() const { return this->int_rot_mat.data()(1, 0); }
        //! Angle in (-pi, pi].
        [[nodiscard]] Element rotAngle() const { return std::atan2(rotSin(), rotCos()); }

        void setAngle(Element angle)
        {
            const Element c = std::cos(angle), s = std::sin(angle);
            auto &m = this->int_rot_mat.data();
            m(0, 0) = c;
            m(0, 1) = -s;
            m(1, 0) = s;
            m(1, 1) = c;
        }
    };

    //! 3D rotation with angle-axis, quaternion and roll-pitch-yaw views.
    template<typename Element>
    class RotationND<3, Element> : public RotationND_common<3, Element, RotationND>
    {
        typedef RotationND_common<3, Element, RotationND> base;
        typedef typename VectorND<3, Element>::EigenType EigenVector;
    public:
        typedef typename base::ElementType ElementType;
        typedef typename base::VectorType VectorType;
        typedef typename base::MatrixType MatrixType;

        //! Identity (angle 0 about the x axis).
        RotationND() = default;
        RotationND(const RotationND &rot) = default;
        //! The shortest rotation taking v1's direction to v2's (zero vectors give the identity).
        RotationND(const VectorType &v1, const VectorType &v2) { setRot(v1, v2); }
        //! Rotation of the quaternion, normalised first (a zero quaternion gives the identity).
        explicit RotationND(const Quaternion<ElementType> &quat) { setQuaternion(quat.data()); }
        //! Rotation by `angle` (radians, right-handed) about `axis` (normalised; a zero axis gives the identity).
        RotationND(ElementType angle, const VectorType &axis) { setAngleAxis(angle, axis); }
        //! Rx(roll) * Ry(pitch) * Rz(yaw), the convention of Quaternion(roll, pitch, yaw).
        RotationND(ElementType roll, ElementType pitch, ElementType yaw)
        {
            using AA = Eigen::AngleAxis<Element>;
            this->int_rot_mat.data() = AA(roll, EigenVector::UnitX()).toRotationMatrix()
                                       * AA(pitch, EigenVector::UnitY()).toRotationMatrix()
                                       * AA(yaw, EigenVector::UnitZ()).toRotationMatrix();
            rotMatUpdated();
        }
        RotationND &operator=(const RotationND &rot) = default;

        //! The shortest rotation taking v1's direction to v2's (zero vectors give the identity).
        void setRot(const VectorType &v1, const VectorType &v2)
        {
            EigenVector a, b;   // (Eigen normalises through the squared norm, which overflows near the limits)
            if (!detail::unitDirection(v1.data(), a) || !detail::unitDirection(v2.data(), b))
            {
                setQuaternion(Eigen::Quaternion<Element>::Identity());
                return;
            }
            Eigen::Quaternion<Element> q;
            q.setFromTwoVectors(a, b);
            setQuaternion(q);
        }

        //! cos and sin of the angle-axis angle.
        [[nodiscard]] Element rotCos() const { return std::cos(int_aa.angle()); }
        [[nodiscard]] Element rotSin() const { return std::sin(int_aa.angle()); }
        //! Angle of the angle-axis representation; in [0, pi] unless set explicitly through setAngle/setAngleAxis.
        [[nodiscard]] Element rotAngle() const { return int_aa.angle(); }
        //! Unit axis of the angle-axis representation (x for the identity).
        [[nodiscard]] VectorND<3, Element> rotAxis() const { return VectorND<3, Element>(EigenVector(int_aa.axis())); }
        [[nodiscard]] Quaternion<Element> rotQuaternion() const
        {
            return Quaternion<Element>(typename Quaternion<Element>::EigenType(int_aa));
        }
        //! Decomposes R = Rx(roll) Ry(pitch) Rz(yaw); the triple may differ from the one used to build the rotation
        //! but always rebuilds the same rotation.
        void rotRpy(ElementType &roll, ElementType &pitch, ElementType &yaw) const
        {
            const EigenVector e = this->int_rot_mat.data().eulerAngles(0, 1, 2);
            roll = e[0];
            pitch = e[1];
            yaw = e[2];
        }

        void setAngle(ElementType angle) { setAngleAxis(angle, rotAxis()); }
        void setAxis(const VectorND<3, Element> &axis) { setAngleAxis(rotAngle(), axis); }
        void setAngleAxis(Element angle, const VectorND<3, Element> &axis)
        {
            EigenVector unit;
            if (!detail::unitDirection(axis.data(), unit))
                int_aa = Eigen::AngleAxis<Element>(Element(0), EigenVector::UnitX());
            else
                int_aa = Eigen::AngleAxis<Element>(angle, unit);
            // Eigen's formula gives exact 0/1 entries for axis-aligned axes (bounding boxes rely on it).
            this->int_rot_mat.data() = int_aa.toRotationMatrix();
        }

        static RotationND<3, Element> identity() { return RotationND<3, Element>(); }

    private:
        friend RotationND_common<3, Element, RotationND>;

        void setQuaternion(const Eigen::Quaternion<Element> &q)
        {
            typename Eigen::Quaternion<Element>::Coefficients c;
            const Eigen::Quaternion<Element> u = detail::unitDirection(q.coeffs(), c) ? Eigen::Quaternion<Element>(c)
                                                                                      : Eigen::Quaternion<Element>::Identity();
            this->int_rot_mat.data() = u.toRotationMatrix();
            int_aa = Eigen::AngleAxis<Element>(u);
        }

        //! Recomputes the cached angle-axis from the matrix (called by every matrix-changing base operation).
        void rotMatUpdated() { int_aa = Eigen::AngleAxis<Element>(Eigen::Quaternion<Element>(this->int_rot_mat.data())); }

        Eigen::AngleAxis<Element> int_aa{Element(0), EigenVector::UnitX()};
    };
}

// Composition with translations returns RigidTfND: make all three transformation types complete together.
#include "rtl/tf/RigidTfND.h"
