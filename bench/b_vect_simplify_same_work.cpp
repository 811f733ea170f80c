// Douglas-Peucker (line and segment distance), Reumann-Witkam, incremental TLS 2D and simplifyCompatibleIndices at
// the paper's setting (semicircle r 8, noise 0.01, eps 0.09, sigma 0.03) at 1e5, 1e6 and 1e7 points. Every figure
// is a ratio to a floor measured in the same run: one pass over the chain computing each point's squared distance
// to one fixed chord and its maximum (the least work of one DP level, and of RW's strip test). Rounds are
// interleaved (floor, DP, ..., floor, DP, ...) and medians reported, so load drift hits all cases alike.
// --smoke: 2000 points, one round.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "bench_util.h"
#include "rtl/Vectorization.h"

namespace
{
    std::vector<rtl::Vector2f> semicircle(size_t n, unsigned seed)
    {
        std::mt19937 rng(seed);
        std::normal_distribution<float> g(0.0f, 0.01f);
        std::vector<rtl::Vector2f> pts;
        pts.reserve(n);
        for (size_t i = 0; i < n; ++i)
        {
            const double a = M_PI * static_cast<double>(i) / static_cast<double>(n - 1);
            pts.emplace_back(static_cast<float>(8 * std::cos(a)) + g(rng), static_cast<float>(8 * std::sin(a)) + g(rng));
        }
        return pts;
    }

    double median(std::vector<double> v)
    {
        std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
        return v[v.size() / 2];
    }
}

int main(int argc, char **argv)
{
    const auto opt = rtl::bench::parseOptions(argc, argv);
    const std::vector<size_t> sizes = opt.smoke ? std::vector<size_t>{2000} : std::vector<size_t>{100000, 1000000, 10000000};
    for (size_t n : sizes)
    {
        const auto pts = semicircle(n, 42);
        std::vector<float> flat;
        for (const auto &p : pts) { flat.push_back(p.x()); flat.push_back(p.y()); }
        rtl::VectorizerDouglasPeucker2f dp(0.09f), dps(0.09f);
        dps.setDistance(rtl::DpDistance::Segment);
        rtl::VectorizerReumannWitkam2f rw(0.09f);
        rtl::VectorizerITLSProjections2D<float, double> itls;
        itls.setSigma(0.03f);
        dp.setMaxSize(n); dps.setMaxSize(n); rw.setMaxSize(n); itls.setMaxSize(n);
        std::vector<rtl::LineSegment2f> out;
        size_t kept_dp = 0, kept_dps = 0, kept_rw = 0, kept_sc = 0, ranges_itls = 0;
        const auto &a = pts.front(), &b = pts.back();
        const float ux = b.x() - a.x(), uy = b.y() - a.y();
        struct Case { std::string name; std::function<void()> fn; std::vector<double> t; };
        std::vector<Case> cases{
            {"floor: distance to one chord", [&] {
                 float m = 0;
                 for (const auto &p : pts)
                 {
                     const float c = (p.x() - a.x()) * uy - (p.y() - a.y()) * ux;
                     m = std::max(m, c * c);
                 }
                 rtl::bench::doNotOptimize(m);
             }, {}},
            {"Douglas-Peucker eps 0.09", [&] { dp(pts, out); kept_dp = out.size() + 1; }, {}},
            {"Douglas-Peucker segment distance", [&] { dps(pts, out); kept_dps = out.size() + 1; }, {}},
            {"Reumann-Witkam eps 0.09", [&] { rw(pts, out); kept_rw = out.size() + 1; }, {}},
            {"incremental TLS sigma 0.03", [&] { itls(pts); ranges_itls = itls.indices().size(); }, {}},
            {"simplifyCompatibleIndices hq 0.09", [&] {
                 kept_sc = rtl::simplifyCompatibleIndices(flat.data(), n, 2, 0.09f, true).size();
             }, {}},
        };
        for (auto &c : cases) c.fn();   // warm-up
        for (int r = 0; r < opt.repetitions; ++r)
            for (auto &c : cases)
            {
                const auto start = std::chrono::steady_clock::now();
                c.fn();
                c.t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
            }
        const std::string title = "semicircle r 8, noise 0.01, " + std::to_string(n) + " points, interleaved medians of " +
                                  std::to_string(opt.repetitions);
        rtl::bench::printHeader(title.c_str());
        const double floor_t = median(cases[0].t);
        for (auto &c : cases)
            rtl::bench::printRow(c.name, n, median(c.t), floor_t);
        std::printf("kept: DP %zu, DP segment %zu, RW %zu, simplify-compatible %zu; ITLS ranges %zu\n", kept_dp, kept_dps,
                    kept_rw, kept_sc, ranges_itls);
    }
    return 0;
}
