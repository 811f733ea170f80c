// Polygon3D: a planar polygon in 3D, i.e. a plane n.x = distance (unit normal n) plus the ordered vertex list.
// addPoint() projects vertices onto the plane; addPointDirect() stores them as given.
//
// Invariant: the normal is a unit vector (precondition: the constructor's normal is non-zero). Vertices added with
// addPoint() lie on the plane; addPointDirect() trusts the caller. Transformations move the vertices and the plane
// together. Complexity: O(n) per transformation, amortised O(1) per vertex added.
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
    class Polygon3D
    {
    public:
        typedef Element ElementType;
        typedef VectorND<3, ElementType> VectorType;

        Polygon3D() = default;
        //! The plane normal.x = distance. The normal is normalised (precondition: non-zero); distance is kept as the
        //! signed distance of the plane from the origin along the unit normal.
        Polygon3D(VectorType normal, ElementType distance) : int_normal(normal.normalized()), int_distance(distance) {}
        ~Polygon3D() = default;

        [[nodiscard]] VectorType normal() const { return int_normal; }
        [[nodiscard]] ElementType distance() const { return int_distance; }
        [[nodiscard]] ElementType a() const { return int_normal.x(); }
        [[nodiscard]] ElementType b() const { return int_normal.y(); }
        [[nodiscard]] ElementType c() const { return int_normal.z(); }
        //! -distance, so that a x + b y + c z + d = 0 on the plane.
        [[nodiscard]] ElementType d() const { return -int_distance; }
        [[nodiscard]] const std::vector<VectorType> &points() const { return int_points; }

        // Transformations move every vertex and the plane with them.
        [[nodiscard]] Polygon3D transformed(const TranslationND<3, Element> &tr) const { Polygon3D p(*this); p.transform(tr); return p; }
        void transform(const TranslationND<3, Element> &tr)
        {
            int_distance += int_normal.dot(tr.trVec());
            for (auto &p : int_points)
                p.transform(tr);
        }
        [[nodiscard]] Polygon3D transformed(const RotationND<3, Element> &rot) const { Polygon3D p(*this); p.transform(rot); return p; }
        void transform(const RotationND<3, Element> &rot)
        {
            int_normal.transform(rot);
            for (auto &p : int_points)
                p.transform(rot);
        }
        [[nodiscard]] Polygon3D transformed(const RigidTfND<3, Element> &tf) const { Polygon3D p(*this); p.transform(tf); return p; }
        void transform(const RigidTfND<3, Element> &tf)
        {
            int_normal = VectorType(typename VectorType::EigenType(tf.rotMat().data() * int_normal.data()));
            int_distance += int_normal.dot(tf.trVec());
            for (auto &p : int_points)
                p.transform(tf);
        }

        void reservePoints(size_t cnt) { int_points.reserve(cnt); }
        //! Stores the orthogonal projection of `point` onto the plane.
        void addPoint(const VectorType &point) { int_points.push_back(point - int_normal * (int_normal.dot(point) - int_distance)); }
        template<class Iter>
        void addPoints(Iter beg, Iter end)
        {
            checkIter<Iter>();
            for (; beg != end; ++beg)
                addPoint(static_cast<VectorType>(*beg));
        }
        //! Stores `point` as given (the caller guarantees it lies on the plane).
        void addPointDirect(VectorType point) { int_points.push_back(point); }
        template<class Iter>
        void addPointsDirect(Iter beg, Iter end)
        {
            checkIter<Iter>();
            for (; beg != end; ++beg)
                int_points.push_back(static_cast<VectorType>(*beg));
        }

        static constexpr int dimensionality() { return 3; }

    private:
        VectorType int_normal;
        ElementType int_distance{0};
        std::vector<VectorType> int_points;

        template<class Iter>
        static constexpr void checkIter()
        {
            static_assert(std::is_convertible_v<typename std::iterator_traits<Iter>::value_type, VectorType>,
                          "Polygon3D::addPoints: the iterator's value type must convert to VectorType.");
        }
    };
}
