// Traces of CAR_Segmenter and IA_Segmenter (seg/SegTrace.h): known-answer traces checked by hand, and on every real
// scan in tests/data (30 Intel and 30 CSAIL laser scans, 4 Ouster rings), steps 1..4: replaying the trace gives
// exactly the clusters the untraced segmenter returns (CAR) and its alive and closed clusters while streaming (IA),
// every comparison's `linked` is distance <= threshold, and the compared pairs are those of the window.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "rtl/io/CarmenLog.h"
#include "rtl/io/OrganizedLidar.h"
#include "rtl/seg/CAR_Segmenter.h"
#include "rtl/seg/IA_Segmenter.h"
#include "rtl/seg/SegTrace.h"

#include "interleaved_scan.h"

namespace
{
    using V2d = rtl::VectorND<2, double>;
    using V2f = rtl::VectorND<2, float>;
    constexpr size_t none = static_cast<size_t>(-1);
    const std::string data_dir = RTL_TEST_DATA_DIR;

    //! One event as text, through its kind and fields(): "compare i=2 j=1 distance=0.9 threshold=1 linked=1".
    struct Printer
    {
        std::string s;
        void operator()(const char *name, bool v) { s += std::string(" ") + name + "=" + (v ? "1" : "0"); }
        void operator()(const char *name, size_t v) { s += std::string(" ") + name + "=" + std::to_string(v); }
        void operator()(const char *name, double v)
        {
            char b[32];
            std::snprintf(b, sizeof b, "%.4g", v);
            s += std::string(" ") + name + "=" + b;
        }
    };

    template<class Log>
    std::vector<std::string> text(const Log &log)
    {
        std::vector<std::string> out;
        for (const auto &ev : log.events)
            std::visit([&](const auto &e) {
                Printer p{e.kind};
                e.fields(p);
                out.push_back(p.s);
            }, ev);
        return out;
    }

    template<class V>
    std::vector<std::vector<V>> grabAll(rtl::CAR_Segmenter<V> &car)
    {
        std::vector<std::vector<V>> out;
        while (car.clustersAvailable() > 0) out.push_back(car.grabCluster());
        return out;
    }

    //! Replays a CAR trace (rules in SegTrace.h) and returns the clusters it describes, as points; checks every
    //! comparison on the way.
    template<class V>
    std::vector<std::vector<V>> replayCar(const rtl::CarTraceLog &log, const std::vector<V> &pts, size_t step, const std::string &what)
    {
        const size_t n = pts.size(), window = step - 1;
        std::vector<size_t> label(n, none);
        std::vector<std::vector<V>> clusters;
        size_t bad_compare = 0, bad_pair = 0, bad_link = 0, scans = 0;
        for (const auto &ev : log.events)
        {
            if (auto *e = std::get_if<rtl::car_trace::Scan>(&ev))
            {
                ++scans;
                EXPECT_EQ(e->size, n);
                EXPECT_EQ(e->step, step);
                EXPECT_EQ(e->window, window);
            }
            else if (auto *e = std::get_if<rtl::car_trace::Compare>(&ev))
            {
                bad_compare += e->linked != (e->distance <= e->threshold);
                bad_pair += !(e->j < e->i && e->i - e->j <= window);
            }
            else if (auto *e = std::get_if<rtl::car_trace::Seam>(&ev))
            {
                bad_compare += e->linked != (e->distance <= e->threshold);
                bad_pair += !(e->j > e->i && e->i + n - e->j <= window);
            }
            else if (auto *e = std::get_if<rtl::car_trace::Start>(&ev)) label[e->i] = e->i;
            else if (auto *e = std::get_if<rtl::car_trace::Link>(&ev))
            {
                bad_link += label[e->j] != e->cluster || label[e->i] != none;
                label[e->i] = e->cluster;
            }
            else if (auto *e = std::get_if<rtl::car_trace::Merge>(&ev))
            {
                bad_link += !(e->into < e->from) || label[e->i] == label[e->j];
                bad_link += (label[e->i] != e->from && label[e->i] != e->into) || (label[e->j] != e->from && label[e->j] != e->into);
                for (size_t &l : label)
                    if (l == e->from) l = e->into;
            }
            else if (auto *e = std::get_if<rtl::car_trace::Cluster>(&ev))
            {
                EXPECT_EQ(e->index, clusters.size()) << what;
                std::vector<size_t> idx;
                for (size_t i = 0; i < n; ++i)
                    if (label[i] == e->label) idx.push_back(i);
                EXPECT_EQ(idx.size(), e->size) << what;
                EXPECT_TRUE(!idx.empty() && idx.front() == e->label) << what << ": label is not the smallest index";
                const auto first = std::find(idx.begin(), idx.end(), e->first);
                EXPECT_TRUE(first != idx.end()) << what << ": first point not in the cluster";
                std::rotate(idx.begin(), first, idx.end());
                std::vector<V> c;
                for (size_t i : idx) c.push_back(pts[i]);
                clusters.push_back(c);
            }
            else if (auto *e = std::get_if<rtl::car_trace::Gap>(&ev)) bad_link += label[e->i] != none;
        }
        EXPECT_EQ(scans, 1u) << what;
        EXPECT_EQ(bad_compare, 0u) << what << ": linked differs from distance <= threshold";
        EXPECT_EQ(bad_pair, 0u) << what << ": compared pair outside the window";
        EXPECT_EQ(bad_link, 0u) << what << ": link or merge inconsistent with the replayed labels";
        return clusters;
    }

    size_t car_merges = 0, car_seam_merges = 0, ia_merges = 0, events = 0;   // coverage of the real-scan test

    template<class V>
    void checkCarTrace(const std::vector<V> &pts, const V &origin, size_t step, typename V::ElementType lb,
                       typename V::ElementType ub, const std::string &what)
    {
        rtl::CAR_Segmenter<V> plain(step, lb, ub);
        plain.loadData(pts, origin);
        const auto expected = grabAll(plain);
        rtl::CarTraceLog log;
        rtl::CAR_Segmenter<V, rtl::CarTraceLog> traced(step, lb, ub);
        traced.setObserver(&log);
        traced.loadData(pts, origin);
        std::vector<std::vector<V>> got;
        while (traced.clustersAvailable() > 0) got.push_back(traced.grabCluster());
        EXPECT_EQ(got, expected) << what << ": the traced segmenter returns other clusters";
        EXPECT_EQ(replayCar(log, pts, step, what), expected) << what << ": the replayed trace ends elsewhere";
        events += log.size();
        bool after_seam = false;
        for (const auto &ev : log.events)
        {
            after_seam |= std::holds_alternative<rtl::car_trace::Seam>(ev);
            if (std::holds_alternative<rtl::car_trace::Merge>(ev)) ++(after_seam ? car_seam_merges : car_merges);
        }
    }

    //! Replays an IA trace as it grows (rules in SegTrace.h).
    struct IaReplay
    {
        std::map<size_t, size_t> window;                 // stream index -> cluster id (none: gap)
        std::map<size_t, std::vector<size_t>> alive;     // id -> stream indices
        std::vector<std::vector<size_t>> closed;
        size_t next = 0;                                 // first event not replayed yet
        size_t step = 1;
        size_t bad_compare = 0, bad_pair = 0, bad_move = 0;
        size_t slid = none, slid_cluster = none;         // the last point that left the window, and its cluster

        void advance(const rtl::IaTraceLog &log)
        {
            for (; next < log.events.size(); ++next)
            {
                const auto &ev = log.events[next];
                if (auto *e = std::get_if<rtl::ia_trace::Add>(&ev))
                {
                    bad_move += window.count(e->i);
                    window[e->i] = none;
                }
                else if (auto *e = std::get_if<rtl::ia_trace::Compare>(&ev))
                {
                    bad_compare += e->linked != (e->distance <= e->threshold);
                    bad_pair += !(e->j < e->i && e->i - e->j <= step && window.count(e->j) && window[e->j] != none);
                }
                else if (auto *e = std::get_if<rtl::ia_trace::Open>(&ev)) window[e->i] = e->cluster;
                else if (auto *e = std::get_if<rtl::ia_trace::Link>(&ev))
                {
                    bad_move += window[e->j] != e->cluster;
                    window[e->i] = e->cluster;
                }
                else if (auto *e = std::get_if<rtl::ia_trace::Merge>(&ev))
                {
                    bad_move += !(e->into < e->from);
                    for (auto &w : window)
                        if (w.second == e->from) w.second = e->into;
                    auto it = alive.find(e->from);
                    if (it != alive.end())
                    {
                        auto &into = alive[e->into];
                        into.insert(into.end(), it->second.begin(), it->second.end());
                        std::sort(into.begin(), into.end());
                        alive.erase(e->from);
                    }
                }
                else if (auto *e = std::get_if<rtl::ia_trace::Slide>(&ev))
                {
                    auto it = window.find(e->i);
                    bad_move += it == window.end() || it->first != window.begin()->first || (it->second == none) != e->gap;
                    slid = e->i;
                    slid_cluster = it == window.end() ? none : it->second;
                    if (it != window.end()) window.erase(it);
                }
                else if (auto *e = std::get_if<rtl::ia_trace::Alive>(&ev))
                {
                    bad_move += e->i != slid || e->cluster != slid_cluster;
                    alive[e->cluster].push_back(e->i);
                }
                else if (auto *e = std::get_if<rtl::ia_trace::Close>(&ev))
                {
                    for (const auto &w : window) bad_move += w.second == e->cluster;
                    bad_move += alive[e->cluster].size() != e->size;
                    closed.push_back(alive[e->cluster]);
                    alive.erase(e->cluster);
                }
            }
        }
    };

    template<class V>
    std::vector<V> points(const std::vector<V> &pts, const std::vector<size_t> &idx)
    {
        std::vector<V> out;
        for (size_t i : idx) out.push_back(pts[i]);
        return out;
    }

    template<class V>
    void checkIaTrace(const std::vector<V> &pts, const V &origin, size_t step, typename V::ElementType lb,
                      typename V::ElementType ub, typename V::ElementType scaling, const std::string &what)
    {
        rtl::IA_Segmenter<V> plain(step, lb, ub, scaling);
        rtl::IaTraceLog log;
        rtl::IA_Segmenter<V, rtl::IaTraceLog> traced(step, lb, ub, scaling);
        traced.setObserver(&log);
        IaReplay replay;
        replay.step = step;
        std::vector<std::vector<V>> grabbed_plain, grabbed;
        size_t alive_mismatch = 0;
        for (size_t i = 0; i < pts.size(); ++i)
        {
            plain.addPoint(pts[i], origin);
            traced.addPoint(pts[i], origin);
            while (plain.closedClustersAvailable() > 0) grabbed_plain.push_back(plain.grabCluster());
            while (traced.closedClustersAvailable() > 0) grabbed.push_back(traced.grabCluster());
            if (i % 29 == 0 || i + 1 == pts.size())
            {
                replay.advance(log);
                std::map<size_t, std::vector<V>> alive;
                for (const auto &kv : replay.alive) alive[kv.first] = points(pts, kv.second);
                alive_mismatch += alive != plain.aliveClusters() || alive != traced.aliveClusters();
            }
        }
        plain.flush();
        traced.flush();
        while (plain.closedClustersAvailable() > 0) grabbed_plain.push_back(plain.grabCluster());
        while (traced.closedClustersAvailable() > 0) grabbed.push_back(traced.grabCluster());
        replay.advance(log);
        events += log.size();
        for (const auto &ev : log.events) ia_merges += std::holds_alternative<rtl::ia_trace::Merge>(ev);
        EXPECT_EQ(alive_mismatch, 0u) << what << ": replayed alive clusters differ from aliveClusters()";
        EXPECT_TRUE(replay.alive.empty() && replay.window.empty()) << what << ": points left after flush";
        EXPECT_EQ(grabbed, grabbed_plain) << what << ": the traced segmenter returns other clusters";
        std::vector<std::vector<V>> closed;
        for (const auto &c : replay.closed) closed.push_back(points(pts, c));
        EXPECT_EQ(closed, grabbed_plain) << what << ": the replayed closed clusters differ";
        EXPECT_EQ(replay.bad_compare, 0u) << what << ": linked differs from distance <= threshold";
        EXPECT_EQ(replay.bad_pair, 0u) << what << ": compared pair outside the window";
        EXPECT_EQ(replay.bad_move, 0u) << what << ": window or alive move inconsistent with the replay";
    }

    template<class E>
    std::vector<std::vector<rtl::VectorND<2, E>>> carmenScans(const std::string &file)
    {
        std::vector<std::vector<rtl::VectorND<2, E>>> out;
        for (const auto &s : rtl::readCarmenLogFile<E>(data_dir + "/" + file)) out.push_back(s.points);
        return out;
    }

    std::vector<std::vector<rtl::VectorND<3, float>>> ousterRings()
    {
        const auto cloud = rtl::readOrganizedLidarFile<float>(data_dir + "/rellis3d-os1-4x2048.bin", 4);
        std::vector<std::vector<rtl::VectorND<3, float>>> out;
        for (size_t b = 0; b < cloud.beams; ++b) out.push_back(cloud.ring(b));
        return out;
    }
}

TEST(CarTrace, KnownAnswerWithMerge)
{
    // step 3 (window: two previous points), fixed threshold 1 m. 2 joins 1 (0.9 m), then 0 (0.9 m): clusters of 0
    // and 1 merge into 0. 3 is a gap; 5 joins 4; nothing is close across the seam.
    const std::vector<V2d> pts = {V2d(0, 0), V2d(0, 1.8), V2d(0, 0.9), V2d::nan(), V2d(10, 0), V2d(10, 0.6)};
    rtl::CarTraceLog log;
    rtl::CAR_Segmenter<V2d, rtl::CarTraceLog> car(3, 1.0, 1.0);
    car.setObserver(&log);
    car.loadData(pts);
    const std::vector<std::string> expected = {
        "scan size=6 step=3 window=2 scaling=3.142 lowerBound=1 upperBound=1",
        "threshold i=0 range=0 raw=0 threshold=1",
        "start i=0",
        "threshold i=1 range=1.8 raw=5.655 threshold=1",
        "compare i=1 j=0 distance=1.8 threshold=1 linked=0",
        "start i=1",
        "threshold i=2 range=0.9 raw=2.827 threshold=1",
        "compare i=2 j=1 distance=0.9 threshold=1 linked=1",
        "link i=2 j=1 cluster=1",
        "compare i=2 j=0 distance=0.9 threshold=1 linked=1",
        "merge i=2 j=0 from=1 into=0",
        "gap i=3",
        "threshold i=4 range=10 raw=31.42 threshold=1",
        "compare i=4 j=2 distance=10.04 threshold=1 linked=0",
        "start i=4",
        "threshold i=5 range=10.02 raw=31.47 threshold=1",
        "compare i=5 j=4 distance=0.6 threshold=1 linked=1",
        "link i=5 j=4 cluster=4",
        "seam i=0 j=5 distance=10.02 threshold=1 linked=0",
        "seam i=0 j=4 distance=10 threshold=1 linked=0",
        "seam i=1 j=5 distance=10.07 threshold=1 linked=0",
        "cluster index=0 label=0 first=0 size=3",
        "cluster index=1 label=4 first=4 size=2",
    };
    EXPECT_EQ(text(log), expected);
    ASSERT_EQ(car.clustersAvailable(), 2u);
    EXPECT_EQ(car.grabCluster(), (std::vector<V2d>{pts[0], pts[1], pts[2]}));
    EXPECT_EQ(car.grabCluster(), (std::vector<V2d>{pts[4], pts[5]}));
}

TEST(CarTrace, KnownAnswerSeamAndStepOne)
{
    // step 2: 5 -> 0 across the seam (0.5 m) merges cluster 5 into 0; the wrapped cluster starts at 5
    const std::vector<V2d> pts = {V2d(0, 0), V2d(10, 0), V2d(20, 0), V2d(30, 0), V2d(40, 0), V2d(0, 0.5)};
    rtl::CarTraceLog log;
    rtl::CAR_Segmenter<V2d, rtl::CarTraceLog> car(2, 1.0, 1.0);
    car.setObserver(&log);
    car.loadData(pts);
    std::vector<std::string> tail;
    for (const auto &t : text(log))
        if (t.rfind("seam", 0) == 0 || t.rfind("merge", 0) == 0 || t.rfind("cluster", 0) == 0 || t.rfind("start", 0) == 0) tail.push_back(t);
    const std::vector<std::string> expected = {
        "start i=0", "start i=1", "start i=2", "start i=3", "start i=4", "start i=5",
        "seam i=0 j=5 distance=0.5 threshold=1 linked=1",
        "merge i=0 j=5 from=5 into=0",
        "cluster index=0 label=0 first=5 size=2",
        "cluster index=1 label=1 first=1 size=1",
        "cluster index=2 label=2 first=2 size=1",
        "cluster index=3 label=3 first=3 size=1",
        "cluster index=4 label=4 first=4 size=1",
    };
    EXPECT_EQ(tail, expected);
    EXPECT_EQ(car.grabCluster(), (std::vector<V2d>{pts[5], pts[0]}));

    // step 1 compares nothing: a threshold and a start per point, no comparison, no seam
    log.clear();
    car.setStepSize(1);
    car.loadData(pts);
    size_t compares = 0, starts = 0;
    for (const auto &ev : log.events)
    {
        compares += std::holds_alternative<rtl::car_trace::Compare>(ev) || std::holds_alternative<rtl::car_trace::Seam>(ev);
        starts += std::holds_alternative<rtl::car_trace::Start>(ev);
    }
    EXPECT_EQ(compares, 0u);
    EXPECT_EQ(starts, 6u);
    EXPECT_EQ(car.clustersAvailable(), 6u);

    // no observer: nothing recorded, same clusters
    log.clear();
    car.setObserver(nullptr);
    car.setStepSize(2);
    car.loadData(pts);
    EXPECT_EQ(log.size(), 0u);
    EXPECT_EQ(car.grabCluster(), (std::vector<V2d>{pts[5], pts[0]}));
}

TEST(IaTrace, KnownAnswerWindowOfTwo)
{
    // step 2, fixed threshold 1 m: 2 is 0.8 m from 0 and from 1, so cluster 1 merges into 0; 3 is a gap
    const std::vector<V2d> pts = {V2d(0, 0), V2d(0, 1.6), V2d(0, 0.8), V2d::nan()};
    rtl::IaTraceLog log;
    rtl::IA_Segmenter<V2d, rtl::IaTraceLog> ia(2, 1.0, 1.0, 0.0);
    ia.setObserver(&log);
    for (const auto &p : pts) ia.addPoint(p);
    ia.flush();
    const std::vector<std::string> expected = {
        "add i=0 gap=0", "threshold i=0 range=0 raw=0 threshold=1", "open i=0 cluster=0",
        "add i=1 gap=0", "threshold i=1 range=1.6 raw=0 threshold=1", "compare i=1 j=0 distance=1.6 threshold=1 linked=0",
        "open i=1 cluster=1",
        "add i=2 gap=0", "threshold i=2 range=0.8 raw=0 threshold=1", "compare i=2 j=0 distance=0.8 threshold=1 linked=1",
        "link i=2 j=0 cluster=0", "compare i=2 j=1 distance=0.8 threshold=1 linked=1", "merge i=2 j=1 from=1 into=0",
        "slide i=0 gap=0", "alive i=0 cluster=0",
        "add i=3 gap=1", "slide i=1 gap=0", "alive i=1 cluster=0",
        "slide i=2 gap=0", "alive i=2 cluster=0", "close cluster=0 size=3", "slide i=3 gap=1",
    };
    EXPECT_EQ(text(log), expected);
    EXPECT_EQ(ia.grabCluster(), (std::vector<V2d>{pts[0], pts[1], pts[2]}));
}

TEST(IaTrace, KnownAnswerStepOne)
{
    const std::vector<V2d> pts = {V2d(0, 0), V2d(0, 0.5), V2d(0, 5)};
    rtl::IaTraceLog log;
    rtl::IA_Segmenter<V2d, rtl::IaTraceLog> ia(1, 1.0, 1.0, 0.0);
    ia.setObserver(&log);
    for (const auto &p : pts) ia.addPoint(p);
    ia.flush();
    const std::vector<std::string> expected = {
        "add i=0 gap=0", "threshold i=0 range=0 raw=0 threshold=1", "open i=0 cluster=0",
        "add i=1 gap=0", "threshold i=1 range=0.5 raw=0 threshold=1", "compare i=1 j=0 distance=0.5 threshold=1 linked=1",
        "link i=1 j=0 cluster=0", "slide i=0 gap=0", "alive i=0 cluster=0",
        "add i=2 gap=0", "threshold i=2 range=5 raw=0 threshold=1", "compare i=2 j=1 distance=4.5 threshold=1 linked=0",
        "open i=2 cluster=1", "slide i=1 gap=0", "alive i=1 cluster=0", "close cluster=0 size=2",
        "slide i=2 gap=0", "alive i=2 cluster=1", "close cluster=1 size=1",
    };
    EXPECT_EQ(text(log), expected);
    EXPECT_EQ(ia.grabCluster(), (std::vector<V2d>{pts[0], pts[1]}));
    EXPECT_EQ(ia.grabCluster(), (std::vector<V2d>{pts[2]}));
}

TEST(SegTrace, DistancesCompareLikeTheirSquares)
{
    // adjacent doubles whose square roots round to the same value: the reported distance stays above the threshold
    const double tsq = 2.0, dsq = std::nextafter(2.0, 3.0);
    double d, t;
    rtl::detail::traceDistances(dsq, tsq, false, d, t);
    EXPECT_GT(d, t);
    rtl::detail::traceDistances(tsq, tsq, true, d, t);
    EXPECT_LE(d, t);
}

TEST(SegTrace, ReplayEqualsResultOnRealScans)
{
    size_t scans = 0;
    for (const char *file : {"intel.log", "csail.log"})
    {
        const auto sf = carmenScans<float>(file);
        const auto sd = carmenScans<double>(file);
        ASSERT_EQ(sf.size(), 30u);
        for (size_t step = 1; step <= 4; ++step)
            for (size_t k = 0; k < sf.size(); ++k, ++scans)
            {
                const std::string what = std::string(file) + " scan " + std::to_string(k) + " step " + std::to_string(step);
                const auto &pts = sf[k];
                checkCarTrace(pts, V2f::zeros(), step, 0.05f, 0.5f, what + " CAR");
                checkIaTrace(pts, V2f::zeros(), step, 0.05f, 0.5f, rtl::detail::circularScaling<float>(step + 1, pts.size()), what + " IA");
                if (k % 5 == 0) checkCarTrace(sd[k], V2d::zeros(), step, 0.03, 0.3, what + " CAR double");
                if (::testing::Test::HasFailure()) return;
            }
    }
    const auto rings = ousterRings();
    for (size_t step = 1; step <= 4; ++step)
        for (size_t b = 0; b < rings.size(); ++b, ++scans)
        {
            const std::string what = "ouster ring " + std::to_string(b) + " step " + std::to_string(step);
            checkCarTrace(rings[b], rtl::VectorND<3, float>::zeros(), step, 0.1f, 1.0f, what + " CAR");
            checkIaTrace(rings[b], rtl::VectorND<3, float>::zeros(), step, 0.1f, 1.0f,
                         rtl::detail::circularScaling<float>(step + 1, rings[b].size()), what + " IA");
            if (::testing::Test::HasFailure()) return;
        }
    EXPECT_EQ(scans, 2 * 30 * 4 + 4 * 4u);
    std::printf("%zu scans, %zu events: %zu CAR merges, %zu at the seam, %zu IA merges\n", scans, events, car_merges,
                car_seam_merges, ia_merges);
    EXPECT_GT(car_merges, 0u);
    EXPECT_GT(car_seam_merges, 0u);
    EXPECT_GT(ia_merges, 0u);
}

// A traced IA type always takes the slow path, with or without an observer (its fast paths are not compiled): without
// one, and with one set and removed mid-stream, it closes the same clusters in the same order and keeps the same alive
// lists as the untraced segmenter, over window changes, gaps, interleaved chains and flushes.
TEST(IaTrace, TracedTypeWithoutObserverEqualsUntraced)
{
    const auto pts = segcheck::interleavedScan<V2f>(4000, 7, {0.02, 60, 3, 0.01, 0.02});
    for (unsigned step = 1; step <= 10; ++step)
    {
        rtl::IA_Segmenter<V2f> plain(step, 0.05f, 0.5f, 0.02f);
        rtl::IA_Segmenter<V2f, rtl::IaTraceLog> traced(step, 0.05f, 0.5f, 0.02f);
        rtl::IaTraceLog log;
        std::vector<std::vector<V2f>> a, b;
        for (size_t i = 0; i < pts.size(); ++i)
        {
            if (i == 1000) traced.setObserver(&log);
            if (i == 1500) traced.setObserver(nullptr);
            if (i == 2500) { plain.setStepSize(step + 3); traced.setStepSize(step + 3); }
            plain.addPoint(pts[i]);
            traced.addPoint(pts[i]);
            while (plain.closedClustersAvailable()) a.push_back(plain.grabCluster());
            while (traced.closedClustersAvailable()) b.push_back(traced.grabCluster());
            if (i % 997 == 0)
            {
                ASSERT_EQ(plain.aliveClusters(), traced.aliveClusters()) << "step " << step << " point " << i;
            }
        }
        EXPECT_FALSE(log.events.empty());
        plain.flush();
        traced.flush();
        while (plain.closedClustersAvailable()) a.push_back(plain.grabCluster());
        while (traced.closedClustersAvailable()) b.push_back(traced.grabCluster());
        EXPECT_GT(a.size(), 20u) << "step " << step;
        EXPECT_EQ(a, b) << "step " << step;
    }
}
