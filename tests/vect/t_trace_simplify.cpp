// Traces of the incremental TLS, Douglas-Peucker and Reumann-Witkam vectorizers (rtl/vect/SimplifyTrace.h):
// known-answer traces on small hand-checked inputs; on every chain of the real scans in tests/data the replayed
// trace equals the untraced result exactly, every reported RMS / distance agrees with an independent
// recomputation, and the reported decisions follow from the reported numbers.
#include <cmath>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "rtl/Vectorization.h"
#include "rtl/io/CarmenLog.h"
#include "rtl/io/OrganizedLidar.h"
#include "scan_chains.h"
#include "vect_reference.h"

using namespace vect_test;

// RTL's names still denote the untraced classes.
static_assert(std::is_same_v<rtl::VectorizerDouglasPeucker2f, rtl::VectorizerDouglasPeuckerND<2, float, rtl::NoTrace>>);
static_assert(std::is_same_v<rtl::VectorizerReumannWitkam3d, rtl::VectorizerReumannWitkamND<3, double, rtl::NoTrace>>);
static_assert(std::is_base_of_v<rtl::detail::VectorizerIncremental<rtl::ApproximationTlsLine2D<float, double>, rtl::NoTrace>,
                                rtl::VectorizerITLSProjections2D<float, double>>);

namespace
{
    template<class T, class Log>
    std::vector<T> eventsOf(const Log &log)
    {
        std::vector<T> out;
        for (const auto &e : log.events)
            if (const T *t = std::get_if<T>(&e))
                out.push_back(*t);
        return out;
    }

    //! |reported - reference| within 1e-9 of max(|reference|, scale) (scale: the bound it is compared with, so that
    //! values near zero are compared at the precision that matters for the decision).
    void expectClose(double reported, double reference, double scale, const char *what)
    {
        EXPECT_NEAR(reported, reference, 1e-9 * std::max(std::abs(reference), scale)) << what;
    }

    // ---- replays (as documented in SimplifyTrace.h) ----

    struct ItlsReplay
    {
        std::vector<Range> ranges;                         // from close / tail / tailRange
        std::vector<Range> segmentRanges;                  // from segment
        std::vector<std::vector<double>> segmentEnds;      // x0 y0 [z0] x1 y1 [z1]
    };

    ItlsReplay replay(const rtl::ItlsTraceLog &log)
    {
        ItlsReplay r;
        bool inTail = false;
        for (const auto &e : log.events)
        {
            if (const auto *c = std::get_if<rtl::ItlsClose>(&e))
            {
                EXPECT_FALSE(inTail);
                r.ranges.emplace_back(c->first, c->end);
            }
            else if (const auto *t = std::get_if<rtl::ItlsTail>(&e))
            {
                EXPECT_LE(t->kept, r.ranges.size());
                r.ranges.resize(t->kept);
                inTail = true;
            }
            else if (const auto *tr = std::get_if<rtl::ItlsTailRange>(&e))
            {
                EXPECT_TRUE(inTail);
                r.ranges.emplace_back(tr->first, tr->end);
            }
            else if (const auto *s = std::get_if<rtl::ItlsSegment>(&e))
            {
                EXPECT_EQ(s->range, r.segmentRanges.size());
                r.segmentRanges.emplace_back(s->first, s->end);
                std::vector<double> v;
                s->fields([&](const char *name, auto value) {
                    const std::string n(name);
                    if (n != "range" && n != "first" && n != "end") v.push_back(static_cast<double>(value));
                });
                r.segmentEnds.push_back(v);
            }
        }
        return r;
    }

    std::vector<size_t> replay(const rtl::DpTraceLog &log)
    {
        std::vector<char> kept;
        for (const auto &e : log.events)
        {
            if (const auto *s = std::get_if<rtl::DpStart>(&e))
            {
                kept.assign(s->count, 0);
                kept.front() = kept.back() = 1;
            }
            else if (const auto *r = std::get_if<rtl::DpRange>(&e); r && r->split)
                kept.at(r->farthest) = 1;
        }
        std::vector<size_t> keys;
        for (size_t i = 0; i < kept.size(); ++i)
            if (kept[i]) keys.push_back(i);
        return keys;
    }

    std::vector<size_t> replay(const rtl::RwTraceLog &log)
    {
        std::vector<size_t> keys;
        for (const auto &k : eventsOf<rtl::RwKeep>(log))
            keys.push_back(k.index);
        return keys;
    }

    //! The polyline vertices of a point-elimination result equal the points at `keys`, exactly.
    template<class Segment, class V>
    void expectPolylineThrough(const std::vector<Segment> &out, const std::vector<V> &pts, const std::vector<size_t> &keys)
    {
        ASSERT_EQ(out.size() + 1, keys.size());
        for (size_t i = 0; i < out.size(); ++i)
        {
            EXPECT_EQ(out[i].beg(), pts[keys[i]]) << "segment " << i;
            EXPECT_EQ(out[i].end(), pts[keys[i + 1]]) << "segment " << i;
        }
    }

    //! Independent distance of p from the line through a and b (from a if they coincide), in long double.
    template<class V>
    double refLineDistance(const V &p, const V &a, const V &b)
    {
        constexpr int d = V::dimensionality();
        long double v[d], u[d], uu = 0, vu = 0;
        for (int k = 0; k < d; ++k)
        {
            v[k] = static_cast<long double>(p[k]) - static_cast<long double>(a[k]);
            u[k] = static_cast<long double>(b[k]) - static_cast<long double>(a[k]);
            uu += u[k] * u[k];
            vu += v[k] * u[k];
        }
        long double r2 = 0;
        for (int k = 0; k < d; ++k)
        {
            const long double w = uu > 0 ? v[k] - u[k] * (vu / uu) : v[k];
            r2 += w * w;
        }
        return static_cast<double>(std::sqrt(r2));
    }

    template<class V>
    bool finitePoint(const V &p)
    {
        for (int k = 0; k < V::dimensionality(); ++k)
            if (!std::isfinite(p[k])) return false;
        return true;
    }

    // ---- the checks run on every chain ----

    //! ITLS traced vs untraced on one chain, the replay, and every reported number.
    template<class Traced, class Plain, class V>
    void checkItls(Traced &traced, Plain &plain, rtl::ItlsTraceLog &log, const std::vector<V> &pts, double sigma)
    {
        constexpr int d = V::dimensionality();
        log.clear();
        const bool ok = plain(pts);
        ASSERT_EQ(traced(pts), ok);
        ASSERT_TRUE(ok);
        EXPECT_EQ(traced.indices(), plain.indices());
        const auto &segs = plain.lineSegments();
        ASSERT_EQ(traced.lineSegments().size(), segs.size());
        for (size_t i = 0; i < segs.size(); ++i)
        {
            EXPECT_EQ(traced.lineSegments()[i].beg(), segs[i].beg());
            EXPECT_EQ(traced.lineSegments()[i].end(), segs[i].end());
        }

        const ItlsReplay r = replay(log);
        EXPECT_EQ(r.ranges, plain.indices());
        EXPECT_EQ(r.segmentRanges, plain.indices());
        ASSERT_EQ(r.segmentEnds.size(), segs.size());
        for (size_t i = 0; i < segs.size(); ++i)
        {
            ASSERT_EQ(r.segmentEnds[i].size(), size_t(2 * d));
            for (int k = 0; k < d; ++k)
            {
                EXPECT_EQ(r.segmentEnds[i][k], static_cast<double>(segs[i].beg()[k]));
                EXPECT_EQ(r.segmentEnds[i][d + k], static_cast<double>(segs[i].end()[k]));
            }
        }

        const auto refRms2 = [&](size_t b, size_t e) { return refFit<d>(pts, b, e).lineErr(); };
        const double s2 = sigma * sigma;
        const auto start = eventsOf<rtl::ItlsStart>(log);
        ASSERT_EQ(start.size(), 1u);
        EXPECT_EQ(start[0].count, pts.size());
        EXPECT_DOUBLE_EQ(start[0].sigma, sigma);
        // Every point is added once to the range it starts or continues, in order; a failed add is followed by the
        // close and the point's add as the first of the next range.
        size_t expectIndex = 0, first = 0;
        bool lastFailed = false;
        for (const auto &e : log.events)
        {
            if (const auto *a = std::get_if<rtl::ItlsAdd>(&e))
            {
                EXPECT_EQ(a->first, first);
                EXPECT_EQ(a->index, lastFailed ? expectIndex - 1 : expectIndex);
                if (!lastFailed) ++expectIndex;
                lastFailed = false;
                EXPECT_EQ(a->count, a->index + 1 - a->first);
                EXPECT_EQ(a->tested, a->count >= 3);
                const double ref = refRms2(a->first, a->index + 1);
                expectClose(a->rms * a->rms, ref, s2, "add rms^2");
                if (!a->tested) EXPECT_TRUE(a->fits);
                else if (a->fits) EXPECT_LT(ref, s2 * (1 + 1e-9));
                else EXPECT_GT(ref, s2 * (1 - 1e-9));
                if (!a->fits) lastFailed = true;
            }
            else if (const auto *c = std::get_if<rtl::ItlsClose>(&e))
            {
                EXPECT_EQ(c->first, first);
                expectClose(c->rms * c->rms, refRms2(c->first, c->end), s2, "close rms^2");
                if (c->atEnd)
                {
                    EXPECT_EQ(c->end, pts.size());
                    EXPECT_TRUE(std::isnan(c->rmsWithNext));
                }
                else
                {
                    EXPECT_TRUE(lastFailed);
                    EXPECT_EQ(c->end + 1, expectIndex);
                    expectClose(c->rmsWithNext * c->rmsWithNext, refRms2(c->first, c->end + 1), s2, "close rmsWithNext^2");
                    EXPECT_GT(c->rmsWithNext * c->rmsWithNext, s2 * (1 - 1e-9));
                    first = c->end;
                }
            }
            else if (const auto *t = std::get_if<rtl::ItlsTailRange>(&e))
                expectClose(t->rms * t->rms, refRms2(t->first, t->end), s2, "tailRange rms^2");
            else if (const auto *t = std::get_if<rtl::ItlsTail>(&e))
            {
                EXPECT_EQ(t->index, pts.size() - 1);
                EXPECT_EQ(expectIndex, pts.size());
            }
        }
        EXPECT_EQ(expectIndex, pts.size());
    }

    //! DP traced vs untraced on one chain, the replay, the recursion order and every reported distance.
    template<class Traced, class Plain, class V>
    void checkDp(Traced &traced, Plain &plain, rtl::DpTraceLog &log, const std::vector<V> &pts, double eps, double rel = 1e-9)
    {
        typedef typename Plain::LineSegmentType Segment;
        std::vector<Segment> a, b;
        log.clear();
        plain(pts, a);
        traced(pts, b);
        ASSERT_EQ(a.size(), b.size());
        for (size_t i = 0; i < a.size(); ++i)
        {
            EXPECT_EQ(a[i].beg(), b[i].beg());
            EXPECT_EQ(a[i].end(), b[i].end());
        }
        const auto keys = replay(log);
        expectPolylineThrough(a, pts, keys);

        // The recursion: a stack of ranges, the left part examined before the right one.
        std::vector<Range> stack{{0, pts.size() - 1}};
        const auto ranges = eventsOf<rtl::DpRange>(log);
        size_t next = 0;
        while (!stack.empty())
        {
            const Range cur = stack.back();
            stack.pop_back();
            if (cur.second - cur.first < 2) continue;
            ASSERT_LT(next, ranges.size());
            const rtl::DpRange &r = ranges[next++];
            EXPECT_EQ(r.first, cur.first);
            EXPECT_EQ(r.last, cur.second);
            EXPECT_DOUBLE_EQ(r.epsilon, eps);
            double best = 0;
            for (size_t i = r.first + 1; i < r.last; ++i)
                if (finitePoint(pts[i]))
                    best = std::max(best, refLineDistance(pts[i], pts[r.first], pts[r.last]));
            if (r.farthest != r.first)
            {
                ASSERT_GT(r.farthest, r.first);
                ASSERT_LT(r.farthest, r.last);
                expectClose(r.distance, refLineDistance(pts[r.farthest], pts[r.first], pts[r.last]), eps, "dp distance");
            }
            else
                EXPECT_EQ(r.distance, 0.0);
            // In float the decisions compare float distances: the farthest point may differ from the true one by
            // float rounding (`rel`).
            EXPECT_NEAR(r.distance, best, rel * std::max(best, eps)) << "dp distance is the maximum";
            EXPECT_EQ(r.split, r.distance > eps) << "range [" << r.first << ", " << r.last << "]";
            if (r.split)
            {
                stack.emplace_back(r.farthest, r.last);
                stack.emplace_back(r.first, r.farthest);
            }
        }
        EXPECT_EQ(next, ranges.size());
    }

    //! RW traced vs untraced on one chain, the replay, and every strip and exit.
    template<class Traced, class Plain, class V>
    void checkRw(Traced &traced, Plain &plain, rtl::RwTraceLog &log, const std::vector<V> &pts, double eps, double rel)
    {
        typedef typename Plain::LineSegmentType Segment;
        std::vector<Segment> a, b;
        log.clear();
        plain(pts, a);
        traced(pts, b);
        ASSERT_EQ(a.size(), b.size());
        for (size_t i = 0; i < a.size(); ++i)
        {
            EXPECT_EQ(a[i].beg(), b[i].beg());
            EXPECT_EQ(a[i].end(), b[i].end());
        }
        expectPolylineThrough(a, pts, replay(log));

        // Strip, then its exit: every point between the strip's through point and the exit lies inside it.
        size_t key = 0, through = 0;
        bool open = false;
        for (const auto &e : log.events)
        {
            if (const auto *s = std::get_if<rtl::RwStrip>(&e))
            {
                EXPECT_DOUBLE_EQ(s->epsilon, eps);
                key = s->key; through = s->through; open = true;
                EXPECT_NE(pts[key], pts[through]);
            }
            else if (const auto *x = std::get_if<rtl::RwExit>(&e))
            {
                ASSERT_TRUE(open);
                EXPECT_EQ(x->key, key);
                EXPECT_GT(x->index, through);
                const double ref = refLineDistance(pts[x->index], pts[key], pts[through]);
                EXPECT_NEAR(x->distance, ref, 1e-9 * std::max(ref, eps));
                EXPECT_GT(x->distance, eps * (1 - rel));
                for (size_t i = through + 1; i < x->index; ++i)
                    EXPECT_LE(refLineDistance(pts[i], pts[key], pts[through]), eps * (1 + rel)) << "point " << i;
                open = false;
            }
        }
        if (open)
        {
            for (size_t i = through + 1; i < pts.size(); ++i)
                EXPECT_LE(refLineDistance(pts[i], pts[key], pts[through]), eps * (1 + rel)) << "point " << i;
        }
    }


    template<int d>
    std::vector<rtl::VectorND<d, double>> asDouble(const std::vector<rtl::VectorND<d, float>> &pts)
    {
        std::vector<rtl::VectorND<d, double>> out;
        for (const auto &p : pts)
            out.push_back(p.template cast<double>());
        return out;
    }
}

// ---- known answers ----

TEST(TraceSimplify, DouglasPeuckerZigzag)
{
    // Hand-checked: chord (0,0)-(4,0) gives |y|: 2, 1, 1.5 -> point 1 at 2 (split); chord (1,2)-(4,0), u = (3,-2):
    // |cross| 7 and 2.5 over sqrt(13) -> point 2 at 1.9415 (split); chord (2,-1)-(4,0), u = (2,1): point 3 at
    // |1*1 - 2.5*2| / sqrt(5) = 1.7889 < 1.8 (no split). The empty ranges [0,1], [1,2] are not examined.
    const std::vector<rtl::Vector2d> pts{{0, 0}, {1, 2}, {2, -1}, {3, 1.5}, {4, 0}};
    rtl::DpTraceLog log;
    rtl::VectorizerDouglasPeuckerND<2, double, rtl::DpTraceLog> dp(1.8);
    dp.setObserver(&log);
    std::vector<rtl::LineSegment2d> out;
    dp(pts, out);
    ASSERT_EQ(log.size(), 4u);
    const auto &s = std::get<rtl::DpStart>(log.events[0]);
    EXPECT_EQ(s.count, 5u);
    EXPECT_EQ(s.epsilon, 1.8);
    const struct { size_t first, last, farthest; double distance; bool split; } expected[] = {
        {0, 4, 1, 2.0, true}, {1, 4, 2, 7 / std::sqrt(13.0), true}, {2, 4, 3, 4 / std::sqrt(5.0), false}};
    for (size_t k = 0; k < 3; ++k)
    {
        const auto &r = std::get<rtl::DpRange>(log.events[k + 1]);
        EXPECT_EQ(r.first, expected[k].first) << k;
        EXPECT_EQ(r.last, expected[k].last) << k;
        EXPECT_EQ(r.farthest, expected[k].farthest) << k;
        EXPECT_NEAR(r.distance, expected[k].distance, 1e-12) << k;
        EXPECT_EQ(r.split, expected[k].split) << k;
        EXPECT_EQ(r.epsilon, 1.8);
    }
    EXPECT_EQ(replay(log), (std::vector<size_t>{0, 1, 2, 4}));
    expectPolylineThrough(out, pts, {0, 1, 2, 4});
}

TEST(TraceSimplify, DouglasPeuckerCoincidentEndsAndNaN)
{
    // Closed loop: the end points coincide, so distances are to point 0; the NaN point is never farthest.
    const double nan = std::nan("");
    const std::vector<rtl::Vector2d> pts{{0, 0}, {1, 0}, {nan, 0}, {1, 1}, {0, 0}};
    rtl::DpTraceLog log;
    rtl::VectorizerDouglasPeuckerND<2, double, rtl::DpTraceLog> dp(0.5);
    dp.setObserver(&log);
    std::vector<rtl::LineSegment2d> out;
    dp(pts, out);
    const auto ranges = eventsOf<rtl::DpRange>(log);
    ASSERT_GE(ranges.size(), 1u);
    EXPECT_EQ(ranges[0].farthest, 3u);
    EXPECT_NEAR(ranges[0].distance, std::sqrt(2.0), 1e-15);
    EXPECT_TRUE(ranges[0].split);
    // [0,3]: point 1 (line (0,0)-(1,1): distance 1/sqrt(2)), point 2 is NaN.
    ASSERT_EQ(ranges.size(), 3u);
    EXPECT_EQ(ranges[1].first, 0u);
    EXPECT_EQ(ranges[1].last, 3u);
    EXPECT_EQ(ranges[1].farthest, 1u);
    EXPECT_NEAR(ranges[1].distance, std::sqrt(0.5), 1e-15);
    EXPECT_TRUE(ranges[1].split);
    // [1,3]: only the NaN point inside: nothing to show.
    EXPECT_EQ(ranges[2].farthest, 1u);
    EXPECT_EQ(ranges[2].distance, 0.0);
    EXPECT_FALSE(ranges[2].split);
    EXPECT_EQ(replay(log), (std::vector<size_t>{0, 1, 3, 4}));
}

TEST(TraceSimplify, ReumannWitkamKnownAnswer)
{
    // A duplicate start point, then along x, a step up: strip 0 -> 2 (point 1 repeats point 0); point 5 at
    // y = 1 leaves it (distance 1 > 0.3), so point 4 becomes key and the strip 4 -> 5 runs up to the end.
    const std::vector<rtl::Vector2d> pts{{0, 0}, {0, 0}, {1, 0}, {2, 0.1}, {3, 0}, {3, 1}, {3, 2}, {3.1, 3}};
    rtl::RwTraceLog log;
    rtl::VectorizerReumannWitkamND<2, double, rtl::RwTraceLog> rw(0.3);
    rw.setObserver(&log);
    std::vector<rtl::LineSegment2d> out;
    rw(pts, out);
    ASSERT_EQ(log.size(), 7u);
    EXPECT_EQ(std::get<rtl::RwStart>(log.events[0]).count, 8u);
    EXPECT_NEAR(std::get<rtl::RwStart>(log.events[0]).epsilon, 0.3, 1e-7);   // setEpsilon takes a float
    EXPECT_EQ(std::get<rtl::RwKeep>(log.events[1]).index, 0u);
    const auto &s0 = std::get<rtl::RwStrip>(log.events[2]);
    EXPECT_EQ(s0.key, 0u);
    EXPECT_EQ(s0.through, 2u);
    const auto &x = std::get<rtl::RwExit>(log.events[3]);
    EXPECT_EQ(x.index, 5u);
    EXPECT_EQ(x.key, 0u);
    EXPECT_NEAR(x.distance, 1.0, 1e-15);
    EXPECT_EQ(std::get<rtl::RwKeep>(log.events[4]).index, 4u);
    const auto &s1 = std::get<rtl::RwStrip>(log.events[5]);
    EXPECT_EQ(s1.key, 4u);
    EXPECT_EQ(s1.through, 5u);
    EXPECT_EQ(std::get<rtl::RwKeep>(log.events[6]).index, 7u);
    expectPolylineThrough(out, pts, {0, 4, 7});
}

TEST(TraceSimplify, ItlsCornerKnownAnswer)
{
    // Four points along x, three along x = 3 from y = 1: the fifth point (3,1) lifts the RMS of the first range
    // to sqrt(0.76 - sqrt(0.36 + 0.0576)) (covariance cxx 1.36, cyy 0.16, cxy 0.24) > 0.1: [0,4) closes and (3,1)
    // starts [4,7), which the end of the chain closes.
    const std::vector<rtl::Vector2f> pts{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {3, 2}, {3, 3}};
    rtl::ItlsTraceLog log;
    rtl::VectorizerITLSProjections2D<float, double, rtl::ItlsTraceLog> it;
    it.setSigma(0.1f);
    it.setObserver(&log);
    ASSERT_TRUE(it(pts));
    std::vector<std::string> kinds;
    for (const auto &e : log.events)
        std::visit([&](const auto &ev) { kinds.push_back(ev.kind); }, e);
    EXPECT_EQ(kinds, (std::vector<std::string>{"start", "add", "add", "add", "add", "add", "close", "add", "add", "add",
                                               "close", "segment", "segment"}));
    const auto adds = eventsOf<rtl::ItlsAdd>(log);
    ASSERT_EQ(adds.size(), 8u);
    const struct { size_t index, first, count; bool tested, fits; } ea[] = {
        {0, 0, 1, false, true}, {1, 0, 2, false, true}, {2, 0, 3, true, true}, {3, 0, 4, true, true},
        {4, 0, 5, true, false}, {4, 4, 1, false, true}, {5, 4, 2, false, true}, {6, 4, 3, true, true}};
    for (size_t k = 0; k < 8; ++k)
    {
        EXPECT_EQ(adds[k].index, ea[k].index) << k;
        EXPECT_EQ(adds[k].first, ea[k].first) << k;
        EXPECT_EQ(adds[k].count, ea[k].count) << k;
        EXPECT_EQ(adds[k].tested, ea[k].tested) << k;
        EXPECT_EQ(adds[k].fits, ea[k].fits) << k;
        EXPECT_NEAR(adds[k].sigma, 0.1, 1e-7);
    }
    const double corner = std::sqrt(0.76 - std::sqrt(0.36 + 0.0576));
    EXPECT_NEAR(adds[4].rms, corner, 1e-12);
    for (size_t k : {0, 1, 2, 3, 5, 6, 7})
        EXPECT_NEAR(adds[k].rms, 0.0, 1e-7) << k;
    const auto closes = eventsOf<rtl::ItlsClose>(log);
    ASSERT_EQ(closes.size(), 2u);
    EXPECT_EQ(closes[0].first, 0u);
    EXPECT_EQ(closes[0].end, 4u);
    EXPECT_FALSE(closes[0].atEnd);
    EXPECT_NEAR(closes[0].rmsWithNext, corner, 1e-12);
    EXPECT_EQ(closes[1].first, 4u);
    EXPECT_EQ(closes[1].end, 7u);
    EXPECT_TRUE(closes[1].atEnd);
    const auto segs = eventsOf<rtl::ItlsSegment>(log);
    ASSERT_EQ(segs.size(), 2u);
    EXPECT_NEAR(segs[0].x0, 0, 1e-6); EXPECT_NEAR(segs[0].y0, 0, 1e-6);
    EXPECT_NEAR(segs[0].x1, 3, 1e-6); EXPECT_NEAR(segs[0].y1, 0, 1e-6);
    EXPECT_NEAR(segs[1].x0, 3, 1e-6); EXPECT_NEAR(segs[1].y0, 1, 1e-6);
    EXPECT_NEAR(segs[1].x1, 3, 1e-6); EXPECT_NEAR(segs[1].y1, 3, 1e-6);
    // 2D segments list no z.
    std::vector<std::string> names;
    segs[0].fields([&](const char *n, auto) { names.emplace_back(n); });
    EXPECT_EQ(names, (std::vector<std::string>{"range", "first", "end", "x0", "y0", "x1", "y1"}));
}

TEST(TraceSimplify, ItlsTailKnownAnswers)
{
    typedef rtl::VectorizerITLSProjections2D<double, double, rtl::ItlsTraceLog> Itls;
    rtl::ItlsTraceLog log;
    Itls it;
    it.setSigma(0.1);
    it.setObserver(&log);
    const auto tailOf = [&](const std::vector<rtl::Vector2d> &pts) {
        log.clear();
        EXPECT_TRUE(it(pts));
        const auto tails = eventsOf<rtl::ItlsTail>(log);
        EXPECT_EQ(tails.size(), 1u);
        EXPECT_EQ(replay(log).ranges, it.indices());
        return tails.empty() ? rtl::ItlsTail{0, 0, -1} : tails[0];
    };
    // (3,5) alone at the end: it does not fit [0,5); the last range gives up (3,0): [0,3) [3,5).
    auto t = tailOf({{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 5}});
    // (Appending to the last range, or the previous range taking a point, re-test a point set the loop has
    // already rejected: those methods only happen by rounding, so no known answer shows them.)
    EXPECT_EQ(t.index, 4u);
    EXPECT_EQ(t.method, rtl::itlsTailLastSplit);
    EXPECT_EQ(t.kept, 0u);
    EXPECT_EQ(it.indices(), (std::vector<Range>{{0, 3}, {3, 5}}));
    // [0,3) [3,5) [5,7): the x axis [0,4) is closed by (10,5), the pair [4,6) by (20,6); the previous range
    // cannot take (10,5), so it gives up (3,0) and the last points pair up.
    t = tailOf({{0, 0}, {1, 0}, {2, 0}, {3, 0}, {10, 5}, {10, 6}, {20, 6}});
    EXPECT_EQ(t.method, rtl::itlsTailPrevShrunk);
    EXPECT_EQ(t.kept, 0u);
    EXPECT_EQ(it.indices(), (std::vector<Range>{{0, 3}, {3, 5}, {5, 7}}));
    // A zigzag of 7 points: no three consecutive points fit, so every range has 2 points and no re-partition
    // of the odd tail exists: the last point is left out.
    t = tailOf({{0, 0}, {1, 1}, {2, 0}, {3, 1}, {4, 0}, {5, 1}, {6, 0}});
    EXPECT_EQ(t.method, rtl::itlsTailLeftOut);
    EXPECT_EQ(t.kept, 3u);
    EXPECT_EQ(it.indices(), (std::vector<Range>{{0, 2}, {2, 4}, {4, 6}}));
    EXPECT_TRUE(eventsOf<rtl::ItlsTailRange>(log).empty());
    // Ten points on the x axis, then a zigzag of 5: [0,10) [10,12) [12,14) {14}; the dynamic programme re-cuts
    // the whole chain into 4 ranges (the x axis gives up its last point to make the pairs even).
    std::vector<rtl::Vector2d> pts;
    for (int i = 0; i < 10; ++i) pts.emplace_back(i, 0);
    for (int i = 10; i < 15; ++i) pts.emplace_back(i, i % 2 ? -3 : 3);
    t = tailOf(pts);
    EXPECT_EQ(t.method, rtl::itlsTailRepartitioned);
    EXPECT_EQ(t.kept, 0u);
    ASSERT_EQ(it.indices().size(), 4u);
    EXPECT_EQ(it.indices().back().second, 15u);
    const auto ranges = eventsOf<rtl::ItlsTailRange>(log);
    ASSERT_EQ(ranges.size(), 4u);
    for (size_t r = 0; r < ranges.size(); ++r)
    {
        EXPECT_EQ(Range(ranges[r].first, ranges[r].end), it.indices()[r]);
        EXPECT_NEAR(ranges[r].rms * ranges[r].rms, refFit<2>(pts, ranges[r].first, ranges[r].end).lineErr(), 1e-12);
    }
}

TEST(TraceSimplify, NullObserverAndFailedCallsRecordNothing)
{
    rtl::ItlsTraceLog log;
    rtl::VectorizerITLSProjections2D<float, double, rtl::ItlsTraceLog> it;
    const std::vector<rtl::Vector2f> pts{{0, 0}, {1, 0}, {2, 0}};
    EXPECT_TRUE(it(pts));                          // no observer set
    it.setObserver(&log);
    EXPECT_FALSE(it(std::vector<rtl::Vector2f>{{0, 0}}));
    EXPECT_FALSE(it(std::vector<rtl::Vector2f>{{0, 0}, {std::nanf(""), 0}, {2, 0}}));
    EXPECT_EQ(log.size(), 0u);
    EXPECT_TRUE(it(pts));
    EXPECT_EQ(log.size(), 6u);                     // start, 3 adds, close, segment
    it.setObserver(nullptr);
    EXPECT_TRUE(it(pts));
    EXPECT_EQ(log.size(), 6u);
}

// ---- every chain of the real scans ----

TEST(TraceSimplify, RealLaserChainsItls)
{
    const auto all = test_data::laserChains(10);
    ASSERT_GT(all.size(), 100u);
    rtl::ItlsTraceLog log;
    size_t tails = 0, closes = 0;
    for (double sigma : {0.03, 0.01})
    {
        rtl::VectorizerITLSProjections2D<float, double> plain;
        rtl::VectorizerITLSProjections2D<float, double, rtl::ItlsTraceLog> traced;
        plain.setSigma(static_cast<float>(sigma));
        traced.setSigma(static_cast<float>(sigma));
        traced.setObserver(&log);
        for (size_t c = 0; c < all.size(); ++c)
        {
            SCOPED_TRACE(testing::Message() << "chain " << c << " (" << all[c].size() << " points), sigma " << sigma);
            checkItls(traced, plain, log, all[c], static_cast<float>(sigma));
            tails += eventsOf<rtl::ItlsTail>(log).size();
            closes += eventsOf<rtl::ItlsClose>(log).size();
            if (HasFatalFailure()) return;
        }
    }
    EXPECT_GT(tails, 0u);                          // the tail events were exercised
    EXPECT_GT(closes, 2 * all.size());
}

TEST(TraceSimplify, RealOusterChainsItls)
{
    const auto all = test_data::ousterChains({{"rellis3d-os1-4x2048.bin", 4}, {"rellis3d-os1-16x2048.bin", 16}}, 10);
    ASSERT_GT(all.size(), 40u);
    rtl::ItlsTraceLog log;
    rtl::VectorizerITLSProjections3D<float, double> plain;
    rtl::VectorizerITLSProjections3D<float, double, rtl::ItlsTraceLog> traced;
    plain.setSigma(0.03f);
    traced.setSigma(0.03f);
    traced.setObserver(&log);
    for (size_t c = 0; c < all.size(); ++c)
    {
        SCOPED_TRACE(testing::Message() << "chain " << c << " (" << all[c].size() << " points)");
        checkItls(traced, plain, log, all[c], 0.03f);
        if (HasFatalFailure()) return;
    }
}

TEST(TraceSimplify, RealLaserChainsDouglasPeuckerAndReumannWitkam)
{
    const auto all = test_data::laserChains(10);
    rtl::DpTraceLog dlog;
    rtl::RwTraceLog rlog;
    size_t splits = 0, exits = 0;
    for (float eps : {0.09f, 0.02f})
    {
        rtl::VectorizerDouglasPeucker2f dp(eps);
        rtl::VectorizerDouglasPeuckerND<2, float, rtl::DpTraceLog> dpt(eps);
        rtl::VectorizerReumannWitkam2f rw(eps);
        rtl::VectorizerReumannWitkamND<2, float, rtl::RwTraceLog> rwt(eps);
        rtl::VectorizerDouglasPeucker2d dpd(eps);
        rtl::VectorizerDouglasPeuckerND<2, double, rtl::DpTraceLog> dptd(eps);
        rtl::VectorizerReumannWitkam2d rwd(eps);
        rtl::VectorizerReumannWitkamND<2, double, rtl::RwTraceLog> rwtd(eps);
        dpt.setObserver(&dlog); dptd.setObserver(&dlog);
        rwt.setObserver(&rlog); rwtd.setObserver(&rlog);
        for (size_t c = 0; c < all.size(); ++c)
        {
            SCOPED_TRACE(testing::Message() << "chain " << c << " (" << all[c].size() << " points), epsilon " << eps);
            checkDp(dpt, dp, dlog, all[c], eps, 2e-5);
            for (const auto &r : eventsOf<rtl::DpRange>(dlog)) splits += r.split;
            checkRw(rwt, rw, rlog, all[c], eps, 2e-5);
            exits += eventsOf<rtl::RwExit>(rlog).size();
            const auto pd = asDouble<2>(all[c]);
            checkDp(dptd, dpd, dlog, pd, eps);
            checkRw(rwtd, rwd, rlog, pd, eps, 1e-9);
            if (HasFatalFailure()) return;
        }
    }
    EXPECT_GT(splits, all.size());
    EXPECT_GT(exits, all.size());
}

TEST(TraceSimplify, RealOusterChainsDouglasPeuckerAndReumannWitkam)
{
    const auto all = test_data::ousterChains({{"rellis3d-os1-4x2048.bin", 4}, {"rellis3d-os1-16x2048.bin", 16}}, 10);
    rtl::DpTraceLog dlog;
    rtl::RwTraceLog rlog;
    rtl::VectorizerDouglasPeucker3f dp(0.09f);
    rtl::VectorizerDouglasPeuckerND<3, float, rtl::DpTraceLog> dpt(0.09f);
    rtl::VectorizerReumannWitkam3f rw(0.09f);
    rtl::VectorizerReumannWitkamND<3, float, rtl::RwTraceLog> rwt(0.09f);
    dpt.setObserver(&dlog);
    rwt.setObserver(&rlog);
    for (size_t c = 0; c < all.size(); ++c)
    {
        SCOPED_TRACE(testing::Message() << "chain " << c << " (" << all[c].size() << " points)");
        checkDp(dpt, dp, dlog, all[c], 0.09f, 2e-5);
        checkRw(rwt, rw, rlog, all[c], 0.09f, 2e-5);
        if (HasFatalFailure()) return;
    }
}

// The traced DP examines every range with the untraced decision, also on inputs that take the plain
// (non-SoA) scan (taken when some point is not finite), and in 4-D (the generic N-D scan).
TEST(TraceSimplify, DouglasPeuckerFallbackPaths)
{
    std::vector<rtl::Vector2d> withNaN;
    std::vector<rtl::VectorND<4, double>> four;
    for (int i = 0; i < 200; ++i)
    {
        const double t = i * 0.05, y = std::sin(t) * (1 + 0.1 * std::cos(7 * t));
        withNaN.emplace_back(t, i % 37 == 5 ? std::nan("") : y);
        four.push_back(rtl::VectorND<4, double>(t, y, std::cos(t), 0.5 * t * t));
    }
    rtl::DpTraceLog log;
    {
        rtl::VectorizerDouglasPeucker2d dp(0.05);
        rtl::VectorizerDouglasPeuckerND<2, double, rtl::DpTraceLog> dpt(0.05);
        dpt.setObserver(&log);
        log.clear();
        std::vector<rtl::LineSegment2d> a;
        dp(withNaN, a);
        checkDp(dpt, dp, log, withNaN, 0.05);
        EXPECT_GT(a.size(), 3u);
    }
    {
        rtl::VectorizerDouglasPeuckerND<4, double> dp(0.05);
        rtl::VectorizerDouglasPeuckerND<4, double, rtl::DpTraceLog> dpt(0.05);
        dpt.setObserver(&log);
        checkDp(dpt, dp, log, four, 0.05);
        rtl::RwTraceLog rlog;
        rtl::VectorizerReumannWitkamND<4, double> rw(0.05f);
        rtl::VectorizerReumannWitkamND<4, double, rtl::RwTraceLog> rwt(0.05f);
        rwt.setObserver(&rlog);
        checkRw(rwt, rw, rlog, four, 0.05f, 1e-6);
        EXPECT_GT(eventsOf<rtl::RwExit>(rlog).size(), 2u);
    }
}
