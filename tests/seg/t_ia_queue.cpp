// IA_Segmenter's closed queue and window test: a consumer that lets the queue grow (past the point where the
// handed-out front is dropped) gets the clusters of an eager consumer in the same order, with the same counts at
// every point, also from a copy; a point that links only to a window point older than the newest (the newest a gap,
// or of another cluster) joins that cluster. Alive lists stay out of the alive map until aliveClusters() is called
// (parked): the counts, the map and the clusters do not depend on when it is called, also for copies and merges.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "rtl/seg/IA_Segmenter.h"
#include "interleaved_scan.h"
#include "seg_check.h"

namespace
{
    using V2f = rtl::VectorND<2, float>;
    using V3d = rtl::VectorND<3, double>;

    //! Many short clusters (runs of `run` points alternating between two radii), as bench/b_seg_same_work.cpp.
    template<class V>
    std::vector<V> shortRuns(size_t n, size_t run)
    {
        using E = typename V::ElementType;
        std::vector<V> pts;
        for (size_t i = 0; i < n; ++i)
        {
            const double a = 2 * M_PI * static_cast<double>(i) / static_cast<double>(n), r = (i / run) % 2 ? 12.0 : 10.0;
            typename V::EigenType e = V::zeros().data();
            e[0] = static_cast<E>(r * std::cos(a));
            e[1] = static_cast<E>(r * std::sin(a));
            pts.push_back(V(e));
        }
        return pts;
    }

    template<class V>
    void lagging(const std::vector<V> &pts, size_t step, typename V::ElementType scaling)
    {
        using E = typename V::ElementType;
        const E lb = E(0.01), ub = E(0.1);
        // eager: every cluster as soon as it closes; closed_by[i] = clusters closed after point i
        rtl::IA_Segmenter<V> eager(step, lb, ub, scaling);
        std::vector<std::vector<V>> ref;
        std::vector<size_t> closed_by;
        for (const V &p : pts)
        {
            eager.addPoint(p);
            while (eager.closedClustersAvailable() > 0) ref.push_back(eager.grabCluster());
            closed_by.push_back(ref.size());
        }
        eager.flush();
        while (eager.closedClustersAvailable() > 0) ref.push_back(eager.grabCluster());
        ASSERT_GT(closed_by.back(), 200u);   // enough for the queue to pass 64 handed-out clusters

        // lagging: phases of 2000 points that grab one cluster every 30 points (the queue grows) alternate with
        // phases that grab up to two per point (the handed-out front grows past the rest and is dropped); a copy
        // taken midway continues on its own, grabbing one every 5 points
        rtl::IA_Segmenter<V> ia(step, lb, ub, scaling);
        std::vector<std::vector<V>> got, copy_got;
        size_t count_mismatches = 0, max_queued = 0;
        rtl::IA_Segmenter<V> copy;
        size_t copy_at = pts.size() / 2;
        for (size_t i = 0; i < pts.size(); ++i)
        {
            ia.addPoint(pts[i]);
            const size_t grabs = (i / 2000) % 2 == 0 ? (i % 30 == 0 ? 1 : 0) : 2;
            for (size_t g = 0; g < grabs && ia.closedClustersAvailable() > 0; ++g) got.push_back(ia.grabCluster());
            count_mismatches += ia.closedClustersAvailable() == closed_by[i] - got.size() ? 0 : 1;
            max_queued = std::max(max_queued, ia.closedClustersAvailable());
            if (i == copy_at)
            {
                copy = ia;
                copy_got = got;
            }
            else if (i > copy_at)
            {
                copy.addPoint(pts[i]);
                if (i % 5 == 0 && copy.closedClustersAvailable() > 0) copy_got.push_back(copy.grabCluster());
            }
        }
        EXPECT_EQ(count_mismatches, 0u);
        EXPECT_GT(max_queued, 64u);
        ia.flush();
        copy.flush();
        while (ia.closedClustersAvailable() > 0) got.push_back(ia.grabCluster());
        while (copy.closedClustersAvailable() > 0) copy_got.push_back(copy.grabCluster());
        EXPECT_TRUE(ia.grabCluster().empty());
        EXPECT_EQ(got, ref);
        EXPECT_EQ(copy_got, ref);
    }

    template<class V>
    std::vector<std::vector<V>> drain(rtl::IA_Segmenter<V> &ia)
    {
        ia.flush();
        std::vector<std::vector<V>> out;
        while (ia.closedClustersAvailable() > 0) out.push_back(ia.grabCluster());
        return out;
    }

    template<class V>
    V pt(double x, double y)
    {
        typename V::EigenType e = V::zeros().data();
        e[0] = static_cast<typename V::ElementType>(x);
        e[1] = static_cast<typename V::ElementType>(y);
        return V(e);
    }

    template<class V>
    void linksPastTheNewest(size_t step)
    {
        // bounds [0.5, 0.5]: points 0.4 apart link, 1 apart do not
        {
            rtl::IA_Segmenter<V> ia(step, 0.5, 0.5, 0);
            ia.addPoint(pt<V>(0, 0));
            ia.addPoint(V::nan());                 // the newest window point is a gap
            ia.addPoint(pt<V>(0.4, 0));            // links to the older point only
            EXPECT_EQ(drain(ia), (std::vector<std::vector<V>>{{pt<V>(0, 0), pt<V>(0.4, 0)}})) << "step " << step;
        }
        {
            rtl::IA_Segmenter<V> ia(step, 0.5, 0.5, 0);
            ia.addPoint(pt<V>(0, 0));              // cluster 0
            ia.addPoint(pt<V>(0, 1));              // cluster 1, the newest
            ia.addPoint(pt<V>(0.4, 0));            // links to cluster 0 only
            EXPECT_EQ(drain(ia), (std::vector<std::vector<V>>{{pt<V>(0, 1)}, {pt<V>(0, 0), pt<V>(0.4, 0)}})) << "step " << step;
        }
        {
            rtl::IA_Segmenter<V> ia(step, 0.5, 0.5, 0);
            ia.addPoint(pt<V>(0, 0));              // cluster 0
            ia.addPoint(pt<V>(0.8, 0));            // cluster 1, the newest
            ia.addPoint(pt<V>(0.4, 0));            // links to both: they merge
            EXPECT_EQ(drain(ia), (std::vector<std::vector<V>>{{pt<V>(0, 0), pt<V>(0.8, 0), pt<V>(0.4, 0)}})) << "step " << step;
        }
    }
}

namespace
{
    // One segmenter never asks for the alive map, one asks after every `every`-th point; copies of both are taken at
    // `copy_every` points (parked and attached lists side by side), compared there and run to the end.
    template<class V>
    void parkedAliveLists(const std::vector<V> &pts, size_t step, typename V::ElementType scaling, size_t every)
    {
        using E = typename V::ElementType;
        const E lb = E(0.01), ub = E(0.1);
        rtl::IA_Segmenter<V> quiet(step, lb, ub, scaling), asked(step, lb, ub, scaling);
        std::vector<std::vector<V>> a, b;
        size_t mismatches = 0, copies = 0;
        for (size_t i = 0; i < pts.size(); ++i)
        {
            quiet.addPoint(pts[i]);
            asked.addPoint(pts[i]);
            mismatches += quiet.aliveClustersAvailable() == asked.aliveClustersAvailable() ? 0 : 1;
            if (i % every == 0)
            {
                const size_t n = asked.aliveClustersAvailable();
                mismatches += asked.aliveClusters().size() == n && asked.aliveClustersAvailable() == n ? 0 : 1;
            }
            if (i % 997 == 0)
            {
                // copies of a segmenter with parked lists (quiet) and with attached ones (asked)
                rtl::IA_Segmenter<V> cq(quiet), ca(asked);
                const auto &alive = cq.aliveClusters();
                mismatches += alive == ca.aliveClusters() && alive == asked.aliveClusters() ? 0 : 1;
                ++copies;
            }
            while (quiet.closedClustersAvailable() > 0) a.push_back(quiet.grabCluster());
            while (asked.closedClustersAvailable() > 0) b.push_back(asked.grabCluster());
        }
        EXPECT_EQ(quiet.aliveClusters(), asked.aliveClusters());
        quiet.flush();
        asked.flush();
        while (quiet.closedClustersAvailable() > 0) a.push_back(quiet.grabCluster());
        while (asked.closedClustersAvailable() > 0) b.push_back(asked.grabCluster());
        EXPECT_EQ(mismatches, 0u) << "every " << every;
        EXPECT_GT(copies, 3u);
        EXPECT_GT(a.size(), 100u);
        EXPECT_EQ(a, b) << "every " << every;
    }
}

TEST(IaQueue, AliveClustersDoNotDependOnWhenTheMapIsAskedFor)
{
    for (size_t step : {size_t(1), size_t(2), size_t(3), size_t(10)})
        for (size_t every : {size_t(1), size_t(3), size_t(50)})
        {
            SCOPED_TRACE("step " + std::to_string(step));
            const size_t n = 6000;
            const float s = rtl::detail::circularScaling<float>(step, n);
            parkedAliveLists(shortRuns<V2f>(n, 10), step, s, every);
            // interleaved chains: merges of parked and attached lists
            parkedAliveLists(segcheck::interleavedScan<V2f>(n, 3, {0.05, 60, 3, 0.02, 0.02}), step, 0.01f, every);
            parkedAliveLists(segcheck::interleavedScan<V3d>(n, 4, {0.03, 40, 2, 0.0, 0.04}), step, 0.02, every);
        }
}

TEST(IaQueue, LaggingConsumerGetsTheEagerClustersInOrder)
{
    for (size_t step : {size_t(2), size_t(3), size_t(10)})
    {
        SCOPED_TRACE("step " + std::to_string(step));
        const size_t n = 20000;
        const float s = rtl::detail::circularScaling<float>(step, n);
        {
            SCOPED_TRACE("2D float runs of 10");
            lagging(shortRuns<V2f>(n, 10), step, s);
        }
        {
            SCOPED_TRACE("3D double runs of 12");
            lagging(shortRuns<V3d>(n, 12), step, static_cast<double>(s));
        }
        {
            SCOPED_TRACE("interleaved");
            lagging(segcheck::interleavedScan<V2f>(n, 3, {0.05, 60, 3, 0.02, 0.02}), step, 0.01f);
        }
    }
}

TEST(IaQueue, PointLinkingOnlyPastTheNewestWindowPointJoinsThatCluster)
{
    for (size_t step : {size_t(2), size_t(3), size_t(5), size_t(10)})
    {
        linksPastTheNewest<V2f>(step);
        linksPastTheNewest<V3d>(step);
    }
}
