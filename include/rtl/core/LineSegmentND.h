// LineSegmentND: a segment from beg() to end() with its unit direction cached, in any dimension >= 1.
// Distances and projections refer to the infinite line through the segment unless stated otherwise.
// Precondition for construction from endpoints: beg != end (a zero-length segment has no direction; its
// direction() is NaN).
//
// Invariant: direction() is the unit vector from beg() to end(); every setter and transformation keeps it so
// (setBegin/setEnd recompute it, moves and swaps flip or keep it, a rotation rotates it). Only the constructor that
// takes a direction stores it as given. Caching it is the point of the class: distances and projections along the
// line cost one dot product each.
// Complexity: O(dimensions) per operation, no allocation; cropByHyperRect and fitToHyperRect O(dimensions).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

#include <Eigen/Dense>

#include "rtl/core/VectorND.h"

namespace rtl
{
    template<int, typename> class TranslationND;
    template<int, typename> class RotationND;
    template<int, typename> class RigidTfND;

    //! Shared implementation of LineSegmentND and its 2D/3D specialisations (CRTP over the child template).
    template<int dimensions, typename Element, template<int, typename> class ChildTemplate>
    class LineSegmentND_common
    {
        static_assert(dimensions > 0, "LineSegmentND needs at least one dimension.");
        typedef ChildTemplate<dimensions, Element> ChildType;

    public:
        typedef Element ElementType;
        typedef VectorND<dimensions, Element> VectorType;

        //! Distance of two lines: the angle between their directions and the difference of their distances to the origin.
        struct DistanceType
        {
            DistanceType(Element d_ang, Element d_lin) : dist_lin(d_lin), dist_ang(d_ang) {}
            Element dist_lin{0}, dist_ang{0};
            //! dist_ang * c_ang + dist_lin * c_lin.
            Element combined(Element c_ang, Element c_lin) { return dist_ang * c_ang + dist_lin * c_lin; }
        };

        ~LineSegmentND_common() = default;

        [[nodiscard]] ChildType transformed(const TranslationND<dimensions, Element> &tr) const { ChildType c(child()); c.transform(tr); return c; }
        void transform(const TranslationND<dimensions, Element> &tr)
        {
            int_beg.data() += tr.trVec().data();
            int_end.data() += tr.trVec().data();
        }
        [[nodiscard]] ChildType transformed(const detail::RotationArg<dimensions, Element> &rot) const { ChildType c(child()); c.transform(rot); return c; }
        void transform(const detail::RotationArg<dimensions, Element> &rot)
        {
            int_beg.data() = (rot.rotMat().data() * int_beg.data()).eval();
            int_end.data() = (rot.rotMat().data() * int_end.data()).eval();
            int_dir.data() = (rot.rotMat().data() * int_dir.data()).eval();
        }
        [[nodiscard]] ChildType transformed(const detail::RigidTfArg<dimensions, Element> &tf) const { ChildType c(child()); c.transform(tf); return c; }
        void transform(const detail::RigidTfArg<dimensions, Element> &tf)
        {
            int_beg.data() = (tf.rotMat().data() * int_beg.data() + tf.trVec().data()).eval();
            int_end.data() = (tf.rotMat().data() * int_end.data() + tf.trVec().data()).eval();
            int_dir.data() = (tf.rotMat().data() * int_dir.data()).eval();
        }

        VectorType beg() const { return int_beg; }
        VectorType end() const { return int_end; }
        //! Unit vector from beg towards end.
        VectorType direction() const { return int_dir; }

        //! Distance of the origin from the infinite line.
        typename VectorType::DistanceType distanceToOrigin() const { return distanceToPoint(VectorType::zeros()); }
        //! Perpendicular distance of `point` from the infinite line (not clamped to the segment).
        typename VectorType::DistanceType distanceToPoint(const VectorType &point) const { return std::sqrt(distanceToPointSquared(point)); }
        typename VectorType::DistanceType distanceToPointSquared(const VectorType &point) const
        {
            const typename VectorType::EigenType rel = point.data() - int_beg.data();
            const Element along = rel.dot(int_dir.data());
            return std::max(Element(0), rel.squaredNorm() - along * along);
        }
        typename VectorType::DistanceType length() const { return (int_end.data() - int_beg.data()).dot(int_dir.data()); }

        //! New beg (the direction is recomputed from the endpoints).
        void setBegin(const VectorType &beg) { int_beg = beg; updateDirection(); }
        //! Moves beg to beg + t (end - beg); the line stays the same, the direction flips if beg passes end (t > 1).
        void moveBegin(Element t)
        {
            int_beg.data() += t * (int_end.data() - int_beg.data());
            if (t > Element(1))
                int_dir = -int_dir;
        }
        //! New end (the direction is recomputed from the endpoints).
        void setEnd(const VectorType &end) { int_end = end; updateDirection(); }
        //! Moves end to beg + t (end - beg); the direction flips if end passes beg (t < 0).
        void moveEnd(Element t)
        {
            int_end.data() = int_beg.data() + t * (int_end.data() - int_beg.data());
            if (t < Element(0))
                int_dir = -int_dir;
        }
        void swapEndpoints()
        {
            std::swap(int_beg, int_end);
            int_dir = -int_dir;
        }

        //! (p - beg).(end - beg) / |end - beg|: the distance of p's projection from beg, along the line.
        typename VectorType::DistanceType scalarProjection(const VectorType &point) const
        {
            const typename VectorType::EigenType seg = int_end.data() - int_beg.data();
            return (point.data() - int_beg.data()).dot(seg) / seg.norm();
        }
        //! (p - beg).direction(): as scalarProjection, using the cached unit direction.
        typename VectorType::DistanceType scalarProjectionUnit(const VectorType &point) const
        {
            return (point.data() - int_beg.data()).dot(int_dir.data());
        }
        //! The projection of `point` on the infinite line.
        VectorType vectorProjection(const VectorType &point) const
        {
            return VectorType(typename VectorType::EigenType(int_beg.data() + scalarProjectionUnit(point) * int_dir.data()));
        }

        /*! The parameter t (0 = beg, 1 = end, along end - beg) of the point of this infinite line closest to the
         *  infinite line of `ls`. Returns false (t untouched) if the lines are parallel. */
        bool closestPoint(const LineSegmentND_common &ls, typename VectorType::DistanceType &t) const
        {
            typename VectorType::DistanceType t2;
            return closestPoint(*this, ls, t, t2);
        }
        //! As closestPoint, with t measured in units of length along direction() from beg.
        bool closestPointUnit(const LineSegmentND_common &ls, typename VectorType::DistanceType &t) const
        {
            typename VectorType::DistanceType t2;
            return closestPointUnit(*this, ls, t, t2);
        }

        /*! Intersects the infinite line with the axis-aligned box spanned by corner1 and corner2 (any two opposite
         *  corners). On success the outputs are the entry and exit parameters along direction() measured from beg
         *  (entry <= exit). Returns false if the line misses the box, including a line parallel to an axis but outside
         *  the box's slab for that axis (the published version wrongly accepted those). */
        bool cropByHyperRect(const VectorType &corner1, const VectorType &corner2, Element &segment_beg_t, Element &segment_end_t) const
        {
            Element t_min = std::numeric_limits<Element>::lowest(), t_max = std::numeric_limits<Element>::max();
            for (Eigen::Index i = 0; i < dimensions; ++i)
            {
                const Element lo = std::min(corner1.data()[i], corner2.data()[i]), hi = std::max(corner1.data()[i], corner2.data()[i]);
                const Element b = int_beg.data()[i], d = int_dir.data()[i];
                if (d == Element(0))
                {
                    if (b < lo || b > hi)
                        return false;
                    continue;
                }
                Element t1 = (lo - b) / d, t2 = (hi - b) / d;
                if (t1 > t2)
                    std::swap(t1, t2);
                t_min = std::max(t_min, t1);
                t_max = std::min(t_max, t2);
                if (t_min > t_max)
                    return false;
            }
            segment_beg_t = t_min;
            segment_end_t = t_max;
            return true;
        }
        //! As above, returning the entry and exit points.
        bool cropByHyperRect(const VectorType &corner1, const VectorType &corner2, VectorType &segment_beg, VectorType &segment_end) const
        {
            Element t1, t2;
            if (!cropByHyperRect(corner1, corner2, t1, t2))
                return false;
            segment_beg = pointAt(t1);
            segment_end = pointAt(t2);
            return true;
        }
        //! Replaces beg/end by the entry/exit points of the box (direction kept). Returns false, unchanged, if the line misses it.
        bool fitToHyperRect(const VectorType &corner1, const VectorType &corner2)
        {
            Element t1, t2;
            if (!cropByHyperRect(corner1, corner2, t1, t2))
                return false;
            const VectorType b = pointAt(t1), e = pointAt(t2);
            int_beg = b;
            int_end = e;
            return true;
        }

        /*! Parameters t1 (along ls1's end - beg) and t2 (along ls2's end - beg) of the closest points of the two
         *  infinite lines. Returns false (outputs untouched) if the lines are parallel, i.e. the determinant vanishes. */
        static bool closestPoint(const LineSegmentND_common &ls1, const LineSegmentND_common &ls2,
                                 typename VectorType::DistanceType &t1, typename VectorType::DistanceType &t2)
        {
            const typename VectorType::EigenType d1 = ls1.int_end.data() - ls1.int_beg.data();
            const typename VectorType::EigenType d2 = ls2.int_end.data() - ls2.int_beg.data();
            return solveClosest(d1, d2, ls1.int_beg.data() - ls2.int_beg.data(), t1, t2);
        }
        //! As closestPoint, with both parameters in units of length along the unit directions.
        static bool closestPointUnit(const LineSegmentND_common &ls1, const LineSegmentND_common &ls2,
                                     typename VectorType::DistanceType &t1, typename VectorType::DistanceType &t2)
        {
            return solveClosest(ls1.int_dir.data(), ls2.int_dir.data(), ls1.int_beg.data() - ls2.int_beg.data(), t1, t2);
        }

        static constexpr int dimensionality() { return dimensions; }

        static DistanceType distance(const LineSegmentND_common &l1, const LineSegmentND_common &l2)
        {
            return DistanceType(VectorType::angleShortest(l1.int_dir, l2.int_dir), l2.child().distanceToOrigin() - l1.child().distanceToOrigin());
        }

        //! Two random endpoints, beg first; each element static_cast<Element>(el_rnd_gen()).
        template<class ElRndSrc, typename = std::enable_if_t<std::is_invocable_v<const ElRndSrc &>>>
        static ChildType random(const ElRndSrc &el_rnd_gen)
        {
            const VectorType b = VectorType::random(el_rnd_gen);
            const VectorType e = VectorType::random(el_rnd_gen);
            return ChildType(b, e);
        }

    protected:
        VectorType int_beg, int_end, int_dir;

        LineSegmentND_common() = default;
        LineSegmentND_common(const VectorType &beg, const VectorType &end, const VectorType dir) : int_beg(beg), int_end(end), int_dir(dir) {}
        LineSegmentND_common(const LineSegmentND_common &ls) = default;
        LineSegmentND_common &operator=(const LineSegmentND_common &ls) = default;
        LineSegmentND_common(const VectorType &beg, const VectorType &end) : int_beg(beg), int_end(end) { updateDirection(); }

        void updateDirection() { int_dir = VectorType(typename VectorType::EigenType((int_end.data() - int_beg.data()).normalized())); }
        VectorType pointAt(Element t) const { return VectorType(typename VectorType::EigenType(int_beg.data() + t * int_dir.data())); }

    private:
        // Minimises |b1 + t1 d1 - (b2 + t2 d2)|^2 with w = b1 - b2 (normal equations of the two parameters).
        static bool solveClosest(const typename VectorType::EigenType &d1, const typename VectorType::EigenType &d2,
                                 const typename VectorType::EigenType &w, Element &t1, Element &t2)
        {
            const Element a = d1.squaredNorm(), b = d1.dot(d2), c = d2.squaredNorm(), d = d1.dot(w), e = d2.dot(w);
            const Element det = a * c - b * b;
            if (!(det > std::numeric_limits<Element>::epsilon() * a * c))
                return false;
            t1 = (b * e - c * d) / det;
            t2 = (a * e - b * d) / det;
            return true;
        }
        const ChildType &child() const { return static_cast<const ChildType &>(*this); }
    };

    //! General N-D line segment.
    template<int dimensions, typename Element>
    class LineSegmentND : public LineSegmentND_common<dimensions, Element, LineSegmentND>
    {
        typedef LineSegmentND_common<dimensions, Element, LineSegmentND> base;

    public:
        typedef typename base::VectorType VectorType;

        LineSegmentND() = default;
        LineSegmentND(const LineSegmentND &ls) = default;
        LineSegmentND(const VectorType &beg, const VectorType &end) : base(beg, end) {}          // implicit on purpose: {beg, end}
        LineSegmentND(const VectorType &beg, const VectorType &end, const VectorType dir) : base(beg, end, dir) {}
        LineSegmentND &operator=(const LineSegmentND &ls) = default;
    };

    //! 2D line segment: normal, crossings of two segments, rectangle cropping.
    template<typename Element>
    class LineSegmentND<2, Element> : public LineSegmentND_common<2, Element, LineSegmentND>
    {
        typedef LineSegmentND_common<2, Element, LineSegmentND> base;

    public:
        typedef typename base::ElementType ElementType;
        typedef typename base::VectorType VectorType;
        using base::setBegin;
        using base::setEnd;

        LineSegmentND() = default;
        LineSegmentND(const LineSegmentND &ls) = default;
        LineSegmentND(const VectorType &beg, const VectorType &end) : base(beg, end) {}          // implicit on purpose: {beg, end}
        LineSegmentND(const VectorType &beg, const VectorType &end, const VectorType dir) : base(beg, end, dir) {}
        LineSegmentND(ElementType beg_x, ElementType beg_y, ElementType end_x, ElementType end_y)
                : base(VectorType(beg_x, beg_y), VectorType(end_x, end_y)) {}
        LineSegmentND &operator=(const LineSegmentND &ls) = default;

        //! The direction turned by +90 degrees: (-dir.y, dir.x).
        VectorType normal() const { return VectorType(-this->int_dir.y(), this->int_dir.x()); }
        typename VectorType::DistanceType distanceToOrigin() const { return std::abs(this->int_beg.dot(normal())); }

        void setBegin(Element beg_x, Element beg_y) { base::setBegin(VectorType(beg_x, beg_y)); }
        void setEnd(Element end_x, Element end_y) { base::setEnd(VectorType(end_x, end_y)); }

        bool cropByRect(const VectorType &corner1, const VectorType &corner2, Element &t_beg, Element &t_end) const
        {
            return this->cropByHyperRect(corner1, corner2, t_beg, t_end);
        }
        bool cropByRect(const VectorType &corner1, const VectorType &corner2, VectorType &beg, VectorType &end) const
        {
            return this->cropByHyperRect(corner1, corner2, beg, end);
        }

        /*! Crossing of the two infinite lines: t_first along first's end - beg, t_second along second's end - beg
         *  (both within [0, 1] means the segments themselves cross). Returns false for parallel lines and then sets
         *  each t to max() or lowest() by the sign of its numerator. */
        static bool getCrossing(const LineSegmentND<2, Element> &first, const LineSegmentND<2, Element> &second, Element &t_first, Element &t_second)
        {
            return getCrossing(first.int_beg, first.int_end, second.int_beg, second.int_end, t_first, t_second);
        }
        //! As above, giving the crossing point (untouched for parallel lines).
        static bool getCrossing(const LineSegmentND<2, Element> &first, const LineSegmentND<2, Element> &second, VectorType &crossing)
        {
            return getCrossing(first.int_beg, first.int_end, second.int_beg, second.int_end, crossing);
        }
        static bool getCrossing(const VectorType &first_beg, const VectorType &first_end, const VectorType &second_beg,
                                const VectorType &second_end, Element &t_first, Element &t_second)
        {
            const VectorType d1 = first_end - first_beg, d2 = second_end - second_beg, w = second_beg - first_beg;
            const Element den = d1.cross(d2), num1 = w.cross(d2), num2 = w.cross(d1);
            if (den == Element(0))
            {
                t_first = num1 >= Element(0) ? std::numeric_limits<Element>::max() : std::numeric_limits<Element>::lowest();
                t_second = num2 >= Element(0) ? std::numeric_limits<Element>::max() : std::numeric_limits<Element>::lowest();
                return false;
            }
            t_first = num1 / den;
            t_second = num2 / den;
            return true;
        }
        static bool getCrossing(const VectorType &first_beg, const VectorType &first_end, const VectorType &second_beg,
                                const VectorType &second_end, VectorType &crossing)
        {
            Element t1, t2;
            if (!getCrossing(first_beg, first_end, second_beg, second_end, t1, t2))
                return false;
            crossing = first_beg + (first_end - first_beg) * t1;
            return true;
        }
    };

    //! 3D line segment.
    template<typename Element>
    class LineSegmentND<3, Element> : public LineSegmentND_common<3, Element, LineSegmentND>
    {
        typedef LineSegmentND_common<3, Element, LineSegmentND> base;

    public:
        typedef typename base::VectorType VectorType;

        LineSegmentND() = default;
        LineSegmentND(const LineSegmentND &ls) = default;
        LineSegmentND(const VectorType &beg, const VectorType &end) : base(beg, end) {}          // implicit on purpose: {beg, end}
        LineSegmentND(const VectorType &beg, const VectorType &end, const VectorType dir) : base(beg, end, dir) {}
        LineSegmentND &operator=(const LineSegmentND &ls) = default;
    };
}
