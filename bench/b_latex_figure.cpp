// Writing a TikZ figure must be linear in the number of points: the time per point of a polyline with a mark at
// every point (the figure of a long trajectory or a dense scan) is compared across 1e4, 1e5 and 1e6 points.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "bench_util.h"
#include "rtl/io/LaTeXTikz2D.h"

namespace
{
    std::vector<rtl::Vector2f> spiral(size_t n)
    {
        std::vector<rtl::Vector2f> v;
        v.reserve(n);
        for (size_t i = 0; i < n; ++i)
        {
            float t = 0.001f * static_cast<float>(i);
            v.emplace_back(std::cos(t) * (1 + 0.01f * t), std::sin(t) * (1 + 0.01f * t));
        }
        return v;
    }

    //! Collect and write the whole figure (to /dev/null: we time the exporter, not the disk).
    void writeFigure(const std::vector<rtl::Vector2f> &pts)
    {
        rtl::LaTeXTikz2D le;
        le.addPlot(pts, "style={draw=blue}", "style={fill=red}", rtl::LaTeXTikz2D::latex_mark_dot);
        std::ofstream null("/dev/null");
        le.writeTEX(null);
    }
}

int main(int argc, char **argv)
{
    auto opt = rtl::bench::parseOptions(argc, argv);
    std::vector<size_t> sizes = opt.smoke ? std::vector<size_t>{1000, 10000} : std::vector<size_t>{10000, 100000, 1000000};
    rtl::bench::printHeader("LaTeXTikz2D: addPlot (line + dot marks) and writeTEX, time per point vs the smallest size");
    double base_per_point = 0;
    for (size_t n : sizes)
    {
        auto pts = spiral(n);
        int reps = n >= 1000000 ? std::max(1, opt.repetitions / 2) : opt.repetitions;
        double s = rtl::bench::medianSeconds([&] { writeFigure(pts); }, reps);
        if (base_per_point == 0)
            base_per_point = s / static_cast<double>(n);
        // ratio = (time per point) / (time per point at the smallest size): ~1 means linear.
        char note[96];
        std::snprintf(note, sizeof(note), "%.1f ns/point, %.1f ms total", 1e9 * s / static_cast<double>(n), 1e3 * s);
        rtl::bench::printRow("figure " + std::to_string(n) + " points", n, s, base_per_point * static_cast<double>(n),
                             note);
    }
    return 0;
}
