// The chord a 2D line cuts from the disc of radius delta about a corner's reference point, as the angles of its
// ends: the geometric reduction behind the chord test of the exact partition search.
//
// Two lines meet within delta of m (their crossing lies in the disc) exactly when their chords cross, i.e. when
// the angular intervals [p, q] of the two chords interleave. cornerChord classifies each line: `regular` (the
// interval is exact up to the returned error bound), `tangent` (the line passes too close to the disc's edge, or
// its rounding is too large, for the angles to decide: the caller tests such lines exactly), `misses` (the line
// does not reach the disc, so it can meet no line within delta there).
// Preconditions: delta > 0 and delta_squared = delta * delta. O(1).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "rtl/core/VectorND.h"

namespace rtl
{
    namespace detail
    {
        //! A chord as the angles of its ends seen from the disc centre; invariant for `regular`: p < q, both in (-pi, pi].
        template<typename C>
        struct CornerChord
        {
            static constexpr int regular = 0, tangent = 1, misses = 2;
            C p, q;
            int kind;
        };

        //! The chord that `line` cuts from the disc of radius `delta` about m; `eta` grows to the angular error bound
        //! of the returned angles (it is left unchanged for `tangent` and `misses`).
        template<class Approximation, typename C>
        CornerChord<C> cornerChord(const Approximation &line, const VectorND<2, C> &m, C delta, C delta_squared, C &eta)
        {
            typedef VectorND<2, C> CV;
            typedef CornerChord<C> Chord;
            typedef typename Approximation::ElementType E;
            const C eps = std::numeric_limits<C>::epsilon();
            const C eps_dir = std::max(eps, static_cast<C>(std::numeric_limits<E>::epsilon()));
            const CV f = line.projectCompute(m), r = f - m;
            const CV c = line.point().template cast<C>();
            CV d = line.direction().template cast<C>();
            const C dl = std::sqrt(d.lengthSquared());
            const C rl = std::sqrt(r.lengthSquared());
            // Rounding of the foot f (and so of |r|): the centroid, m and the lever arm between them.
            const C err_r = 16 * eps * (std::sqrt(m.lengthSquared()) + 2 * std::sqrt(c.lengthSquared()) + std::sqrt(f.lengthSquared()));
            const C tau = C(1e-3);
            if (!(dl > 0) || !std::isfinite(rl) || !std::isfinite(err_r) || !(err_r < tau * delta / 4))
                return Chord{0, 0, Chord::tangent};
            if (rl > delta * (1 + tau))
                return Chord{0, 0, Chord::misses};
            if (rl > delta * (1 - tau))
                return Chord{0, 0, Chord::tangent};
            d = d * (C(1) / dl);
            const C t = std::sqrt(delta_squared - rl * rl);
            const CV e1 = r + d * t, e2 = r - d * t;
            const C a1 = std::atan2(e1.y(), e1.x()), a2 = std::atan2(e2.y(), e2.x());
            eta = std::max(eta, 2 * err_r / (delta * std::sqrt(tau)) + 4 * eps_dir + 8 * eps);
            return Chord{std::min(a1, a2), std::max(a1, a2), Chord::regular};
        }
    }
}
