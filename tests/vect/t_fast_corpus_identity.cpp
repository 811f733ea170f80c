// The results of FTLS and AFTLS on all 300 inputs of the worst-case corpus, strict and split, and
// of the exact search called directly, pinned as digests: the speed-ups of the continuity repair and of the exact
// search must not change a single decision. Two digests:
// - decisions: every success/failure, range, polyline offset, break and failure boundary (integers): exact on every
//   platform;
// - numbers: the bits of every line's point, direction and squared error, every vertex and every reported crossing
//   distance. Pinned only where the arithmetic is the reference build's (x86-64 without FMA contraction): elsewhere
//   a fused multiply-add may round differently without any change of algorithm.
// A digest mismatch prints the new value; it must only change with a deliberate change of results.
#include <cstdint>
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "rtl/Vectorization.h"
#include "t_fast_corpus.h"

namespace
{
    struct Digest
    {
        uint64_t h = 1469598103934665603ull;   // FNV-1a, 64 bit
        void add(uint64_t v)
        {
            for (int k = 0; k < 8; ++k)
            {
                h ^= (v >> (8 * k)) & 0xffu;
                h *= 1099511628211ull;
            }
        }
        void add(double d)
        {
            uint64_t u;
            std::memcpy(&u, &d, sizeof u);
            add(u);
        }
    };

    struct Digests
    {
        Digest decisions, numbers;
    };

    template<class V>
    void addVectorizer(Digests &d, V &v, const rtl::fast_corpus::Case &c, bool split)
    {
        v.setSigma(c.sigma);
        v.setDelta(c.delta);
        v.setSplitAtInfeasibleCorners(split);
        const bool ok = v(c.pts);
        d.decisions.add(uint64_t(ok));
        d.decisions.add(uint64_t(v.indices().size()));
        for (const auto &r : v.indices())
        {
            d.decisions.add(uint64_t(r.first));
            d.decisions.add(uint64_t(r.second));
        }
        for (size_t o : v.polylineOffsets())
            d.decisions.add(uint64_t(o));
        for (const auto &b : v.breaks())
        {
            d.decisions.add(uint64_t(b.boundary));
            d.numbers.add(b.crossingDistance);
        }
        d.decisions.add(uint64_t(v.failure().has_value()));
        if (v.failure())
        {
            d.decisions.add(uint64_t(v.failure()->boundary));
            d.numbers.add(v.failure()->crossingDistance);
        }
        for (const auto &l : v.approximations())
            for (double x : {l.point().x(), l.point().y(), l.direction().x(), l.direction().y(), l.errSquaredCompute()})
                d.numbers.add(x);
        for (const auto &p : v.vertices())
        {
            d.numbers.add(p.x());
            d.numbers.add(p.y());
        }
    }

    void addSearch(Digests &d, const rtl::fast_corpus::Case &c, bool split)
    {
        typedef rtl::ApproximationTlsLine2D<double, double> Line;
        typedef rtl::PrecArrayBlocked<2, double, double> Arr;
        Arr a;
        a.resize(c.pts.size());
        a.precompute(c.pts);
        rtl::PartitionSearch2D<Arr, Line> s;
        s.setSigma(c.sigma);
        s.setDelta(c.delta);
        s.setAllowBreaks(split);
        std::vector<Line> lines;
        std::vector<std::pair<size_t, size_t>> idx;
        const bool ok = s(c.pts, a, lines, idx);
        d.decisions.add(uint64_t(ok));
        for (const auto &r : idx)
        {
            d.decisions.add(uint64_t(r.first));
            d.decisions.add(uint64_t(r.second));
        }
        if (!ok)
        {
            d.decisions.add(uint64_t(s.failure().boundary));
            d.numbers.add(s.failure().crossingDistance);
        }
        for (const auto &l : lines)
            d.numbers.add(l.errSquaredCompute());
    }
}

TEST(VectorizerFTLS, CorpusResultsUnchangedOnAll300Inputs)
{
#if defined(__OPTIMIZE__)
    const unsigned last = 300;
    const uint64_t decisions = 0xc02b3cab2bf5460aull, numbers = 0x9e01491f68bb0ef6ull;
#else
    // Unoptimized builds (e.g. the sanitizer build) take minutes for all 300: the first 60 inputs.
    const unsigned last = 60;
    const uint64_t decisions = 0x4e4273f41d6207acull, numbers = 0x3704692989c23e7dull;
#endif
    Digests d;
    rtl::VectorizerFTLSPolyline2D<double, double> ftls;
    rtl::VectorizerAFTLSPolyline2D<double, double> aftls;
    for (unsigned seed = 1; seed <= last; ++seed)
    {
        const auto c = rtl::fast_corpus::makeCase(seed);
        for (bool split : {false, true})
        {
            addVectorizer(d, ftls, c, split);
            addVectorizer(d, aftls, c, split);
            addSearch(d, c, split);
        }
    }
    EXPECT_EQ(d.decisions.h, decisions) << std::hex << "decisions digest 0x" << d.decisions.h;
#if defined(__x86_64__) && !defined(__FMA__)
    EXPECT_EQ(d.numbers.h, numbers) << std::hex << "numbers digest 0x" << d.numbers.h;
#endif
}
