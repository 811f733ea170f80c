// CAR_Segmenter's neighbour-flag pass skips the validity test of the earlier point (and the link's own) when the
// squared upper bound is finite: a non-finite coordinate then makes the squared distance NaN or +inf, which no
// threshold admits. These scans pin that against the brute-force reference: gaps with a single non-finite
// coordinate (either infinity or NaN), runs of equal gaps, finite coordinates whose squares overflow (distance +inf,
// or 0 between equal points), and upper bounds that are small, whose square overflows, or infinite.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "seg_check.h"

namespace
{
    template<class V>
    class CarGaps : public ::testing::Test {};
    using Types = ::testing::Types<rtl::VectorND<2, float>, rtl::VectorND<2, double>, rtl::VectorND<3, float>, rtl::VectorND<3, double>>;
    TYPED_TEST_SUITE(CarGaps, Types);

    TYPED_TEST(CarGaps, PartialGapsAndOverflowMatchReference)
    {
        using V = TypeParam;
        using E = typename V::ElementType;
        constexpr int D = V::dimensionality();
        const E inf = std::numeric_limits<E>::infinity(), nan = std::numeric_limits<E>::quiet_NaN();
        const E huge = std::sqrt(std::numeric_limits<E>::max()) * E(4);   // its square overflows
        std::mt19937 rng(7 + D + static_cast<unsigned>(sizeof(E)));
        std::uniform_real_distribution<double> u(0, 1);
        for (int trial = 0; trial < 240; ++trial)
        {
            const size_t n = 1 + static_cast<size_t>(u(rng) * (trial < 30 ? 10 : 200));
            const size_t step = 1 + static_cast<size_t>(u(rng) * 6);
            const V origin = V::zeros();
            std::vector<V> pts;
            V last = V::zeros();
            for (size_t i = 0; i < n; ++i)
            {
                const double a = 2 * M_PI * static_cast<double>(i) / static_cast<double>(n), w = u(rng);
                typename V::EigenType e = V::EigenType::Zero();
                e[0] = static_cast<E>(3 * std::cos(a));
                e[1] = static_cast<E>(3 * std::sin(a));
                const E bad[] = {inf, -inf, nan};
                if (w >= 0.12 && w < 0.32) e[static_cast<int>(u(rng) * D)] = bad[static_cast<int>(u(rng) * 3)];
                else if (w >= 0.32 && w < 0.42) e[static_cast<int>(u(rng) * D)] = (u(rng) < 0.5 ? huge : -huge) * (1 + E(i) / 4096);
                // a repeat: runs of gaps, of huge points. Otherwise every valid point is distinct (the huge ones by
                // their factor), so that the reference maps cluster points back to scan indices without ambiguity.
                const V p = w < 0.12 && i > 0 ? last : V(e);
                pts.push_back(p);
                last = p;
            }
            const E lb = static_cast<E>(0.3 * u(rng));
            const double kind = u(rng);
            const E ub = kind < 0.4 ? lb + static_cast<E>(2 * u(rng)) : kind < 0.7 ? huge : inf;
            const std::string what = "trial " + std::to_string(trial) + " n=" + std::to_string(n) + " step=" +
                                     std::to_string(step) + " ub=" + std::to_string(static_cast<double>(ub));
            segcheck::checkCar(pts, origin, step, lb, ub, what);
            if (::testing::Test::HasFailure()) return;
        }
    }
}
