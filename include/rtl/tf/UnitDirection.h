// The unit vector of a direction given by any finite non-zero vector, without overflow or underflow: scaling by the
// largest |element| first keeps the squared norm representable for elements near the type's limits (e.g. floats
// near 1e30, whose squares overflow to inf, or near 1e-30, whose squares flush to 0).
#pragma once

#include <cmath>

namespace rtl::detail
{
    //! Writes v / |v| into unit and returns true; returns false (unit untouched) for a zero or non-finite v.
    template<class EigenVector>
    bool unitDirection(const EigenVector &v, EigenVector &unit)
    {
        using Element = typename EigenVector::Scalar;
        const Element scale = v.cwiseAbs().maxCoeff();
        if (!(scale > Element(0)) || !std::isfinite(scale))
            return false;
        const EigenVector w = v / scale;   // largest |element| is now 1: its squared norm is in [1, size]
        unit = w / w.norm();
        return true;
    }
}
