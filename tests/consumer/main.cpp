// Uses each module through its umbrella header, as code written against the published RTL does,
// and checks a few numbers so that a broken install fails loudly instead of merely compiling.
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <vector>

#include <rtl/Core.h>
#include <rtl/Transformation.h>
#include <rtl/Segmentation.h>
#include <rtl/Vectorization.h>
#include <rtl/io/StdLib.h>

namespace
{
    int failures = 0;
    void check(bool ok, const char *what)
    {
        if (!ok) { std::fprintf(stderr, "consumer check failed: %s\n", what); ++failures; }
    }
}

int main()
{
    // Core + Transformation: a quarter turn about z followed by a shift.
    rtl::RigidTf3d tf(rtl::C_PId / 2.0, rtl::Vector3d::baseZ(), rtl::Vector3d(1.0, 0.0, 0.0));
    rtl::Vector3d p = tf(rtl::Vector3d(1.0, 0.0, 0.0));
    check(std::abs(p.x() - 1.0) < 1e-12 && std::abs(p.y() - 1.0) < 1e-12, "rigid transform");

    // Segmentation: two arcs at clearly different radii are two clusters.
    std::vector<rtl::Vector2f> scan;
    for (int i = 0; i < 360; ++i)
    {
        float a = static_cast<float>(i) * rtl::C_PIf / 180.0f;
        float r = i < 180 ? 2.0f : 6.0f;
        scan.emplace_back(r * std::cos(a), r * std::sin(a));
    }
    // step 3: each point is compared with its two predecessors; the adaptive threshold (3 * 2pi/360 * r) is three
    // times the spacing of the points on each arc, far below the 4 m jumps between the arcs (also across the seam).
    rtl::CAR_Segmenter<rtl::Vector2f> segmenter(3, 0.05f, 0.5f);
    segmenter.loadData(scan);
    const std::size_t clusters = segmenter.clustersAvailable();
    check(clusters == 2, "segmentation into two clusters");
    check(segmenter.grabCluster().size() + segmenter.grabCluster().size() == scan.size(), "every point in a cluster");

    // Vectorization: an L-shape of noise-free points gives two segments.
    std::vector<rtl::Vector2f> l_shape;
    for (int i = 0; i <= 50; ++i) l_shape.emplace_back(static_cast<float>(i) * 0.1f, 0.0f);
    for (int i = 1; i <= 50; ++i) l_shape.emplace_back(5.0f, static_cast<float>(i) * 0.1f);
    rtl::VectorizerFTLSPolyline2D<float, double> vectorizer;
    vectorizer.setSigma(0.01f);
    vectorizer.setDelta(0.5f);
    check(vectorizer(l_shape), "vectorizer succeeds");
    check(vectorizer.lineSegments().size() == 2, "two segments for an L-shape");

    std::printf("consumer %s: p = [%g, %g, %g], %zu clusters, %zu segments\n", failures == 0 ? "OK" : "FAILED",
                p.x(), p.y(), p.z(), clusters, vectorizer.lineSegments().size());
    return failures == 0 ? 0 : 1;
}
