// IA_Segmenter's tail mode (a window all in one cluster kept at the end of its alive list, left on any other event):
// the alive lists, closed clusters and final clusters are those of a brute-force model at every point, however
// the stream is observed, copied, moved or re-parametrised while a cluster is in tail mode.
#include <algorithm>
#include <cmath>
#include <map>
#include <random>
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

    //! Long clusters, clusters interleaved point by point (merged out of order), isolated points and gaps.
    template<class V>
    std::vector<V> scan(size_t n, unsigned seed)
    {
        return segcheck::interleavedScan<V>(n, seed, {0.02, 60, 3, 0.01, 0.02});
    }

    //! The stream model after m points (window `step`): components of the pairs seen so far; a component with a
    //! point among the last `step` is alive with its points before them (listed only when there are some), the
    //! others are closed.
    template<class V>
    struct Model
    {
        std::vector<V> pts;
        size_t step;
        typename V::ElementType lb, ub, scaling;
        segcheck::UnionFind uf{0};

        void add(const V &p)
        {
            pts.push_back(p);
            uf.p.push_back(uf.p.size());
            const size_t i = pts.size() - 1;
            if (segcheck::isGap(p)) return;
            for (size_t k = 1; k <= step && k <= i; ++k)
                if (!segcheck::isGap(pts[i - k]) && rtl::detail::meetsCriterion(pts[i - k], p, V::zeros(), scaling, lb, ub))
                    uf.unite(i, i - k);
        }
        //! Alive lists in the order of their first point (IA's ids grow with creation, a merge keeps the older).
        std::vector<std::vector<V>> alive()
        {
            const size_t m = pts.size(), cut = m > step ? m - step : 0;
            std::map<size_t, bool> in_window;
            for (size_t i = cut; i < m; ++i)
                if (!segcheck::isGap(pts[i])) in_window[uf.find(i)] = true;
            std::map<size_t, std::vector<V>> lists;
            for (size_t i = 0; i < cut; ++i)
                if (!segcheck::isGap(pts[i]) && in_window.count(uf.find(i))) lists[uf.find(i)].push_back(pts[i]);
            std::vector<std::vector<V>> out;
            for (auto &kv : lists) out.push_back(kv.second);
            return out;
        }
        size_t closedPoints()
        {
            const size_t m = pts.size(), cut = m > step ? m - step : 0;
            std::map<size_t, bool> in_window;
            for (size_t i = cut; i < m; ++i)
                if (!segcheck::isGap(pts[i])) in_window[uf.find(i)] = true;
            size_t c = 0;
            for (size_t i = 0; i < cut; ++i) c += !segcheck::isGap(pts[i]) && !in_window.count(uf.find(i)) ? 1 : 0;
            return c;
        }
    };

    template<class V>
    std::vector<std::vector<V>> aliveOf(const rtl::IA_Segmenter<V> &ia)
    {
        std::vector<std::vector<V>> out;
        for (const auto &kv : ia.aliveClusters()) out.push_back(kv.second);
        return out;
    }

    template<class V>
    void aliveListsFollowTheModel(size_t step, unsigned seed)
    {
        using E = typename V::ElementType;
        const auto pts = scan<V>(700, seed);
        const E lb = E(0.05), ub = E(0.6), scaling = E(0.05);
        rtl::IA_Segmenter<V> ia(step, lb, ub, scaling);
        Model<V> model{{}, step, lb, ub, scaling};
        std::mt19937 rng(seed);
        size_t grabbed = 0, mismatches = 0, closed_mismatches = 0;
        for (size_t i = 0; i < pts.size(); ++i)
        {
            ia.addPoint(pts[i]);
            model.add(pts[i]);
            // looked at after some points only, so that tail mode also runs for many points unobserved
            if (rng() % 5 == 0)
            {
                mismatches += aliveOf(ia) == model.alive() ? 0 : 1;
                if (mismatches == 1 && aliveOf(ia) != model.alive()) ADD_FAILURE() << "step " << step << ": first alive mismatch at point " << i;
            }
            if (rng() % 3 == 0)
                while (ia.closedClustersAvailable() > 0) grabbed += ia.grabCluster().size();
            if (rng() % 4 == 0)
            {
                size_t queued = 0;
                // copies see the same queue: count it without emptying this one
                rtl::IA_Segmenter<V> copy(ia);
                while (copy.closedClustersAvailable() > 0) queued += copy.grabCluster().size();
                closed_mismatches += grabbed + queued == model.closedPoints() ? 0 : 1;
            }
        }
        EXPECT_EQ(mismatches, 0u) << "step " << step;
        EXPECT_EQ(closed_mismatches, 0u) << "step " << step;
    }

    template<class V>
    std::vector<std::vector<V>> drainAll(rtl::IA_Segmenter<V> &ia)
    {
        ia.flush();
        std::vector<std::vector<V>> out;
        while (ia.closedClustersAvailable() > 0) out.push_back(ia.grabCluster());
        return out;
    }
}

TEST(IaTail, AliveListsFollowTheModelAtEveryPoint)
{
    for (size_t step : {1, 2, 3, 5, 10})
        for (unsigned seed : {1u, 2u, 3u}) aliveListsFollowTheModel<V2f>(step, seed);
    for (size_t step : {1, 4}) aliveListsFollowTheModel<V3d>(step, 9);
}

// The final clusters against the brute-force reference when the stream is observed after every point (every point
// leaves tail mode), after every 7th, or never; and through the shared checker (grab patterns, accounting).
TEST(IaTail, ClustersMatchTheReferenceWhateverTheObservation)
{
    const auto pts = scan<V2f>(2000, 17);
    for (size_t step : {1, 2, 3, 10})
    {
        for (size_t grab : {1, 5}) segcheck::checkIa(pts, V2f::zeros(), step, 0.05f, 0.6f, grab, "tail step " + std::to_string(step));
        std::vector<std::vector<std::vector<V2f>>> got;
        for (size_t every : {0, 1, 7})
        {
            rtl::IA_Segmenter<V2f> ia(step, 0.05f, 0.6f, 0.05f);
            std::vector<std::vector<V2f>> out;
            for (size_t i = 0; i < pts.size(); ++i)
            {
                ia.addPoint(pts[i]);
                if (every != 0 && i % every == 0) (void)ia.aliveClusters();
                while (ia.closedClustersAvailable() > 0) out.push_back(ia.grabCluster());
            }
            for (auto &c : drainAll(ia)) out.push_back(c);
            got.push_back(out);
        }
        EXPECT_EQ(got[1], got[0]) << "step " << step;
        EXPECT_EQ(got[2], got[0]) << "step " << step;
    }
}

// One long line, so that the segmenter is in tail mode at every cut; there: a copy, a const copy's alive list, a
// move, parameter setters, window changes (grow, shrink) and a flush, each against a segmenter that did not stop.
TEST(IaTail, EventsInsideALongCluster)
{
    auto point = [](size_t i) { return i < 3000 ? V2f(0.01f * static_cast<float>(i), 0) : V2f(0.01f * static_cast<float>(i), 5); };
    std::vector<V2f> pts;
    for (size_t i = 0; i < 4000; ++i) pts.push_back(point(i));
    for (size_t step : {1, 3, 10})
    {
        rtl::IA_Segmenter<V2f> ref(step, 0.02f, 0.02f, 0.0f);
        for (const auto &p : pts) ref.addPoint(p);
        const auto expected = drainAll(ref);
        ASSERT_EQ(expected.size(), 2u);

        rtl::IA_Segmenter<V2f> ia(step, 0.02f, 0.02f, 0.0f);
        for (size_t i = 0; i < 1000; ++i) ia.addPoint(pts[i]);
        {
            const rtl::IA_Segmenter<V2f> frozen(ia);   // a const copy in tail mode: aliveClusters() is const
            ASSERT_EQ(frozen.aliveClustersAvailable(), 1u);
            const auto &c = frozen.aliveClusters().begin()->second;
            ASSERT_EQ(c.size(), 1000 - step);
            for (size_t k = 0; k < c.size(); ++k) ASSERT_EQ(c[k], pts[k]);
        }
        rtl::IA_Segmenter<V2f> copy(ia);
        for (size_t i = 1000; i < 1500; ++i) ia.addPoint(pts[i]);
        rtl::IA_Segmenter<V2f> moved(std::move(ia));
        moved.setLowerBound(0.02f);                      // same values: nothing changes but the checks
        moved.setScaling(0.0f);
        for (size_t i = 1500; i < 2000; ++i) moved.addPoint(pts[i]);
        moved.setStepSize(static_cast<unsigned>(step + 4));
        for (size_t i = 2000; i < 2300; ++i) moved.addPoint(pts[i]);
        EXPECT_EQ(moved.aliveClusters().begin()->second.size(), 2300 - (step + 4));
        moved.setStepSize(static_cast<unsigned>(step));
        EXPECT_EQ(moved.aliveClusters().begin()->second.size(), 2300 - step);
        for (size_t i = 2300; i < pts.size(); ++i) moved.addPoint(pts[i]);
        EXPECT_EQ(drainAll(moved), expected) << "step " << step;
        for (size_t i = 1000; i < pts.size(); ++i) copy.addPoint(pts[i]);
        EXPECT_EQ(drainAll(copy), expected) << "step " << step << " (copy)";

        // flush inside the line: the cluster closes with every point so far, and a new stream starts cleanly
        rtl::IA_Segmenter<V2f> cut(step, 0.02f, 0.02f, 0.0f);
        for (size_t i = 0; i < 700; ++i) cut.addPoint(pts[i]);
        const auto first = drainAll(cut);
        ASSERT_EQ(first.size(), 1u);
        EXPECT_EQ(first[0], std::vector<V2f>(pts.begin(), pts.begin() + 700));
        for (size_t i = 700; i < 1400; ++i) cut.addPoint(pts[i]);
        const auto second = drainAll(cut);
        ASSERT_EQ(second.size(), 1u);
        EXPECT_EQ(second[0], std::vector<V2f>(pts.begin() + 700, pts.begin() + 1400));
    }
}

// A cluster whose alive list is no longer in stream order of consecutive indices (two interleaved chains merged)
// enters tail mode afterwards: the points kept in tail mode get their stream indices, so that a later merge with an
// interleaved cluster still orders them.
TEST(IaTail, TailAfterAnOutOfOrderMerge)
{
    // Scenario 0: even points on y = 0, odd points on y = 1 until 200 (two chains); from 200 on every point on
    // y = 0.5 links both (an interleaved merge, then tail mode). Scenario 1: one chain on y = 0.5 with a gap at
    // 300 (its alive list then skips an index when tail mode starts). In both, odd points of [600, 800) start a
    // chain on y = 1.2 (out of reach of 0.5), and from 800 on points on y = 0.85 join it to the first cluster
    // again: a merge that needs the true stream indices of the points kept in tail mode.
    for (int scenario : {0, 1})
    {
        std::vector<V2f> pts, valid;
        for (size_t i = 0; i < 1200; ++i)
        {
            const float x = 0.01f * static_cast<float>(i);
            float y = i < 200 && scenario == 0 ? ((i % 2) ? 1.0f : 0.0f) : 0.5f;
            if (i >= 600 && i < 800 && i % 2) y = 1.2f;
            if (i >= 800) y = 0.85f;
            pts.push_back(scenario == 1 && i == 300 ? V2f::nan() : V2f(x, y));
            if (!segcheck::isGap(pts.back())) valid.push_back(pts.back());
        }
        for (size_t step : {2, 3, 6})
        {
            const std::string what = "scenario " + std::to_string(scenario) + " step " + std::to_string(step);
            for (size_t grab : {1, 3}) segcheck::checkIa(pts, V2f::zeros(), step, 0.6f, 0.6f, grab, what);
            Model<V2f> model{{}, step, 0.6f, 0.6f, 0.0f};
            rtl::IA_Segmenter<V2f> ia(step, 0.6f, 0.6f, 0.0f);
            size_t mismatches = 0;
            for (size_t i = 0; i < pts.size(); ++i)
            {
                ia.addPoint(pts[i]);
                model.add(pts[i]);
                if (i % 50 == 49) mismatches += aliveOf(ia) == model.alive() ? 0 : 1;
            }
            EXPECT_EQ(mismatches, 0u) << what;
            const auto clusters = drainAll(ia);
            ASSERT_EQ(clusters.size(), 1u) << what;
            EXPECT_EQ(clusters[0], valid) << what << ": not in stream order";
        }
    }
}
