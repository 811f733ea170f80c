// FTLS/AFTLS traces (FtlsTrace.h): the replayed trace ends in exactly the untraced result on every
// chain of tests/data (strict and split mode, three settings, split mode's cover with shared points included), and
// the events' numbers agree with independent recomputation (trial errors, corner distances, optimizer totals, the
// AFTLS choice).
#include <cmath>
#include <limits>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "rtl/Vectorization.h"
#include "rtl/io/CarmenLog.h"
#include "scan_chains.h"
#include "vect_reference.h"

using namespace vect_test;

namespace
{
    struct Replay
    {
        std::vector<Range> ranges[2];
        std::vector<Range> result;
        std::vector<size_t> offsets;
        std::vector<rtl::LineSegment2f> segments;
        bool infeasible = false, chosen = false;
        int kept = 0;
    };

    //! Replays a trace by the rules of FtlsTrace.h; also checks each event's numbers against `pts`.
    Replay replay(const rtl::FtlsTraceLog &log, const std::vector<rtl::Vector2f> &pts)
    {
        Replay r;
        size_t pending = 0;
        int pending_branch = 0;
        Range span{0, 0};
        std::vector<Range> inserted;
        bool extracted = false;
        const auto apply = [&] {
            auto &v = r.ranges[pending_branch];
            std::vector<Range> out;
            bool placed = false;
            for (const auto &x : v)
            {
                if (x.first >= span.first && x.second <= span.second)
                {
                    if (!placed) { out.insert(out.end(), inserted.begin(), inserted.end()); placed = true; }
                    continue;
                }
                if (!placed && x.first >= span.second) { out.insert(out.end(), inserted.begin(), inserted.end()); placed = true; }
                out.push_back(x);
            }
            if (!placed) out.insert(out.end(), inserted.begin(), inserted.end());
            v = out;
        };
        double last_total = std::numeric_limits<double>::infinity();
        for (const auto &ev : log.events)
        {
            std::visit([&](const auto &e) {
                typedef std::decay_t<decltype(e)> E;
                if constexpr (std::is_same_v<E, rtl::FtlsTrial>)
                {
                    const double ref = e.end - e.first <= 2 ? 0.0 : refFit<2>(pts, e.first, e.end).lineErr();
                    EXPECT_NEAR(e.meanSquaredError, ref, 1e-9 + 1e-6 * ref);
                    if (std::abs(ref - e.sigma * e.sigma) > 1e-7)
                    {
                        EXPECT_EQ(e.pass, e.end - e.first <= 2 || ref < e.sigma * e.sigma) << e.first << " " << e.end;
                    }
                }
                else if constexpr (std::is_same_v<E, rtl::FtlsRange>)
                {
                    auto &v = r.ranges[0];
                    while (!v.empty() && v.back().second > e.first)
                        v.pop_back();
                    v.emplace_back(e.first, e.end);
                }
                else if constexpr (std::is_same_v<E, rtl::FtlsCorner>)
                {
                    if (!extracted) { r.ranges[1] = r.ranges[0]; extracted = true; }
                    const auto &v = r.ranges[e.branch];
                    EXPECT_LT(e.index + 1, v.size());
                    if (e.index + 1 < v.size())
                    {
                        EXPECT_EQ(v[e.index].second, e.boundary);
                    }
                    EXPECT_EQ(e.ok, e.crossingDistance <= e.delta);
                }
                else if constexpr (std::is_same_v<E, rtl::FtlsRepair>)
                {
                    if (!extracted) { r.ranges[1] = r.ranges[0]; extracted = true; }
                    pending = e.inserted;
                    pending_branch = e.branch;
                    span = Range(e.first, e.end);
                    inserted.clear();
                    if (pending == 0) apply();
                }
                else if constexpr (std::is_same_v<E, rtl::FtlsRepairRange>)
                {
                    inserted.emplace_back(e.first, e.end);
                    if (--pending == 0) apply();
                }
                else if constexpr (std::is_same_v<E, rtl::FtlsMove>)
                {
                    if (!extracted) { r.ranges[1] = r.ranges[0]; extracted = true; }
                    auto &v = r.ranges[1];
                    EXPECT_GT(e.breakpoint, 0u);
                    EXPECT_LT(e.breakpoint, v.size());
                    EXPECT_EQ(v[e.breakpoint].first, e.from);
                    v[e.breakpoint - 1].second = e.to;
                    v[e.breakpoint].first = e.to;
                    EXPECT_LT(e.totalError, last_total * (1 + 1e-9) + 1e-15);
                    last_total = e.totalError;
                }
                else if constexpr (std::is_same_v<E, rtl::FtlsChoice>)
                {
                    if (!extracted) { r.ranges[1] = r.ranges[0]; extracted = true; }
                    r.chosen = true;
                    r.kept = e.kept;
                    EXPECT_EQ(e.kept == 0, e.ftlsError < e.aftlsError);
                }
                else if constexpr (std::is_same_v<E, rtl::FtlsInfeasible>)
                {
                    r.infeasible = true;
                    EXPECT_GT(e.crossingDistance, e.delta);
                }
                else if constexpr (std::is_same_v<E, rtl::FtlsSegment>)
                {
                    EXPECT_EQ(e.index, r.segments.size());
                    r.segments.emplace_back(rtl::Vector2f(static_cast<float>(e.x0), static_cast<float>(e.y0)),
                                            rtl::Vector2f(static_cast<float>(e.x1), static_cast<float>(e.y1)));
                    r.result.emplace_back(e.first, e.end);
                    if (r.offsets.size() <= e.polyline) r.offsets.push_back(e.index);
                }
            }, ev);
        }
        if (!r.segments.empty())
            r.offsets.push_back(r.segments.size());
        return r;
    }

    //! The replayed partition: the chosen branch, or none after an unrepaired `infeasible`.
    std::vector<Range> replayedPartition(const Replay &r, bool ok)
    {
        if (!ok)
            return {};
        return r.chosen && !r.infeasible ? r.ranges[r.kept] : r.ranges[0];
    }

    template<class Traced, class Plain>
    void checkAll(const char *name)
    {
        const auto all = test_data::laserChains(3);
        size_t repairs = 0, moves = 0, infeasible = 0, trials = 0, covers = 0;
        for (const auto &[sigma, delta] : {std::pair{0.03, 0.3}, std::pair{0.03, 3.0}, std::pair{0.01, 0.3}})
            for (bool split : {false, true})
            {
                Traced t;
                Plain p;
                rtl::FtlsTraceLog log;
                t.setObserver(&log);
                t.setSigma(static_cast<float>(sigma)); t.setDelta(static_cast<float>(delta)); t.setSplitAtInfeasibleCorners(split);
                p.setSigma(static_cast<float>(sigma)); p.setDelta(static_cast<float>(delta)); p.setSplitAtInfeasibleCorners(split);
                for (size_t c = 0; c < all.size(); ++c)
                {
                    const auto &pts = all[c];
                    SCOPED_TRACE(testing::Message() << name << " chain " << c << " (" << pts.size() << " points) sigma " << sigma
                                                    << " delta " << delta << " split " << split);
                    log.clear();
                    const bool ok = p(pts);
                    ASSERT_EQ(t(pts), ok);
                    ASSERT_EQ(t.indices(), p.indices());
                    const Replay r = replay(log, pts);
                    ASSERT_EQ(replayedPartition(r, ok), p.indices());
                    ASSERT_EQ(r.result, p.indices());
                    if (ok)
                    {
                        ASSERT_EQ(r.offsets, p.polylineOffsets());
                        const auto segs = p.lineSegments();
                        ASSERT_EQ(r.segments.size(), segs.size());
                        for (size_t i = 0; i < segs.size(); ++i)
                        {
                            EXPECT_EQ(r.segments[i].beg(), segs[i].beg());
                            EXPECT_EQ(r.segments[i].end(), segs[i].end());
                        }
                    }
                    ASSERT_FALSE(log.events.empty());
                    ASSERT_TRUE(std::holds_alternative<rtl::FtlsStart>(log.events.front()));
                    for (const auto &ev : log.events)
                    {
                        repairs += std::holds_alternative<rtl::FtlsRepair>(ev);
                        moves += std::holds_alternative<rtl::FtlsMove>(ev);
                        infeasible += std::holds_alternative<rtl::FtlsInfeasible>(ev);
                        trials += std::holds_alternative<rtl::FtlsTrial>(ev);
                        // The cover search (ranges may share a point) runs only in split mode, after `infeasible`.
                        if (const auto *rep = std::get_if<rtl::FtlsRepair>(&ev); rep && rep->method == rtl::FtlsCoverSearch)
                        {
                            ++covers;
                            EXPECT_TRUE(split);
                            EXPECT_TRUE(r.infeasible);
                            EXPECT_EQ(rep->first, 0u);
                            EXPECT_EQ(rep->end, pts.size());
                        }
                    }
                }
            }
        EXPECT_GT(repairs, 10u);
        EXPECT_GT(infeasible, 10u);
        EXPECT_GT(trials, 1000u);
        EXPECT_GT(covers, 0u);
        if (std::string(name) == "AFTLS")
        {
            EXPECT_GT(moves, 100u);
        }
    }
}

TEST(FtlsTrace, ReplayEqualsUntracedOnEveryRealChainFtls)
{
    checkAll<rtl::VectorizerFTLSPolyline2D<float, double, rtl::FtlsTraceLog>, rtl::VectorizerFTLSPolyline2D<float, double>>("FTLS");
}

TEST(FtlsTrace, ReplayEqualsUntracedOnEveryRealChainAftls)
{
    checkAll<rtl::VectorizerAFTLSPolyline2D<float, double, rtl::FtlsTraceLog>, rtl::VectorizerAFTLSPolyline2D<float, double>>("AFTLS");
}

// A known answer: 8 collinear points then a right angle; the extractor's first trial is the whole chain (fails), then
// the gallop from length 4, and the corner check at the accepted boundary passes.
TEST(FtlsTrace, KnownAnswerOnAnL)
{
    std::vector<rtl::Vector2f> pts;
    for (int i = 0; i < 8; ++i) pts.emplace_back(0.1f * static_cast<float>(i), 0.f);
    for (int i = 1; i <= 8; ++i) pts.emplace_back(0.7f, 0.1f * static_cast<float>(i));
    rtl::VectorizerFTLSPolyline2D<float, double, rtl::FtlsTraceLog> f;
    rtl::FtlsTraceLog log;
    f.setObserver(&log);
    f.setSigma(0.03f);
    f.setDelta(0.3f);
    ASSERT_TRUE(f(pts));
    ASSERT_GE(log.events.size(), 4u);
    const auto &start = std::get<rtl::FtlsStart>(log.events[0]);
    EXPECT_EQ(start.count, 16u);
    EXPECT_FALSE(start.aftls);
    const auto &t0 = std::get<rtl::FtlsTrial>(log.events[1]);
    EXPECT_EQ(t0.first, 0u);
    EXPECT_EQ(t0.end, 16u);
    EXPECT_EQ(t0.phase, rtl::FtlsWholeRemainder);
    EXPECT_FALSE(t0.pass);
    const auto &t1 = std::get<rtl::FtlsTrial>(log.events[2]);
    EXPECT_EQ(t1.end, 4u);
    EXPECT_EQ(t1.phase, rtl::FtlsGallop);
    EXPECT_TRUE(t1.pass);
    size_t corners = 0;
    for (const auto &ev : log.events)
        if (const auto *c = std::get_if<rtl::FtlsCorner>(&ev))
        {
            ++corners;
            EXPECT_TRUE(c->ok);
            EXPECT_LE(c->crossingDistance, 0.3);
        }
    EXPECT_EQ(corners, f.indices().size() - 1);
    // Without an observer set, nothing is recorded.
    rtl::VectorizerFTLSPolyline2D<float, double, rtl::FtlsTraceLog> g;
    g.setSigma(0.03f);
    g.setDelta(0.3f);
    ASSERT_TRUE(g(pts));
    EXPECT_EQ(g.indices(), f.indices());
}
