// Copies and moves of the segmenters: a copy taken mid-stream continues on its own exactly as the source
// would (the source destroyed first, so that ASan sees any iterator left pointing into it), moves are noexcept, and
// a growing std::vector of segmenters moves them rather than copying.
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>

#include "rtl/seg/CAR_Segmenter.h"
#include "rtl/seg/IA_Segmenter.h"
#include "interleaved_scan.h"
#include "seg_check.h"

namespace
{
    using V2f = rtl::VectorND<2, float>;
    using V3d = rtl::VectorND<3, double>;

    static_assert(std::is_nothrow_move_constructible_v<rtl::IA_Segmenter<V2f>>);
    static_assert(std::is_nothrow_move_assignable_v<rtl::IA_Segmenter<V3d>>);
    static_assert(std::is_nothrow_move_constructible_v<rtl::CAR_Segmenter<V2f>>);
    static_assert(std::is_nothrow_move_assignable_v<rtl::CAR_Segmenter<V3d>>);
    static_assert(std::is_copy_constructible_v<rtl::IA_Segmenter<V2f>> && std::is_copy_assignable_v<rtl::IA_Segmenter<V2f>>);

    //! A scan with long clusters, interleaved chains (so that alive lists are merged out of order) and gaps.
    template<class V>
    std::vector<V> scan(size_t n, unsigned seed)
    {
        return segcheck::interleavedScan<V>(n, seed, {0.03, 40, 2, 0.0, 0.04});
    }

    template<class V>
    using Clusters = std::vector<std::vector<V>>;

    template<class V>
    void drain(rtl::IA_Segmenter<V> &ia, Clusters<V> &out)
    {
        while (ia.closedClustersAvailable() > 0) out.push_back(ia.grabCluster());
    }

    template<class V>
    Clusters<V> finish(rtl::IA_Segmenter<V> &ia, const std::vector<V> &pts, size_t from, Clusters<V> out)
    {
        for (size_t i = from; i < pts.size(); ++i)
        {
            ia.addPoint(pts[i]);
            if (i % 7 == 0) drain(ia, out);
        }
        ia.flush();
        drain(ia, out);
        return out;
    }

    template<class V>
    void iaCopyContinues(size_t step)
    {
        const auto pts = scan<V>(900, 5 + static_cast<unsigned>(step));
        const auto scaling = static_cast<typename V::ElementType>(0.05);
        rtl::IA_Segmenter<V> whole(step, 0.05f, 0.6f, scaling);
        const Clusters<V> expected = finish(whole, pts, 0, {});
        ASSERT_GT(expected.size(), 10u);

        for (size_t cut : {size_t(1), size_t(37), size_t(300), size_t(611)})
        {
            auto source = std::make_unique<rtl::IA_Segmenter<V>>(step, 0.05f, 0.6f, scaling);
            Clusters<V> before;
            for (size_t i = 0; i < cut; ++i)
            {
                source->addPoint(pts[i]);
                if (i % 7 == 0) drain(*source, before);
            }
            const size_t alive = source->aliveClustersAvailable();
            rtl::IA_Segmenter<V> copy(*source);
            rtl::IA_Segmenter<V> assigned;
            assigned = *source;
            EXPECT_EQ(copy.aliveClustersAvailable(), alive);
            // the source goes on first, then dies: the copies must not depend on it
            const Clusters<V> from_source = finish(*source, pts, cut, before);
            source.reset();
            const std::string what = "step " + std::to_string(step) + " cut " + std::to_string(cut);
            EXPECT_EQ(from_source, expected) << what;
            EXPECT_EQ(finish(copy, pts, cut, before), expected) << what << " (copy)";
            EXPECT_EQ(finish(assigned, pts, cut, before), expected) << what << " (assigned)";
        }
    }

    template<class V>
    void iaMoveContinues(size_t step)
    {
        const auto pts = scan<V>(700, 11 + static_cast<unsigned>(step));
        const auto scaling = static_cast<typename V::ElementType>(0.05);
        rtl::IA_Segmenter<V> whole(step, 0.05f, 0.6f, scaling);
        const Clusters<V> expected = finish(whole, pts, 0, {});

        auto source = std::make_unique<rtl::IA_Segmenter<V>>(step, 0.05f, 0.6f, scaling);
        Clusters<V> before;
        for (size_t i = 0; i < 350; ++i) source->addPoint(pts[i]);
        drain(*source, before);
        rtl::IA_Segmenter<V> moved(std::move(*source));
        source.reset();
        rtl::IA_Segmenter<V> target;
        target.addPoint(V::zeros());        // state that the assignment must replace entirely
        target = std::move(moved);
        EXPECT_EQ(finish(target, pts, 350, before), expected) << "step " << step;
    }
}

TEST(CopyMove, IaCopyMidStreamContinuesLikeTheSource)
{
    for (size_t step : {1, 2, 3, 5, 10}) iaCopyContinues<V2f>(step);
    for (size_t step : {1, 4}) iaCopyContinues<V3d>(step);
}

TEST(CopyMove, IaMoveMidStreamContinuesLikeTheSource)
{
    for (size_t step : {1, 3, 10}) iaMoveContinues<V2f>(step);
    iaMoveContinues<V3d>(2);
}

// A vector of segmenters that grows while each is mid-stream (the move is used, or the copy: both must be right).
TEST(CopyMove, IaVectorGrowth)
{
    const auto pts = scan<V2f>(600, 3);
    rtl::IA_Segmenter<V2f> whole(3, 0.05f, 0.6f, 0.05f);
    const Clusters<V2f> expected = finish(whole, pts, 0, {});
    std::vector<rtl::IA_Segmenter<V2f>> many;
    std::vector<Clusters<V2f>> got(40);
    for (size_t k = 0; k < 40; ++k)
    {
        many.emplace_back(3, 0.05f, 0.6f, 0.05f);           // reallocates: earlier segmenters are moved
        for (size_t m = 0; m < many.size(); ++m)
            for (size_t i = 15 * (k - m); i < 15 * (k - m + 1); ++i) many[m].addPoint(pts[i]);
    }
    for (size_t m = 0; m < many.size(); ++m)
    {
        // segmenter m has seen 15 * (40 - m) points
        EXPECT_EQ(finish(many[m], pts, 15 * (40 - m), {}), expected) << "segmenter " << m;
    }
}

TEST(CopyMove, CarCopyAndMoveKeepTheirClusters)
{
    const auto pts = scan<V2f>(800, 9);
    for (size_t step : {1, 2, 3, 10})
    {
        rtl::CAR_Segmenter<V2f> ref(step, 0.05f, 0.6f);
        const Clusters<V2f> expected = segcheck::runCar(ref, pts, V2f::zeros());
        ASSERT_GT(expected.size(), 3u);

        auto source = std::make_unique<rtl::CAR_Segmenter<V2f>>(step, 0.05f, 0.6f);
        source->loadData(pts);
        Clusters<V2f> first{source->grabCluster()};
        rtl::CAR_Segmenter<V2f> copy(*source);
        rtl::CAR_Segmenter<V2f> moved(std::move(*source));
        EXPECT_EQ(source->clustersAvailable(), 0u) << "a moved-from segmenter has nothing to hand out";
        EXPECT_TRUE(source->grabCluster().empty());
        source->loadData(pts);                               // and can work again
        EXPECT_EQ(segcheck::runCar(*source, pts, V2f::zeros()), expected);
        source.reset();
        for (auto *car : {&copy, &moved})
        {
            Clusters<V2f> got = first;
            while (car->clustersAvailable() > 0) got.push_back(car->grabCluster());
            EXPECT_EQ(got, expected) << "step " << step;
            EXPECT_EQ(segcheck::runCar(*car, pts, V2f::zeros()), expected) << "step " << step << " reloaded";
        }
    }
}

TEST(CopyMove, CarVectorGrowth)
{
    const auto pts = scan<V3d>(500, 4);
    rtl::CAR_Segmenter<V3d> ref(3, 0.05, 0.6);
    const Clusters<V3d> expected = segcheck::runCar(ref, pts, V3d::zeros());
    std::vector<rtl::CAR_Segmenter<V3d>> many;
    for (int k = 0; k < 20; ++k)
    {
        many.emplace_back(3, 0.05, 0.6);
        many.back().loadData(pts);
    }
    for (auto &car : many)
    {
        Clusters<V3d> got;
        while (car.clustersAvailable() > 0) got.push_back(car.grabCluster());
        EXPECT_EQ(got, expected);
    }
}
