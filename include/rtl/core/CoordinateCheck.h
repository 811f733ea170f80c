// firstBeyond: the one finite/bounds check of coordinate arrays, used by the vectorizers' input check
// (vect/VectorizerBase.h) and by the bindings that take points from outside (the wasm adapter).
//
// Contract: firstBeyond(x, count, limit, gaps, copyTo) returns the index of the first x[i], i < count, that is out
// of bounds, or count when none is. Out of bounds: |x[i]| > limit (so +-Infinity always is, whatever the limit:
// a limit of at least the type's largest finite value is taken as that value), and NaN unless `gaps` (where NaN
// marks a missing point). With copyTo, x[0 .. count) is copied to copyTo in the same pass (the copy is complete
// only when the result is count). One pass over the input: blocks of kCheckBlock numbers are tested branch-free
// and the scan stops at the first failing block, whose failing index is then located inside it, so that a caller
// can report the offending coordinate without scanning the input again. O(count) time, no allocation.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>

namespace rtl
{
    namespace detail
    {
        //! Numbers tested per branch-free block of firstBeyond.
        constexpr std::size_t kCheckBlock = 256;

        //! Whether one number is out of bounds (see firstBeyond).
        template<typename E>
        inline bool beyond(E v, E lim, bool gaps)
        {
            const E a = std::abs(v);
            return gaps ? a > lim : !(a <= lim);
        }

        //! Whether some number of x[0 .. n) is out of bounds, without a branch per number; copies it to dst if
        //! given. For double, two lanes a step (GCC/clang vector extensions: SSE2 natively, SIMD128 in wasm):
        //! compilers do not vectorise a NaN-aware OR reduction written per number. With gaps the block keeps the
        //! largest |x| per lane (a > m ? a : m passes NaN over), else it ORs the masks of !(|x| <= lim).
        template<bool Gaps, typename E>
        inline bool blockBeyond(const E *x, std::size_t n, E lim, E *dst)
        {
            std::size_t i = 0;
            bool bad = false;
#if defined(__GNUC__)
            if constexpr (sizeof(E) == 8 && std::numeric_limits<E>::is_iec559)
            {
                typedef double V __attribute__((vector_size(16)));
                typedef long long M __attribute__((vector_size(16)));
                const M absMask = M{} + 0x7fffffffffffffffLL;
                const V limit = V{} + lim;
                V m0{}, m1{};
                M acc{};
                for (; i + 4 <= n; i += 4)
                {
                    V a, b;
                    std::memcpy(&a, x + i, sizeof a);
                    std::memcpy(&b, x + i + 2, sizeof b);
                    if (dst != nullptr)
                    {
                        std::memcpy(dst + i, &a, sizeof a);
                        std::memcpy(dst + i + 2, &b, sizeof b);
                    }
                    a = (V)((M)a & absMask);
                    b = (V)((M)b & absMask);
                    if constexpr (Gaps)
                    {
                        m0 = a > m0 ? a : m0;
                        m1 = b > m1 ? b : m1;
                    }
                    else
                    {
                        acc |= ~(a <= limit);  // NaN compares false: out of bounds
                        acc |= ~(b <= limit);
                    }
                }
                if constexpr (Gaps)
                    bad = (m0[0] > lim) | (m0[1] > lim) | (m1[0] > lim) | (m1[1] > lim);
                else
                    bad = (acc[0] | acc[1]) != 0;
            }
#endif
            for (; i < n; ++i)
            {
                if (dst != nullptr) dst[i] = x[i];
                bad |= beyond(x[i], lim, Gaps);
            }
            return bad;
        }

        template<bool Gaps, typename E>
        std::size_t firstBeyondIn(const E *x, std::size_t count, E lim, E *copyTo)
        {
            for (std::size_t b = 0; b < count; b += kCheckBlock)
            {
                const std::size_t n = count - b < kCheckBlock ? count - b : kCheckBlock;
                if (blockBeyond<Gaps>(x + b, n, lim, copyTo != nullptr ? copyTo + b : nullptr))
                    for (std::size_t i = b; i < b + n; ++i)
                        if (beyond(x[i], lim, Gaps)) return i;
            }
            return count;
        }

        //! Index of the first out-of-bounds number of x[0 .. count), count if none (see the file comment).
        //! Not inlined: one copy of the loops per element type, called from several bindings.
        template<typename E>
        [[gnu::noinline]] std::size_t firstBeyond(const E *x, std::size_t count, double limit, bool gaps,
                                                  E *copyTo = nullptr)
        {
            const E max = std::numeric_limits<E>::max();
            const E lim = limit >= static_cast<double>(max) ? max : static_cast<E>(limit);
            return gaps ? firstBeyondIn<true>(x, count, lim, copyTo) : firstBeyondIn<false>(x, count, lim, copyTo);
        }
    } // namespace detail
} // namespace rtl
