// RigidTfND: a rigid (proper Euclidean) transformation v -> R v + t in `dimensions` dimensions,
// stored as a RotationND (R) and a TranslationND (t).
//
// Invariants: those of RotationND for R; t is any vector (a NaN translation is meaningful to LaTeXTikz3D::setView,
// which fits the camera). Inversion gives (R^T, -R^T t). Complexity: applying O(d^2), composing O(d^3); no
// allocation. Default construction gives the identity.
#pragma once

#include <cstddef>
#include <type_traits>

#include <Eigen/Dense>

#include "rtl/core/VectorND.h"
#include "rtl/core/Matrix.h"
#include "rtl/core/Quaternion.h"
#include "rtl/tf/TranslationND.h"
#include "rtl/tf/RotationND.h"

namespace rtl
{
    //! Shared implementation of RigidTfND and its 2D/3D specialisations (CRTP over the child template).
    template<int dimensions, typename Element, template<int, typename> class ChildTemplate>
    class RigidTfND_common
    {
        static_assert(dimensions > 1, "A rigid transformation needs at least two dimensions.");
        typedef ChildTemplate<dimensions, Element> ChildType;

    public:
        typedef Element ElementType;
        typedef VectorND<dimensions, Element> VectorType;
        typedef TranslationND<dimensions, Element> TranslationType;
        typedef RotationND<dimensions, Element> RotationType;
        typedef typename RotationType::MatrixType MatrixType;

        ~RigidTfND_common() = default;

        [[nodiscard]] const TranslationType &tr() const { return int_translation; }
        [[nodiscard]] const VectorType &trVec() const { return int_translation.trVec(); }
        void setTrVec(const VectorType &translation) { int_translation.setTrVec(translation); }

        [[nodiscard]] const RotationType &rot() const { return int_rotation; }
        [[nodiscard]] const MatrixType &rotMat() const { return int_rotation.rotMat(); }
        //! Sets the rotation part as RotationType(v1, v2) would (the translation is kept).
        void setRot(const VectorType &v1, const VectorType &v2) { int_rotation = RotationType(v1, v2); }

        //! The inverse v -> R^T v - R^T t.
        void invert()
        {
            int_rotation.invert();
            int_translation.setTrVec(VectorType(typename VectorType::EigenType(
                    -(int_rotation.rotMat().data() * int_translation.trVec().data()))));
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
            return ChildTemplate<dimensions, NewElement>(int_rotation.template cast<NewElement>(),
                                                         int_translation.template cast<NewElement>());
        }

        //! Applies this transformation to t, i.e. returns t.transformed(*this).
        template<class T>
        auto operator()(const T &t) const { return t.transformed(child()); }

        //! This transformation followed by `tr`: (R, t + tr).
        [[nodiscard]] ChildType transformed(const TranslationND<dimensions, Element> &tr) const
        {
            ChildType r(child());
            r.transform(tr);
            return r;
        }
        void transform(const TranslationND<dimensions, Element> &tr) { int_translation.transform(tr); }

        //! This transformation followed by `rot`: (rot.R R, rot.R t).
        [[nodiscard]] ChildType transformed(const RotationND<dimensions, Element> &rot) const
        {
            ChildType r(child());
            r.transform(rot);
            return r;
        }
        void transform(const RotationND<dimensions, Element> &rot)
        {
            int_rotation.transform(rot);
            int_translation.setTrVec(VectorType(typename VectorType::EigenType(rot.rotMat().data() * int_translation.trVec().data())));
        }

        //! This transformation followed by `tf`: (tf.R R, tf.R t + tf.t).
        [[nodiscard]] ChildType transformed(const ChildType &tf) const
        {
            ChildType r(child());
            r.transform(tf);
            return r;
        }
        void transform(const ChildType &tf)
        {
            int_rotation.transform(tf.rot());
            int_translation.setTrVec(VectorType(typename VectorType::EigenType(
                    tf.rotMat().data() * int_translation.trVec().data() + tf.trVec().data())));
        }

        static ChildType identity() { return ChildType(); }

        //! (RotationType::random(g), TranslationType::random(g)), rotation drawn first.
        template<class ElRndSrc, typename = std::enable_if_t<std::is_invocable_v<const ElRndSrc &>>>
        static ChildType random(const ElRndSrc &el_rnd_gen)
        {
            RotationType rot = RotationType::random(el_rnd_gen);
            TranslationType tr = TranslationType::random(el_rnd_gen);
            return ChildType(rot, tr);
        }

        static constexpr int dimensionality() { return dimensions; }

    protected:
        TranslationType int_translation;     // zero
        RotationType int_rotation;           // identity

        RigidTfND_common() = default;
        RigidTfND_common(const RigidTfND_common &tf) = default;
        RigidTfND_common &operator=(const RigidTfND_common &tf) = default;
        explicit RigidTfND_common(const TranslationType &tr) : int_translation(tr) {}
        explicit RigidTfND_common(const RotationType &rot) : int_rotation(rot) {}
        RigidTfND_common(const RotationType &rot, const TranslationType &tr) : int_translation(tr), int_rotation(rot) {}
        RigidTfND_common(const VectorType &rot_from, const VectorType &rot_to, const VectorType tr)
                : int_translation(tr), int_rotation(rot_from, rot_to) {}
        explicit RigidTfND_common(const ChildType &tf) : int_translation(tf.int_translation), int_rotation(tf.int_rotation) {}

        operator ChildType() const { return child(); }

    private:
        // Every RigidTfND_common object is the base sub-object of a ChildType (constructors are protected).
        const ChildType &child() const { return static_cast<const ChildType &>(*this); }
    };

    //! General N-D rigid transformation.
    template<int dimensions, typename Element>
    class RigidTfND : public RigidTfND_common<dimensions, Element, RigidTfND>
    {
        typedef RigidTfND_common<dimensions, Element, RigidTfND> base;
    public:
        typedef typename base::ElementType ElementType;
        typedef typename base::VectorType VectorType;
        typedef typename base::TranslationType TranslationType;
        typedef typename base::RotationType RotationType;

        //! Identity.
        RigidTfND() = default;
        RigidTfND(const RigidTfND &tf) = default;
        explicit RigidTfND(const TranslationType &tr) : base(tr) {}
        explicit RigidTfND(const RotationType &rot) : base(rot) {}
        RigidTfND(const RotationType &rot, const TranslationType &tr) : base(rot, tr) {}
        //! Rotation RotationType(rot_from, rot_to), then translation by tr.
        RigidTfND(const VectorType &rot_from, const VectorType &rot_to, const VectorType tr) : base(rot_from, rot_to, tr) {}
        RigidTfND &operator=(const RigidTfND &tf) = default;
    };

    //! 2D rigid transformation.
    template<typename Element>
    class RigidTfND<2, Element> : public RigidTfND_common<2, Element, RigidTfND>
    {
        typedef RigidTfND_common<2, Element, RigidTfND> base;
    public:
        typedef typename base::ElementType ElementType;
        typedef typename base::VectorType VectorType;
        typedef typename base::TranslationType TranslationType;
        typedef typename base::RotationType RotationType;

        RigidTfND() = default;
        RigidTfND(const RigidTfND &tf) = default;
        explicit RigidTfND(const TranslationType &tr) : base(tr) {}
        explicit RigidTfND(const RotationType &rot) : base(rot) {}
        RigidTfND(const RotationType &rot, const TranslationType &tr) : base(rot, tr) {}
        RigidTfND(const VectorType &rot_from, const VectorType &rot_to, const VectorType tr) : base(rot_from, rot_to, tr) {}
        //! Counter-clockwise rotation by `angle` (radians), then translation by (tr_x, tr_y).
        RigidTfND(Element angle, Element tr_x, Element tr_y) : base(RotationType(angle), TranslationType(tr_x, tr_y)) {}
        RigidTfND(Element angle, const VectorType &tr) : base(RotationType(angle), TranslationType(tr)) {}
        RigidTfND &operator=(const RigidTfND &tf) = default;

        [[nodiscard]] Element trVecX() const { return this->int_translation.trVecX(); }
        [[nodiscard]] Element trVecY() const { return this->int_translation.trVecY(); }
        void setTrVecX(Element x) { this->int_translation.setTrVecX(x); }
        void setTrVecY(Element y) { this->int_translation.setTrVecY(y); }

        [[nodiscard]] Element rotCos() const { return this->int_rotation.rotCos(); }
        [[nodiscard]] Element rotSin() const { return this->int_rotation.rotSin(); }
        [[nodiscard]] Element rotAngle() const { return this->int_rotation.rotAngle(); }
        void setAngle(Element angle) { this->int_rotation.setAngle(angle); }
    };

    //! 3D rigid transformation.
    template<typename Element>
    class RigidTfND<3, Element> : public RigidTfND_common<3, Element, RigidTfND>
    {
        typedef RigidTfND_common<3, Element, RigidTfND> base;
    public:
        typedef typename base::ElementType ElementType;
        typedef typename base::VectorType VectorType;
        typedef typename base::TranslationType TranslationType;
        typedef typename base::RotationType RotationType;

        RigidTfND() = default;
        RigidTfND(const RigidTfND &tf) = default;
        explicit RigidTfND(const TranslationType &tr) : base(tr) {}
        explicit RigidTfND(const RotationType &rot) : base(rot) {}
        RigidTfND(const RotationType &rot, const TranslationType &tr) : base(rot, tr) {}
        RigidTfND(const VectorType &rot_from, const VectorType &rot_to, const VectorType tr) : base(rot_from, rot_to, tr) {}
        //! Rotation by `angle` about `axis` (normalised), then translation by tr.
        RigidTfND(Element angle, const VectorType &axis, const VectorType &tr) : base(RotationType(angle, axis), TranslationType(tr)) {}
        RigidTfND(const Quaternion<Element> &quat, const VectorType &tr) : base(RotationType(quat), TranslationType(tr)) {}
        //! Rx(roll) Ry(pitch) Rz(yaw), then translation by tr.
        RigidTfND(ElementType roll, ElementType pitch, ElementType yaw, const VectorType &tr)
                : base(RotationType(roll, pitch, yaw), TranslationType(tr)) {}
        RigidTfND &operator=(const RigidTfND &tf) = default;

        [[nodiscard]] Element trVecX() const { return this->int_translation.trVecX(); }
        [[nodiscard]] Element trVecY() const { return this->int_translation.trVecY(); }
        [[nodiscard]] Element trVecZ() const { return this->int_translation.trVecZ(); }
        void setTrVecX(Element x) { this->int_translation.setTrVecX(x); }
        void setTrVecY(Element y) { this->int_translation.setTrVecY(y); }
        void setTrVecZ(Element z) { this->int_translation.setTrVecZ(z); }

        [[nodiscard]] Element rotCos() const { return this->int_rotation.rotCos(); }
        [[nodiscard]] Element rotSin() const { return this->int_rotation.rotSin(); }
        [[nodiscard]] Element rotAngle() const { return this->int_rotation.rotAngle(); }
        [[nodiscard]] VectorType rotAxis() const { return this->int_rotation.rotAxis(); }
        [[nodiscard]] Quaternion<Element> rotQuaternion() const { return this->int_rotation.rotQuaternion(); }
        void rotRpy(ElementType &roll, ElementType &pitch, ElementType &yaw) const { this->int_rotation.rotRpy(roll, pitch, yaw); }

        void setAngle(ElementType angle) { this->int_rotation.setAngle(angle); }
        void setAxis(const VectorND<3, Element> &axis) { this->int_rotation.setAxis(axis); }
        void setAngleAxis(Element angle, const VectorND<3, Element> &axis) { this->int_rotation.setAngleAxis(angle, axis); }
    };
}
