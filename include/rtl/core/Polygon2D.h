// Polygon2D: a planar polygon as its ordered vertex list.
//
// No invariant is imposed on the vertices (they need not form a simple or convex polygon). Complexity: transformations
// O(n) in the vertex count; adding a vertex amortised O(1).
#pragma once

#include <cstddef>
#include <iterator>
#include <type_traits>
#include <vector>

#include "rtl/core/VectorND.h"

namespace rtl
{
    template<int, typename> class TranslationND;
    template<int, typename> class RotationND;
    template<int, typename> class RigidTfND;

    template<typename Element>
    class Polygon2D
    {
    public:
        typedef Element ElementType;
        typedef VectorND<2, ElementType> VectorType;

        Polygon2D() = default;
        ~Polygon2D() = default;

        // Transformations move every vertex.
        [[nodiscard]] Polygon2D transformed(const TranslationND<2, Element> &tr) const { Polygon2D p(*this); p.transform(tr); return p; }
        void transform(const TranslationND<2, Element> &tr) { apply(tr); }
        [[nodiscard]] Polygon2D transformed(const RotationND<2, Element> &rot) const { Polygon2D p(*this); p.transform(rot); return p; }
        void transform(const RotationND<2, Element> &rot) { apply(rot); }
        [[nodiscard]] Polygon2D transformed(const RigidTfND<2, Element> &tf) const { Polygon2D p(*this); p.transform(tf); return p; }
        void transform(const RigidTfND<2, Element> &tf) { apply(tf); }

        [[nodiscard]] const std::vector<VectorType> &points() const { return int_points; }
        void reservePoints(size_t cnt) { int_points.reserve(cnt); }
        void addPoint(VectorType point) { int_points.push_back(point); }
        template<class Iter>
        void addPoints(Iter beg, Iter end)
        {
            static_assert(std::is_convertible_v<typename std::iterator_traits<Iter>::value_type, VectorType>,
                          "Polygon2D::addPoints: the iterator's value type must convert to VectorType.");
            for (; beg != end; ++beg)
                int_points.push_back(static_cast<VectorType>(*beg));
        }

        static constexpr int dimensionality() { return 2; }

    private:
        std::vector<VectorType> int_points;

        template<typename Tf>
        void apply(const Tf &tf)
        {
            for (auto &p : int_points)
                p.transform(tf);
        }
    };
}
