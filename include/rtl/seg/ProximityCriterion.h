// The proximity criterion shared by CAR_Segmenter and IA_Segmenter, in one place so that both segmenters (and the
// tests that check them) evaluate it with the same arithmetic, bit for bit.
//
// A point p joins an earlier point q (at most `step` places back in scan order) when
//     |p - q|^2 <= t(p)^2,   t(p) = clamp(scaling * |p - origin|, lower_bound, upper_bound),
// evaluated as |p - q|^2 <= clamp(scaling^2 |p - origin|^2, lower_bound^2, upper_bound^2),
// i.e. the threshold belongs to the later point of the pair. Points with a non-finite coordinate are gaps.
#pragma once

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace rtl::detail
{
    //! Squared distance of two D-element arrays, summed in coordinate order.
    template<int D, typename E>
    inline E squaredDistance(const E *a, const E *b)
    {
        E s = E(0);
        for (int k = 0; k < D; ++k)
        {
            const E d = a[k] - b[k];
            s += d * d;
        }
        return s;
    }

    //! The squared threshold t(p)^2 = clamp(scaling^2 |p - origin|^2, lower^2, upper^2), from |p - origin|^2: the
    //! same value as squaring the clamped threshold, without a square root per point (so loops vectorise).
    //! A negative scaling acts as its absolute value. NaN in, NaN out.
    template<typename E>
    struct SquaredThreshold
    {
        E scaling_sq, lower_sq, upper_sq;
        SquaredThreshold(E scaling, E lower, E upper) : scaling_sq(scaling * scaling), lower_sq(lower * lower), upper_sq(upper * upper) {}
        E operator()(E origin_dist_sq) const
        {
            E t = scaling_sq * origin_dist_sq;
            t = t < lower_sq ? lower_sq : t;
            return t > upper_sq ? upper_sq : t;
        }
    };

    //! True when every coordinate is finite (x - x is 0 for finite x, NaN for NaN and infinities).
    template<int D, typename E>
    inline bool isFinite(const E *a)
    {
        bool ok = true;
        for (int k = 0; k < D; ++k) ok &= (a[k] - a[k]) == E(0);
        return ok;
    }

    //! Threshold scaling of CAR_Segmenter: the arc of `step` angular increments of a closed scan of n points.
    template<typename E>
    inline E circularScaling(std::size_t step, std::size_t n)
    {
        return static_cast<E>(2.0 * 3.14159265358979323846264338327950288 * static_cast<double>(step) / static_cast<double>(n));
    }

    //! The checks done by every processing entry point: 0 <= lower <= upper (upper may be +inf), finite origin.
    template<typename E>
    inline void checkParameters(const char *who, E lower, E upper, bool origin_finite)
    {
        if (!(lower >= E(0)) || !(upper >= lower))
            throw std::invalid_argument(std::string(who) + ": bounds must satisfy 0 <= lower <= upper, got lower = " +
                                        std::to_string(lower) + ", upper = " + std::to_string(upper));
        if (!origin_finite) throw std::invalid_argument(std::string(who) + ": the origin must be finite");
    }

    //! Evaluates the criterion for a pair of vectors; used by tests and by the segmenters' slow paths.
    template<class Vector>
    inline bool meetsCriterion(const Vector &earlier, const Vector &later, const Vector &origin,
                               typename Vector::ElementType scaling, typename Vector::ElementType lower,
                               typename Vector::ElementType upper)
    {
        constexpr int D = Vector::dimensionality();
        using E = typename Vector::ElementType;
        const E *p = later.data().data();
        const E tsq = SquaredThreshold<E>(scaling, lower, upper)(squaredDistance<D, E>(p, origin.data().data()));
        return squaredDistance<D, E>(p, earlier.data().data()) <= tsq;
    }
}
