// TranslationND: a pure translation v -> v + t in `dimensions` dimensions.
//
// Conventions shared by every transformation (docs/reference.md, "Composition rules"):
//  - a.transformed(b) means "apply a first, then b" (the result is b o a); a.transform(b) does it in place.
//  - tf(x) == x.transformed(tf), for any x with a matching transformed() (vectors, segments, boxes, other tfs...).
//
// Complexity: O(dimensions) per application, composition and inversion; no allocation. Default construction gives
// the identity (the zero vector).
#pragma once

#include <cmath>
#include <cstddef>
#include <type_traits>

#include <Eigen/Dense>

#include "rtl/core/VectorND.h"

namespace rtl
{
    template<int, typename> class TranslationND;
    template<int, typename> class RotationND;
    template<int, typename> class RigidTfND;

    //! Shared implementation of TranslationND and its 2D/3D specialisations (CRTP over the child template).
    template<int dimensions, typename Element, template<int, typename> class ChildTemplate>
    class TranslationND_common
    {
        static_assert(dimensions > 0, "TranslationND needs at least one dimension.");
        typedef ChildTemplate<dimensions, Element> ChildType;

        // cast() writes the vector of a translation with another element type.
        template<int, typename, template<int, typename> class> friend class TranslationND_common;

    public:
        typedef Element ElementType;
        typedef Element DistanceType;
        typedef VectorND<dimensions, Element> VectorType;

        ~TranslationND_common() = default;

        //! The translation vector t of v -> v + t.
        [[nodiscard]] const VectorType &trVec() const { return int_translation; }
        void setTrVec(const VectorType &translation) { int_translation = translation; }

        void invert() { int_translation.data() = -int_translation.data(); }
        [[nodiscard]] ChildType inverted() const { return ChildType(VectorType(typename VectorType::EigenType(-int_translation.data()))); }

        template<typename NewElement>
        [[nodiscard]] ChildTemplate<dimensions, NewElement> cast() const
        {
            using NewVector = VectorND<dimensions, NewElement>;
            return ChildTemplate<dimensions, NewElement>(
                    NewVector(typename NewVector::EigenType(int_translation.data().template cast<NewElement>())));
        }

        //! Applies this translation to t, i.e. returns t.transformed(*this).
        template<class T>
        auto operator()(const T &t) const { return t.transformed(child()); }

        //! This translation followed by `tr`.
        [[nodiscard]] ChildType transformed(const TranslationND<dimensions, Element> &tr) const
        {
            return ChildType(VectorType(typename VectorType::EigenType(int_translation.data() + tr.trVec().data())));
        }
        void transform(const TranslationND<dimensions, Element> &tr) { int_translation.data() += tr.trVec().data(); }

        //! This translation followed by `rot`: v -> R (v + t) = R v + R t.
        [[nodiscard]] RigidTfND<dimensions, Element> transformed(const RotationND<dimensions, Element> &rot) const
        {
            VectorType t(typename VectorType::EigenType(rot.rotMat().data() * int_translation.data()));
            return RigidTfND<dimensions, Element>(rot, TranslationND<dimensions, Element>(t));
        }

        //! This translation followed by `tf`: v -> R (v + t) + t' = R v + (R t + t').
        [[nodiscard]] RigidTfND<dimensions, Element> transformed(const RigidTfND<dimensions, Element> &tf) const
        {
            VectorType t(typename VectorType::EigenType(tf.rotMat().data() * int_translation.data() + tf.trVec().data()));
            return RigidTfND<dimensions, Element>(tf.rot(), TranslationND<dimensions, Element>(t));
        }

        //! Euclidean distance of the translation vectors.
        static DistanceType distance(const TranslationND_common &tr1, const TranslationND_common &tr2)
        {
            return (tr1.int_translation.data() - tr2.int_translation.data()).norm();
        }
        static DistanceType distanceSquared(const TranslationND_common &tr1, const TranslationND_common &tr2)
        {
            return (tr1.int_translation.data() - tr2.int_translation.data()).squaredNorm();
        }

        //! The zero translation.
        static ChildType identity() { return ChildType(VectorType(typename VectorType::EigenType(VectorType::EigenType::Zero()))); }

        //! Every element is static_cast<Element>(el_rnd_gen()), drawn in index order.
        template<class ElRndSrc, typename = std::enable_if_t<std::is_invocable_v<const ElRndSrc &>>>
        static ChildType random(const ElRndSrc &el_rnd_gen)
        {
            typename VectorType::EigenType e;
            for (int i = 0; i < dimensions; ++i)
                e[i] = static_cast<Element>(el_rnd_gen());
            return ChildType(VectorType(e));
        }

        static constexpr int dimensionality() { return dimensions; }

    protected:
        VectorType int_translation;     // value-initialised (zero) by VectorND's default constructor

        TranslationND_common() = default;
        template<typename... T, typename std::enable_if<sizeof...(T) == dimensions, int>::type = 0>
        explicit TranslationND_common(T... args) : int_translation(fromElements(static_cast<Element>(args)...)) {}
        TranslationND_common(const TranslationND_common &tr) = default;
        TranslationND_common &operator=(const TranslationND_common &tr) = default;
        explicit TranslationND_common(const VectorType &v) : int_translation(v) {}
        explicit TranslationND_common(const ChildType &tr) : int_translation(tr.int_translation) {}

        operator ChildType() const { return child(); }

    private:
        template<typename... T>
        static VectorType fromElements(T... elements)
        {
            const Element el[] = {elements...};
            return VectorType(typename VectorType::EigenType(Eigen::Map<const typename VectorType::EigenType>(el)));
        }

        // Every TranslationND_common object is the base sub-object of a ChildType (constructors are protected).
        const ChildType &child() const { return static_cast<const ChildType &>(*this); }
    };

    //! General N-D translation.
    template<int dimensions, typename Element>
    class TranslationND : public TranslationND_common<dimensions, Element, TranslationND>
    {
        typedef TranslationND_common<dimensions, Element, TranslationND> base;
    public:
        typedef typename base::ElementType ElementType;
        typedef typename base::VectorType VectorType;

        TranslationND() = default;
        TranslationND(const TranslationND &tr) = default;
        template<typename... T, std::enable_if_t<sizeof...(T) == dimensions, int> = 0>
        explicit TranslationND(T... args) : base(args...) {}
        explicit TranslationND(const VectorType &vec) : base(vec) {}
        TranslationND &operator=(const TranslationND &tr) = default;
    };

    //! 2D translation with per-axis accessors.
    template<typename Element>
    class TranslationND<2, Element> : public TranslationND_common<2, Element, TranslationND>
    {
        typedef TranslationND_common<2, Element, TranslationND> base;
    public:
        typedef typename base::ElementType ElementType;
        typedef typename base::VectorType VectorType;

        TranslationND() = default;
        TranslationND(const TranslationND &tr) = default;
        TranslationND(ElementType x, ElementType y) : base(x, y) {}          // implicit on purpose: {x, y}
        explicit TranslationND(const VectorType &vec) : base(vec) {}
        TranslationND &operator=(const TranslationND &tr) = default;

        [[nodiscard]] ElementType trVecX() const { return this->int_translation.data()[0]; }
        [[nodiscard]] ElementType trVecY() const { return this->int_translation.data()[1]; }
        void setTrVecX(ElementType x) { this->int_translation.data()[0] = x; }
        void setTrVecY(ElementType y) { this->int_translation.data()[1] = y; }
    };

    //! 3D translation with per-axis accessors.
    template<typename Element>
    class TranslationND<3, Element> : public TranslationND_common<3, Element, TranslationND>
    {
        typedef TranslationND_common<3, Element, TranslationND> base;
    public:
        typedef typename base::ElementType ElementType;
        typedef typename base::VectorType VectorType;

        TranslationND() = default;
        TranslationND(const TranslationND &tr) = default;
        TranslationND(ElementType x, ElementType y, ElementType z) : base(x, y, z) {}   // implicit on purpose: {x, y, z}
        explicit TranslationND(const VectorType &vec) : base(vec) {}
        TranslationND &operator=(const TranslationND &tr) = default;

        [[nodiscard]] ElementType trVecX() const { return this->int_translation.data()[0]; }
        [[nodiscard]] ElementType trVecY() const { return this->int_translation.data()[1]; }
        [[nodiscard]] ElementType trVecZ() const { return this->int_translation.data()[2]; }
        void setTrVecX(ElementType x) { this->int_translation.data()[0] = x; }
        void setTrVecY(ElementType y) { this->int_translation.data()[1] = y; }
        void setTrVecZ(ElementType z) { this->int_translation.data()[2] = z; }
    };
}

// Composition with rotations returns RigidTfND: make all three transformation types complete together,
// whichever of their headers is included first.
#include "rtl/tf/RigidTfND.h"
