// BoundingBoxND: an axis-aligned box [min, max] in any dimension >= 1. Boxes are closed: touching boxes intersect,
// but intersection() only returns a box when the overlap has positive extent in every dimension.
//
// Invariant: min() <= max() in every dimension (constructors and addPoint keep it; a box is never empty, so there
// is no default constructor). Complexity: O(dim) per point added or box compared; a rotation or rigid
// transformation maps all 2^dim corners and takes their bounds, O(2^dim * dim^2), and transform() in place gives
// exactly the bits of transformed(). intersection() allocates the result (a std::unique_ptr, RTL's interface).
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include <Eigen/Dense>

#include "rtl/core/VectorND.h"

namespace rtl
{
    template<int, typename> class TranslationND;
    template<int, typename> class RotationND;
    template<int, typename> class RigidTfND;

    namespace detail
    {
        //! The default mapping of allVertices(): the vertex itself.
        struct IdentityMap
        {
            template<typename T>
            T operator()(const T &t) const { return t; }
        };
    }

    template<int dimensions, typename Element>
    class BoundingBoxND
    {
        static_assert(dimensions > 0, "BoundingBoxND needs at least one dimension.");

    public:
        typedef Element ElementType;
        typedef VectorND<dimensions, ElementType> VectorType;

        BoundingBoxND() = delete;
        BoundingBoxND(const BoundingBoxND &bb) = default;
        BoundingBoxND &operator=(const BoundingBoxND &bb) = default;
        //! The zero-volume box at v.
        explicit BoundingBoxND(const VectorType &v) : int_min(v), int_max(v) {}
        //! The box spanned by two opposite corners, given in any order.
        BoundingBoxND(const VectorType &v1, const VectorType &v2)                    // implicit on purpose: {v1, v2}
                : int_min(typename VectorType::EigenType(v1.data().cwiseMin(v2.data()))),
                  int_max(typename VectorType::EigenType(v1.data().cwiseMax(v2.data()))) {}
        //! The smallest box containing all vects; throws std::invalid_argument if vects is empty.
        explicit BoundingBoxND(const std::vector<VectorType> &vects) : int_min(firstOf(vects)), int_max(int_min)
        {
            addPoints(vects);
        }

        [[nodiscard]] VectorType min() const { return int_min; }
        [[nodiscard]] VectorType max() const { return int_max; }

        void addPoint(const VectorType &p)
        {
            int_min.data() = int_min.data().cwiseMin(p.data());
            int_max.data() = int_max.data().cwiseMax(p.data());
        }
        void addPoints(const std::vector<VectorType> &pts)
        {
            for (const auto &p : pts)
                addPoint(p);
        }
        void addBoundingBox(const BoundingBoxND &bb)
        {
            addPoint(bb.int_min);
            addPoint(bb.int_max);
        }

        //! True if the closed boxes share at least one point (touching counts).
        bool intersects(const BoundingBoxND &bb) const
        {
            return (int_min.data().array() <= bb.int_max.data().array()).all() && (bb.int_min.data().array() <= int_max.data().array()).all();
        }

        //! All 2^dimensions corners mapped through func (the corners themselves without an argument). Corner k takes
        //! max in dimension i when bit i of k is set, min otherwise.
        template<typename T = detail::IdentityMap>
        std::vector<std::invoke_result_t<T, VectorType>> allVertices(T &&func = T{}) const
        {
            std::vector<std::invoke_result_t<T, VectorType>> out;
            const size_t n = size_t(1) << dimensions;
            out.reserve(n);
            for (size_t k = 0; k < n; ++k)
            {
                VectorType v;
                for (Eigen::Index i = 0; i < dimensions; ++i)
                    v.data()[i] = (k >> i) & 1u ? int_max.data()[i] : int_min.data()[i];
                out.push_back(std::invoke(func, v));
            }
            return out;
        }

        //! Translation shifts the box.
        [[nodiscard]] BoundingBoxND transformed(const TranslationND<dimensions, Element> &tr) const
        {
            BoundingBoxND b(*this);
            b.transform(tr);
            return b;
        }
        void transform(const TranslationND<dimensions, Element> &tr)
        {
            int_min.data() += tr.trVec().data();
            int_max.data() += tr.trVec().data();
        }
        //! Rotations and rigid transformations give the axis-aligned box of the transformed corners.
        [[nodiscard]] BoundingBoxND transformed(const detail::RotationArg<dimensions, Element> &rot) const { return boxOfCorners(rot); }
        void transform(const detail::RotationArg<dimensions, Element> &rot) { *this = boxOfCorners(rot); }
        [[nodiscard]] BoundingBoxND transformed(const detail::RigidTfArg<dimensions, Element> &tf) const { return boxOfCorners(tf); }
        void transform(const detail::RigidTfArg<dimensions, Element> &tf) { *this = boxOfCorners(tf); }

        //! Product of the extents (0 for a degenerate box).
        Element volume() const { return (int_max.data() - int_min.data()).prod(); }
        VectorType centroid() const { return VectorType(typename VectorType::EigenType((int_min.data() + int_max.data()) / Element(2))); }

        //! Volume of the intersection over volume of the union; 0 when intersection() is empty.
        Element intersectionOverUnion(const BoundingBoxND &bb) const
        {
            const auto inter = intersection(*this, bb);
            if (!inter)
                return Element(0);
            const Element vi = inter->volume();
            return vi / (volume() + bb.volume() - vi);
        }

        //! The overlap of two boxes, or nullptr unless it has positive extent in every dimension.
        static std::unique_ptr<BoundingBoxND<dimensions, ElementType>> intersection(const BoundingBoxND &bb1, const BoundingBoxND &bb2)
        {
            const typename VectorType::EigenType lo = bb1.int_min.data().cwiseMax(bb2.int_min.data());
            const typename VectorType::EigenType hi = bb1.int_max.data().cwiseMin(bb2.int_max.data());
            if (!(lo.array() < hi.array()).all())
                return nullptr;
            return std::make_unique<BoundingBoxND>(VectorType(lo), VectorType(hi));
        }

        static constexpr int dimensionality() { return dimensions; }

    private:
        VectorType int_min, int_max;

        static const VectorType &firstOf(const std::vector<VectorType> &vects)
        {
            if (vects.empty())
                throw std::invalid_argument("rtl::BoundingBoxND: cannot bound an empty set of points");
            return vects.front();
        }

        template<typename Tf>
        BoundingBoxND boxOfCorners(const Tf &tf) const
        {
            const auto corners = allVertices([&tf](const VectorType &v) { return v.transformed(tf); });
            BoundingBoxND b(corners.front());
            for (const auto &c : corners)
                b.addPoint(c);
            return b;
        }
    };
}
