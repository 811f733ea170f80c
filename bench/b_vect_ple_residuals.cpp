// Where the squared radial error of rtl::ScanPolylines2D lives on PLE's protocol (see bench/ple/README.md): every hit
// beam of every scan is put in one class, the first that applies, and the classes' shares of the summed squared
// error are printed per log and J, for the defaults and (--points=1) with point candidates:
//   chain end beam  its chain's first or last beam (a beam without a return or a > 1 m step beside it)
//   beside it     the beam next to it inside the chain
//   polyline end  within one beam of its polyline's first or last beam (inside a chain: the polyline breaks there)
//   corner        within one beam of a boundary between two segments of one polyline
//   grazing       the beam meets its segment's line at more than 70 degrees from the normal
//   spill         hit by a segment whose beams do not include it (another segment's widened span)
//   interior      the rest
// Also: how many beams carry half of the error, the share of beams with errors above 0.1 m, and the unexplained beams
// split into chains left out entirely and beams left out inside explained chains. Figures only (no timing).
//
// Data as b_vect_ple_budget (--data=DIR, $RTL_FULL_DATA_DIR, ../shared/data); --smoke: the excerpts in tests/data.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "ple/ple_protocol.h"
#include "rtl/vect/ScanPolylines2D.h"

namespace
{
    std::size_t g_top = 0;   // --top=N: list the N beams of largest error per row
    enum Class { kChainEndBeam, kChainEnd, kPolylineEnd, kCorner, kGrazing, kSpill, kInterior, kClasses };
    const char *const kNames[kClasses] = {"chain end beam", "beside it", "polyline end", "corner", "grazing", "spill", "interior"};

    struct Tally
    {
        std::array<double, kClasses> sum{};
        std::array<std::size_t, kClasses> beams{}, large{};
        std::vector<double> errors;              // every hit beam's squared error
        struct Beam { double e; std::size_t scan, beam, chain_first, chain_last; int cls; long seg_first, seg_last; };
        std::vector<Beam> worst;                 // the beams with |e| > 0.1
        std::size_t unexplained_left_out = 0, unexplained_inside = 0, returned = 0;
    };

    void classify(const rtl::ple::Scan &scan, std::size_t scan_index, const rtl::ScanPolylines2D<double> &ex, double max_gap, Tally &t)
    {
        const std::size_t n = scan.points.size();
        // chain of every returned beam, as in the extractor
        std::vector<long> chain_first(n, -1), chain_last(n, -1);
        for (std::size_t i = 0; i < n;)
        {
            if (!scan.returned[i]) { ++i; continue; }
            std::size_t j = i;
            while (j + 1 < n && scan.returned[j + 1]
                   && std::hypot(scan.points[j + 1][0] - scan.points[j][0], scan.points[j + 1][1] - scan.points[j][1]) <= max_gap) ++j;
            for (std::size_t q = i; q <= j; ++q) { chain_first[q] = static_cast<long>(i); chain_last[q] = static_cast<long>(j); }
            i = j + 1;
        }
        // segment of every beam by the extractor's assignment, and the polylines' and segments' first and last beams
        std::vector<long> seg_of(n, -1);
        std::vector<char> polyline_end(n, 0), corner(n, 0);
        const auto &segs = ex.segments();
        for (std::size_t s = 0; s < segs.size(); ++s)
        {
            for (std::size_t i = segs[s].beams.first; i <= segs[s].beams.second; ++i) seg_of[i] = static_cast<long>(s);
            const bool first = s == 0 || segs[s - 1].polyline != segs[s].polyline;
            const bool last = s + 1 == segs.size() || segs[s + 1].polyline != segs[s].polyline;
            auto mark = [&](std::vector<char> &v, std::size_t b) {
                for (long d = -1; d <= 1; ++d)
                {
                    const long i = static_cast<long>(b) + d;
                    if (i >= 0 && i < static_cast<long>(n)) v[static_cast<std::size_t>(i)] = 1;
                }
            };
            mark(first ? polyline_end : corner, segs[s].beams.first);
            mark(last ? polyline_end : corner, segs[s].beams.second);
        }
        // chains with at least one explained beam
        const auto &rhat = ex.expectedRanges();
        std::vector<char> chain_explained(n, 0);
        for (std::size_t i = 0; i < n; ++i)
            if (scan.returned[i] && !std::isnan(rhat[i])) chain_explained[static_cast<std::size_t>(chain_first[i])] = 1;
        for (std::size_t i = 0; i < n; ++i)
        {
            if (!scan.returned[i]) continue;
            ++t.returned;
            if (std::isnan(rhat[i]))
            {
                (chain_explained[static_cast<std::size_t>(chain_first[i])] ? t.unexplained_inside : t.unexplained_left_out) += 1;
                continue;
            }
            const double e = scan.ranges[i] - rhat[i], e2 = e * e;
            Class c = kInterior;
            const long ii = static_cast<long>(i);
            if (ii == chain_first[i] || ii == chain_last[i]) c = kChainEndBeam;
            else if (ii - chain_first[i] <= 1 || chain_last[i] - ii <= 1) c = kChainEnd;
            else if (polyline_end[i]) c = kPolylineEnd;
            else if (corner[i]) c = kCorner;
            else if (seg_of[i] < 0) c = kSpill;
            else
            {
                const auto &sg = segs[static_cast<std::size_t>(seg_of[i])];
                const double cosine = std::abs(std::cos(sg.theta - scan.angles[i]));
                if (cosine < std::cos(70.0 * rtl::scan_polylines::kPi / 180.0)) c = kGrazing;
            }
            t.sum[c] += e2;
            ++t.beams[c];
            if (std::abs(e) > 0.1)
            {
                ++t.large[c];
                const long sf = seg_of[i] >= 0 ? static_cast<long>(segs[static_cast<std::size_t>(seg_of[i])].beams.first) : -1;
                const long sl = seg_of[i] >= 0 ? static_cast<long>(segs[static_cast<std::size_t>(seg_of[i])].beams.second) : -1;
                t.worst.push_back({e, scan_index, i, static_cast<std::size_t>(chain_first[i]), static_cast<std::size_t>(chain_last[i]), c, sf, sl});
            }
            t.errors.push_back(e2);
        }
    }

    void report(const char *log, std::size_t J, const char *variant, Tally &t)
    {
        double total = 0;
        for (double v : t.sum) total += v;
        std::sort(t.errors.begin(), t.errors.end(), [](double a, double b) { return a > b; });
        std::size_t half = 0;
        for (double acc = 0; half < t.errors.size() && acc < 0.5 * total; ++half) acc += t.errors[half];
        double large_sum = 0;
        std::size_t large = 0;
        for (double e2 : t.errors) if (e2 > 0.01) { large_sum += e2; ++large; }
        std::printf("%-6s %3zu %-8s hit %5zu  sum e^2 %8.4f  half of it in %4zu beams  |e|>0.1: %4zu beams, %5.1f %%  unexplained: left-out chains %4zu, inside %4zu\n",
                    log, J, variant, t.errors.size(), total, half, large, total > 0 ? 100 * large_sum / total : 0.0,
                    t.unexplained_left_out, t.unexplained_inside);
        for (int c = 0; c < kClasses; ++c)
            std::printf("      %-14s beams %5zu (%5.1f %%)  share of e^2 %5.1f %%  |e|>0.1 %4zu\n", kNames[c], t.beams[c],
                        t.errors.empty() ? 0.0 : 100.0 * static_cast<double>(t.beams[c]) / static_cast<double>(t.errors.size()),
                        total > 0 ? 100 * t.sum[c] / total : 0.0, t.large[c]);
        if (g_top)
        {
            std::sort(t.worst.begin(), t.worst.end(), [](const auto &a, const auto &b) { return std::abs(a.e) > std::abs(b.e); });
            for (std::size_t q = 0; q < t.worst.size() && q < g_top; ++q)
            {
                const auto &w = t.worst[q];
                std::printf("      e %+7.3f  scan %2zu beam %3zu  %-14s chain %zu..%zu  segment %ld..%ld\n", w.e, w.scan, w.beam, kNames[w.cls],
                            w.chain_first, w.chain_last, w.seg_first, w.seg_last);
            }
        }
    }
}

int main(int argc, char **argv)
{
    bool smoke = false;
    int points = -1;
    std::string dir;
    if (const char *env = std::getenv("RTL_FULL_DATA_DIR")) dir = env;
    for (int i = 1; i < argc; ++i)
    {
        if (std::strcmp(argv[i], "--smoke") == 0) smoke = true;
        else if (std::strncmp(argv[i], "--data=", 7) == 0) dir = argv[i] + 7;
        else if (std::strncmp(argv[i], "--points=", 9) == 0) points = std::atoi(argv[i] + 9);
        else if (std::strncmp(argv[i], "--top=", 6) == 0) g_top = static_cast<std::size_t>(std::atoi(argv[i] + 6));
        else { std::fprintf(stderr, "usage: %s [--data=DIR] [--points=0|1] [--top=N] [--smoke]\n", argv[0]); return 2; }
    }
    if (dir.empty()) dir = std::string(RTL_TEST_DATA_DIR) + "/../../../shared/data";
    struct LogCase { const char *name, *full, *excerpt; std::vector<std::size_t> lines; };
    const LogCase cases[] = {
        {"intel", "intel-corrected.log.gz", "intel.log", {633, 653, 385, 636, 30, 555, 881, 62, 96, 242, 82, 295, 708, 581, 483, 595, 746, 139, 290, 370}},
        {"csail", "csail-corrected.log.gz", "csail.log", {142, 55, 331, 59, 73, 58, 105, 369, 252, 324, 352, 34, 107, 235, 223, 1, 346, 314, 162, 175}},
    };
    for (const auto &c : cases)
    {
        std::vector<rtl::ple::Scan> scans;
        try
        {
            if (smoke) scans = rtl::ple::readLog(std::string(RTL_TEST_DATA_DIR) + "/" + c.excerpt, false).scans;
            else
            {
                const rtl::ple::Log log = rtl::ple::readLog(dir + "/" + c.full, true);
                for (std::size_t l : c.lines) scans.push_back(log.scans.at(l));
            }
        }
        catch (const std::exception &e)
        {
            std::fprintf(stderr, "%s: %s (give --data=DIR or RTL_FULL_DATA_DIR)\n", c.name, e.what());
            return 1;
        }
        for (std::size_t J : smoke ? std::vector<std::size_t>{50} : std::vector<std::size_t>{30, 40, 50})
            for (int v = 0; v < 2; ++v)
            {
                if ((points == 0 && v == 1) || (points == 1 && v == 0)) continue;
                rtl::ScanPolylines2D<double> ex;
                ex.setMaxVertices(J);
                if (v == 1) ex.setPointCandidates(true, 5);
                Tally t;
                for (std::size_t q = 0; q < scans.size(); ++q)
                {
                    const auto &scan = scans[q];
                    ex(scan.points);
                    classify(scan, q, ex, static_cast<double>(ex.maxGap()), t);
                }
                report(c.name, J, v == 1 ? "points" : "default", t);
            }
    }
    return 0;
}
