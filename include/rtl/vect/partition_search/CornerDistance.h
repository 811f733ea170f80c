// Corner criteria of 2D polylines: where two consecutive TLS lines cross, measured from the corner's reference
// point, and the report of a corner that cannot be met within delta.
//
// The continuity criterion of FTLS/AFTLS: two consecutive ranges join when their lines cross within delta of the
// midpoint of the two boundary points (or of the shared point, when the ranges share one). Both functions are O(1)
// and return +infinity when the lines do not cross (parallel, or a non-finite crossing).
// Preconditions: 0 < boundary < pts.size() (crossingDistanceSquared); 0 < prev_end, next_first < pts.size().
#pragma once

#include <cstddef>
#include <limits>

#include "rtl/core/VectorND.h"

namespace rtl
{
    //! A corner of a 2D polyline that cannot be met within delta. boundary: chain index of the first point of the
    //! range after the corner; crossingDistance: distance of the two lines' crossing from the midpoint of points
    //! boundary - 1 and boundary (the continuity criterion's reference; +infinity for parallel lines, or when the
    //! failure is not at a corner, e.g. 3 points that fit no line: then boundary is 0); delta: the bound it exceeds.
    //! A break at a point shared by two ranges (split mode's cover, PartitionSearch2D::cover): boundary is the
    //! shared point, the first of the range after the corner, and the distance is measured from that point.
    struct CornerReport
    {
        size_t boundary{0};
        double crossingDistance{0};
        double delta{0};
    };

    namespace detail
    {
        //! Squared distance of the crossing of l1 and l2 from the midpoint of pts[boundary - 1] and pts[boundary];
        //! +infinity if the lines do not cross (parallel or non-finite crossing).
        template<class Approximation, class Points>
        typename Approximation::ComputeType crossingDistanceSquared(const Points &pts, const Approximation &l1, const Approximation &l2, size_t boundary)
        {
            typedef typename Approximation::ComputeType C;
            VectorND<2, C> x;
            if (!Approximation::getCrossingCompute(l1, l2, x))
                return std::numeric_limits<C>::infinity();
            const VectorND<2, C> m = (pts[boundary - 1].template cast<C>() + pts[boundary].template cast<C>()) * C(0.5);
            return (x - m).lengthSquared();
        }

        //! The corner criterion between a range ending at `prev_end` and the next one starting at `next_first`:
        //! the distance of the crossing from the midpoint of pts[prev_end - 1] and pts[next_first], i.e. the two
        //! boundary points (next_first == prev_end) or the shared point (next_first == prev_end - 1, cover()).
        template<class Approximation, class Points>
        typename Approximation::ComputeType cornerDistanceSquared(const Points &pts, const Approximation &l1, const Approximation &l2, size_t prev_end,
                                                                  size_t next_first)
        {
            typedef typename Approximation::ComputeType C;
            VectorND<2, C> x;
            if (!Approximation::getCrossingCompute(l1, l2, x))
                return std::numeric_limits<C>::infinity();
            const VectorND<2, C> m = (pts[prev_end - 1].template cast<C>() + pts[next_first].template cast<C>()) * C(0.5);
            return (x - m).lengthSquared();
        }
    }
}
