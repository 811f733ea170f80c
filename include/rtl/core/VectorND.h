// VectorND: a fixed-size column vector of `dimensions` elements on top of Eigen, with 2D and 3D specialisations
// (x()/y()/z() accessors, cross products, base vectors).
//
// Default construction zero-initialises the elements (docs/reference.md, "VectorND"): the published implementation
// left them uninitialised, which made `Vector3d()` unusable as "the zero vector". The compiler drops the zero
// stores whenever they are overwritten before being read (measured in docs/core.md).
//
// Complexity: every operation is O(dimensions) and allocation-free (a fixed-size Eigen vector held by value).
// Invariants: none beyond Eigen's; elements may be any value, NaN included (hasNaN() tells; it and nan() exist for
// floating-point elements only, while the rest compiles for integer, bool and std::complex elements too).
// Preconditions: normalize()/normalized() and the projections "on" a vector need a non-zero vector (a zero one
// gives NaN, as Eigen does); element access by index needs i < dimensions (checked only by Eigen's assertions).
// Why a thin wrapper: RTL's interface (named accessors, static distance/angle helpers, transformed()) on top of
// Eigen's arithmetic, which stays Eigen's (vectorised, and reachable through data()).
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>

#include <Eigen/Dense>

namespace rtl
{
    template<int, int, typename> class Matrix;
    template<int, typename> class TranslationND;
    template<int, typename> class RotationND;
    template<int, typename> class RigidTfND;

    namespace detail
    {
        //! True for types derived from Eigen::EigenBase (so that Eigen objects never pick the element-wise constructor).
        template<typename T>
        constexpr bool is_eigen_v = std::is_base_of_v<Eigen::EigenBase<std::decay_t<T>>, std::decay_t<T>>;

        //! Arguments usable as individual elements of a vector with elements of type E.
        template<typename E, typename... T>
        constexpr bool are_elements_v = ((std::is_convertible_v<T, E> && !is_eigen_v<T>) && ...);
    }

    namespace detail
    {
        //! Stands in for a transformation that does not exist in this dimension; it cannot be constructed.
        template<int tag>
        struct Unavailable
        {
            Unavailable() = delete;
        };

        // Rotations and rigid transformations need at least two dimensions. In one dimension the core types declare
        // their transform overloads with an Unavailable parameter instead, so that overload resolution for
        // transformed(TranslationND<1, E>) never instantiates RotationND<1, E> / RigidTfND<1, E>.
        template<int d, typename E>
        using RotationArg = std::conditional_t<(d > 1), RotationND<d, E>, Unavailable<0>>;
        template<int d, typename E>
        using RigidTfArg = std::conditional_t<(d > 1), RigidTfND<d, E>, Unavailable<1>>;
    }

    //! Shared implementation of VectorND and its 2D/3D specialisations (CRTP over the child template).
    template<int dimensions, typename Element, template<int, typename> class ChildTemplate>
    class VectorND_common
    {
        static_assert(dimensions > 0, "VectorND needs at least one dimension.");
        typedef ChildTemplate<dimensions, Element> ChildType;

    public:
        typedef Element ElementType;
        typedef Element DistanceType;
        typedef Eigen::Matrix<Element, dimensions, 1> EigenType;

        template<int, int, typename> friend class Matrix;

        ~VectorND_common() = default;

        //! Element-wise static_cast to NewElement.
        template<typename NewElement>
        [[nodiscard]] ChildTemplate<dimensions, NewElement> cast() const
        {
            return ChildTemplate<dimensions, NewElement>(typename ChildTemplate<dimensions, NewElement>::EigenType(elements.template cast<NewElement>()));
        }

        //! v + t.
        [[nodiscard]] ChildType transformed(const TranslationND<dimensions, Element> &tr) const
        {
            return ChildType(EigenType(elements + tr.trVec().data()));
        }
        void transform(const TranslationND<dimensions, Element> &tr) { elements += tr.trVec().data(); }

        //! R v.
        [[nodiscard]] ChildType transformed(const detail::RotationArg<dimensions, Element> &rot) const
        {
            return ChildType(EigenType(rot.rotMat().data() * elements));
        }
        void transform(const detail::RotationArg<dimensions, Element> &rot) { elements = (rot.rotMat().data() * elements).eval(); }

        //! R v + t.
        [[nodiscard]] ChildType transformed(const detail::RigidTfArg<dimensions, Element> &tf) const
        {
            return ChildType(EigenType(tf.rotMat().data() * elements + tf.trVec().data()));
        }
        void transform(const detail::RigidTfArg<dimensions, Element> &tf) { elements = (tf.rotMat().data() * elements + tf.trVec().data()).eval(); }

        EigenType &data() { return elements; }
        const EigenType &data() const { return elements; }

        [[nodiscard]] bool hasNaN() const
        {
            static_assert(std::is_floating_point_v<Element>, "hasNaN() needs a floating-point element type.");
            return elements.hasNaN();
        }

        //! Bounds-checked element access; throws std::out_of_range for i >= dimensions.
        Element getElement(size_t i) const { return elements[checkedIndex(i)]; }
        void setElement(size_t i, Element value) { elements[checkedIndex(i)] = value; }

        //! Unchecked element access (precondition: i < dimensions).
        Element &operator[](size_t i) { return elements[static_cast<Eigen::Index>(i)]; }
        const Element &operator[](size_t i) const { return elements[static_cast<Eigen::Index>(i)]; }

        DistanceType length() const { return elements.norm(); }
        DistanceType lengthSquared() const { return elements.squaredNorm(); }

        //! Scales to unit length. Precondition: non-zero length (a zero vector becomes NaN, as a division by zero would).
        void normalize() { elements /= elements.norm(); }
        [[nodiscard]] ChildType normalized() const { return ChildType(EigenType(elements / elements.norm())); }

        ChildType operator+(const VectorND_common &v) const { return ChildType(EigenType(elements + v.elements)); }
        ChildType &operator+=(const VectorND_common &v) { elements += v.elements; return child(); }
        ChildType operator-(const VectorND_common &v) const { return ChildType(EigenType(elements - v.elements)); }
        ChildType &operator-=(const VectorND_common &v) { elements -= v.elements; return child(); }
        ChildType operator*(Element factor) const { return ChildType(EigenType(elements * factor)); }
        ChildType &operator*=(Element factor) { elements *= factor; return child(); }
        ChildType operator/(Element divisor) const { return ChildType(EigenType(elements / divisor)); }
        ChildType &operator/=(Element divisor) { elements /= divisor; return child(); }

        //! Exact element-wise comparison.
        bool operator==(const ChildType &v) const { return elements == v.elements; }
        bool operator!=(const ChildType &v) const { return !(elements == v.elements); }

        ElementType dot(const VectorND_common &v) const { return elements.dot(v.elements); }

        //! The outer product this * v^T, a dimensions x dimensions2 matrix.
        template<int dimensions2, template<int, typename> class ChildTemplate2>
        Matrix<dimensions, dimensions2, Element> outer(const VectorND_common<dimensions2, Element, ChildTemplate2> &v) const
        {
            return Matrix<dimensions, dimensions2, Element>(
                    typename Matrix<dimensions, dimensions2, Element>::EigenType(elements * v.data().transpose()));
        }

        //! The unsigned angle in [0, pi] between v1 and v2. The cosine is clamped to [-1, 1] so that (anti)parallel
        //! vectors give 0 / pi instead of NaN from rounding. Precondition: both vectors non-zero.
        static ElementType angleShortest(const VectorND_common &v1, const VectorND_common &v2)
        {
            ElementType c = v1.elements.dot(v2.elements) / (v1.elements.norm() * v2.elements.norm());
            return std::acos(std::clamp(c, ElementType(-1), ElementType(1)));
        }

        static constexpr int dimensionality() { return dimensions; }

        static DistanceType distance(const VectorND_common &v1, const VectorND_common &v2) { return (v1.elements - v2.elements).norm(); }
        static DistanceType distanceSquared(const VectorND_common &v1, const VectorND_common &v2) { return (v1.elements - v2.elements).squaredNorm(); }

        //! Signed length of proj's projection on the direction of `on`: proj.on / |on|.
        static DistanceType scalarProjection(const VectorND_common &proj, const VectorND_common &on)
        {
            return proj.elements.dot(on.elements) / on.elements.norm();
        }
        //! As scalarProjection, for a unit-length `on`: proj.on.
        static DistanceType scalarProjectionOnUnit(const VectorND_common &proj, const VectorND_common &on) { return proj.elements.dot(on.elements); }
        //! The projection of proj on the line spanned by `on`: on (proj.on) / (on.on).
        static ChildType vectorProjection(const VectorND_common &proj, const VectorND_common &on)
        {
            return ChildType(EigenType(on.elements * (proj.elements.dot(on.elements) / on.elements.squaredNorm())));
        }
        //! As vectorProjection, for a unit-length `on`: on (proj.on).
        static ChildType vectorProjectionOnUnit(const VectorND_common &proj, const VectorND_common &on)
        {
            return ChildType(EigenType(on.elements * proj.elements.dot(on.elements)));
        }

        friend ChildType operator-(const VectorND_common &v) { return ChildType(EigenType(-v.elements)); }

        static ChildType zeros() { return ChildType(EigenType(EigenType::Zero())); }
        static ChildType ones() { return ChildType(EigenType(EigenType::Ones())); }
        static ChildType nan()
        {
            static_assert(std::is_floating_point_v<Element>, "nan() needs a floating-point element type.");
            return ChildType(EigenType(EigenType::Constant(std::numeric_limits<Element>::quiet_NaN())));
        }

        //! Every element is static_cast<Element>(el_rnd_gen()), drawn in index order.
        template<class ElRndSrc, typename = std::enable_if_t<std::is_invocable_v<const ElRndSrc &>>>
        static ChildType random(const ElRndSrc &el_rnd_gen)
        {
            EigenType e;
            for (Eigen::Index i = 0; i < dimensions; ++i)
                e[i] = static_cast<Element>(el_rnd_gen());
            return ChildType(e);
        }

    protected:
        EigenType elements;

        VectorND_common() : elements(EigenType::Zero()) {}
        template<typename... T, typename std::enable_if<sizeof...(T) == dimensions && detail::are_elements_v<Element, T...>, int>::type = 0>
        explicit VectorND_common(T... args)
        {
            Eigen::Index i = 0;
            ((elements[i++] = static_cast<Element>(args)), ...);
        }
        VectorND_common(const VectorND_common &v) = default;
        VectorND_common &operator=(const VectorND_common &v) = default;
        explicit VectorND_common(const EigenType &ev) : elements(ev) {}

    private:
        static Eigen::Index checkedIndex(size_t i)
        {
            if (i >= static_cast<size_t>(dimensions))
                throw std::out_of_range("rtl::VectorND: index " + std::to_string(i) + " out of range for dimension " + std::to_string(dimensions));
            return static_cast<Eigen::Index>(i);
        }
        // Every VectorND_common object is the base sub-object of a ChildType (constructors are protected).
        ChildType &child() { return static_cast<ChildType &>(*this); }
    };

    //! scalar * vector. The scalar may be any arithmetic type (it is converted to the element type) or the element type itself.
    template<typename Scalar, int dimensions, typename Element, template<int, typename> class Child,
             std::enable_if_t<std::is_arithmetic_v<Scalar> || std::is_same_v<Scalar, Element>, int> = 0>
    Child<dimensions, Element> operator*(Scalar factor, const VectorND_common<dimensions, Element, Child> &v)
    {
        return Child<dimensions, Element>(typename Child<dimensions, Element>::EigenType(v.data() * static_cast<Element>(factor)));
    }

    //! General N-D vector.
    template<int dimensions, typename Element>
    class VectorND : public VectorND_common<dimensions, Element, VectorND>
    {
        typedef VectorND_common<dimensions, Element, VectorND> base;

    public:
        typedef typename base::ElementType ElementType;
        typedef typename base::DistanceType DistanceType;
        typedef typename base::EigenType EigenType;

        VectorND() = default;
        VectorND(const VectorND &v) = default;
        explicit VectorND(const EigenType &e) : base(e) {}
        //! One argument per element, each static_cast to Element.
        template<typename... T, typename std::enable_if<sizeof...(T) == dimensions && detail::are_elements_v<Element, T...>, int>::type = 0>
        explicit VectorND(T... args) : base(args...) {}

        VectorND &operator=(const VectorND &v) = default;
        VectorND &operator=(const EigenType &ev) { this->elements = ev; return *this; }
    };

    //! 2D vector: x()/y(), polar angle, scalar cross product.
    template<typename Element>
    class VectorND<2, Element> : public VectorND_common<2, Element, VectorND>
    {
        typedef VectorND_common<2, Element, VectorND> base;

    public:
        typedef typename base::ElementType ElementType;
        typedef typename base::DistanceType DistanceType;
        typedef typename base::EigenType EigenType;
        using base::transform;
        using base::transformed;

        VectorND() = default;
        VectorND(const VectorND<2, Element> &v) = default;
        explicit VectorND(const EigenType &e) : base(e) {}
        VectorND(ElementType x, ElementType y) : base(x, y) {}      // implicit on purpose: {x, y}

        VectorND &operator=(const VectorND &v) = default;
        VectorND &operator=(const EigenType &ev) { this->elements = ev; return *this; }

        [[nodiscard]] ElementType x() const { return this->elements[0]; }
        [[nodiscard]] ElementType y() const { return this->elements[1]; }
        void setX(ElementType x) { this->elements[0] = x; }
        void setY(ElementType y) { this->elements[1] = y; }

        //! atan2(y, x), in (-pi, pi].
        [[nodiscard]] ElementType angleFromZero() const { return std::atan2(this->elements[1], this->elements[0]); }
        //! Signed angle turning `from` onto `to`, counter-clockwise positive, in (-pi, pi].
        static ElementType angleCcw(const VectorND<2, Element> &from, const VectorND<2, Element> &to)
        {
            return std::atan2(from.cross(to), from.dot(to));
        }
        //! The scalar cross product x1 y2 - y1 x2.
        ElementType cross(const VectorND<2, Element> &v) const { return this->elements[0] * v.elements[1] - this->elements[1] * v.elements[0]; }

        static VectorND<2, Element> baseX() { return VectorND<2, Element>(Element(1), Element(0)); }
        static VectorND<2, Element> baseY() { return VectorND<2, Element>(Element(0), Element(1)); }
    };

    //! 3D vector: x()/y()/z(), cross product.
    template<typename Element>
    class VectorND<3, Element> : public VectorND_common<3, Element, VectorND>
    {
        typedef VectorND_common<3, Element, VectorND> base;

    public:
        typedef typename base::ElementType ElementType;
        typedef typename base::DistanceType DistanceType;
        typedef typename base::EigenType EigenType;
        using base::transform;
        using base::transformed;

        VectorND() = default;
        VectorND(const VectorND<3, Element> &v) = default;
        explicit VectorND(const EigenType &e) : base(e) {}
        VectorND(Element x, Element y, Element z) : base(x, y, z) {}      // implicit on purpose: {x, y, z}

        VectorND &operator=(const VectorND &v) = default;
        VectorND &operator=(const EigenType &ev) { this->elements = ev; return *this; }

        [[nodiscard]] Element x() const { return this->elements[0]; }
        [[nodiscard]] Element y() const { return this->elements[1]; }
        [[nodiscard]] Element z() const { return this->elements[2]; }
        void setX(Element x) { this->elements[0] = x; }
        void setY(Element y) { this->elements[1] = y; }
        void setZ(Element z) { this->elements[2] = z; }

        VectorND<3, Element> cross(const VectorND<3, Element> &v) const { return VectorND<3, Element>(EigenType(this->elements.cross(v.elements))); }

        static VectorND<3, Element> baseX() { return VectorND<3, Element>(Element(1), Element(0), Element(0)); }
        static VectorND<3, Element> baseY() { return VectorND<3, Element>(Element(0), Element(1), Element(0)); }
        static VectorND<3, Element> baseZ() { return VectorND<3, Element>(Element(0), Element(0), Element(1)); }
    };
}

// outer() returns a Matrix: make Matrix complete whichever of the two headers is included first.
#include "rtl/core/Matrix.h"
