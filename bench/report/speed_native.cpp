// The paper's speed figure, native side: time per point of FTLS, incremental TLS, Douglas-Peucker,
// Reumann-Witkam on the paper's semicircle (radius 8, noise 0.01; sigma 0.03, delta 3, epsilon 0.09) and of the
// CAR and IA segmenters at RTL's step 10, bounds 0.01-0.1, on a closed scan of 10 walls (the semicircle's 0.01
// noise is the lower bound itself: it would cut it into a number of clusters that grows with n), at n = 10, 30,
// 100, ..., 1e6 points, next to a floor measured in the same run: one pass computing each point's squared distance
// to one chord and their maximum. Points are double, as in the rtl-wasm package, so that speed_wasm.mjs times the
// same calls on the same points (it reads the inputs this program writes with --points=DIR).
//
// Each round times every case once at one size (interleaved: load drift hits all cases alike); a case's time is
// a batch of calls divided by the calls, so that a call of 10 points is not lost in the clock's resolution: as
// many calls as cover --batch points (default 200,000), but no more than take about 5 ms of CPU time. Reported:
// the medians over --rounds (default 11) of the thread's CPU time (what the figure shows: on a shared machine it
// does not count the waits for a core) and of the wall time.
//
// Usage: speed_native [--smoke] [--rounds=R] [--batch=P] [--sizes=10,100,...] [--out=FILE.tsv] [--points=DIR]
//                     [--no-header]
// Output (stdout or --out, appended to with --no-header): a TSV, one row per case and size (see writeRow).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <functional>
#include <memory>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "bench_util.h"
#include "rtl/Segmentation.h"
#include "rtl/Vectorization.h"

namespace
{
    using V = rtl::VectorND<2, double>;

    struct Settings
    {
        std::vector<size_t> sizes{10, 30, 100, 300, 1000, 3000, 10000, 30000, 100000, 300000, 1000000};
        int rounds = 11;
        size_t batch = 200000;
        std::string out, points_dir;
        bool header = true;
    };

    std::vector<size_t> parseSizes(const char *s)
    {
        std::vector<size_t> v;
        while (*s)
        {
            char *end = nullptr;
            const unsigned long long n = std::strtoull(s, &end, 10);
            if (end == s) break;
            if (n >= 2) v.push_back(static_cast<size_t>(n));
            s = *end == ',' ? end + 1 : end;
        }
        return v;
    }

    Settings parse(int argc, char **argv)
    {
        Settings s;
        for (int i = 1; i < argc; ++i)
        {
            const char *a = argv[i];
            if (std::strcmp(a, "--smoke") == 0) { s.sizes = {10, 100, 1000}; s.rounds = 1; s.batch = 1000; }
            else if (std::strncmp(a, "--rounds=", 9) == 0) s.rounds = std::max(1, std::atoi(a + 9));
            else if (std::strncmp(a, "--batch=", 8) == 0) s.batch = std::max<size_t>(1, std::strtoull(a + 8, nullptr, 10));
            else if (std::strncmp(a, "--sizes=", 8) == 0) s.sizes = parseSizes(a + 8);
            else if (std::strncmp(a, "--out=", 6) == 0) s.out = a + 6;
            else if (std::strncmp(a, "--points=", 9) == 0) s.points_dir = a + 9;
            else if (std::strcmp(a, "--no-header") == 0) s.header = false;
            else { std::fprintf(stderr, "speed_native: unknown argument '%s'\n", a); std::exit(2); }
        }
        return s;
    }

    //! The paper's semicircle: n points at equal angles on radius 8 around the origin, Gaussian noise 0.01 per axis.
    std::vector<V> semicircle(size_t n)
    {
        std::mt19937 rng(20211);
        std::normal_distribution<double> g(0.0, 0.01);
        std::vector<V> pts(n);
        for (size_t i = 0; i < n; ++i)
        {
            const double a = M_PI * static_cast<double>(i) / static_cast<double>(n - 1);
            const double x = 8 * std::cos(a) + g(rng), y = 8 * std::sin(a) + g(rng);
            pts[i] = V(x, y);
        }
        return pts;
    }

    //! A closed scan of n beams around the origin: 10 walls alternating between radius 10 and 12 (jumps of 2 m,
    //! over the upper bound), uniform noise of +-0.5 mm (under the lower bound): 10 clusters once the beams are
    //! dense enough to link (from about 1000 points), as in b_seg_same_work.
    std::vector<V> scan(size_t n)
    {
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> noise(-0.0005, 0.0005);
        std::vector<V> pts(n);
        for (size_t i = 0; i < n; ++i)
        {
            const double a = 2 * M_PI * static_cast<double>(i) / static_cast<double>(n);
            const double r = ((i * 10 / n) % 2 ? 12.0 : 10.0) + noise(rng);
            pts[i] = V(r * std::cos(a), r * std::sin(a));
        }
        return pts;
    }

    //! Interleaved x, y doubles (little-endian on every machine this runs on), for speed_wasm.mjs.
    void writePoints(const std::string &dir, const std::string &stem, const std::vector<V> &pts)
    {
        const std::string name = dir + "/" + stem + "_" + std::to_string(pts.size()) + ".f64";
        std::ofstream f(name, std::ios::binary);
        for (const V &p : pts)
        {
            const double xy[2] = {p.x(), p.y()};
            f.write(reinterpret_cast<const char *>(xy), sizeof xy);
        }
        if (!f) { std::fprintf(stderr, "speed_native: cannot write %s\n", name.c_str()); std::exit(1); }
    }

    struct Case
    {
        std::string name;
        std::function<size_t()> run;   // one call; returns its output size (segments, kept points or clusters)
        std::vector<double> cpu, wall; // seconds per call, one entry per round
        size_t output = 0;
    };

    double median(std::vector<double> v)
    {
        std::sort(v.begin(), v.end());
        return v[v.size() / 2];
    }

    std::vector<Case> makeCases(const std::vector<V> &pts, const std::vector<V> &ring)
    {
        const size_t n = pts.size();
        // Every case owns its vectorizer or segmenter, reused from call to call (the package keeps them too).
        auto ftls = std::make_shared<rtl::VectorizerFTLSPolyline2D<double, double>>();
        ftls->setSigma(0.03);
        ftls->setDelta(3);
        auto itls = std::make_shared<rtl::VectorizerITLSProjections2D<double, double>>();
        itls->setSigma(0.03);
        auto dp = std::make_shared<rtl::VectorizerDouglasPeuckerND<2, double>>(0.09);
        auto rw = std::make_shared<rtl::VectorizerReumannWitkamND<2, double>>(0.09);
        auto lines = std::make_shared<std::vector<rtl::LineSegmentND<2, double>>>();
        auto car = std::make_shared<rtl::CAR_Segmenter<V>>(10, 0.01, 0.1);
        // IA at step 9 with CAR step 10's threshold compares the same 9 predecessors: the same clusters.
        const double ia_scaling = rtl::detail::circularScaling<double>(10, n);
        const V a = pts.front(), b = pts.back();
        return {
            {"floor", [&pts, a, b] {
                 const double ux = b.x() - a.x(), uy = b.y() - a.y();
                 double m = 0;
                 for (const V &p : pts)
                 {
                     const double c = (p.x() - a.x()) * uy - (p.y() - a.y()) * ux;
                     m = std::max(m, c * c);
                 }
                 rtl::bench::doNotOptimize(m);
                 return size_t(m > 0);
             }, {}, {}, 0},
            {"FTLS", [&pts, ftls] { return (*ftls)(pts) ? ftls->indices().size() : 0; }, {}, {}, 0},
            {"ITLS", [&pts, itls] { return (*itls)(pts) ? itls->indices().size() : 0; }, {}, {}, 0},
            {"DP", [&pts, dp, lines] { (*dp)(pts, *lines); return lines->size() + 1; }, {}, {}, 0},
            {"RW", [&pts, rw, lines] { (*rw)(pts, *lines); return lines->size() + 1; }, {}, {}, 0},
            {"CAR", [&ring, car] {
                 car->loadData(ring);
                 size_t clusters = 0;
                 while (car->clustersAvailable() > 0) clusters += car->grabCluster().empty() ? 0 : 1;
                 return clusters;
             }, {}, {}, 0},
            {"IA", [&ring, ia_scaling] {
                 rtl::IA_Segmenter<V> ia(9, 0.01, 0.1, ia_scaling);
                 size_t clusters = 0;
                 for (const V &p : ring)
                 {
                     ia.addPoint(p);
                     while (ia.closedClustersAvailable() > 0) clusters += ia.grabCluster().empty() ? 0 : 1;
                 }
                 ia.flush();
                 while (ia.closedClustersAvailable() > 0) clusters += ia.grabCluster().empty() ? 0 : 1;
                 return clusters;
             }, {}, {}, 0},
        };
    }

    double threadCpuSeconds()
    {
        timespec t{};
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
        return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
    }

    //! Calls per timed batch: enough to cover `batch` points, but no more than take about 5 ms of CPU time
    //! (doubling the calls until they take 1 ms tells the time of one; CPU time, so that a wait for a core on a
    //! loaded machine does not shrink the batch).
    size_t batchCalls(Case &c, size_t n, size_t batch)
    {
        const size_t by_points = std::max<size_t>(1, (batch + n - 1) / n);
        for (size_t k = 1;; k *= 2)
        {
            size_t out = 0;
            const double t0 = threadCpuSeconds();
            for (size_t i = 0; i < k; ++i) out += c.run();
            const double t = threadCpuSeconds() - t0;
            rtl::bench::doNotOptimize(out);
            if (t >= 1e-3 || k >= by_points)
                return std::min(by_points, std::max<size_t>(1, static_cast<size_t>(std::ceil(5e-3 * static_cast<double>(k) / t))));
        }
    }

    //! impl, case, points, rounds, calls per batch, median ns per point of the whole call in CPU and in wall time,
    //! of the library's part (natively the whole call: "-"), and the output size.
    void writeRow(std::ostream &os, const Case &c, size_t n, int rounds, size_t calls)
    {
        const double to_ns = 1e9 / static_cast<double>(n);
        char line[256];
        std::snprintf(line, sizeof line, "native\t%s\t%zu\t%d\t%zu\t%.6g\t%.6g\t-\t%zu\n", c.name.c_str(), n, rounds, calls,
                      median(c.cpu) * to_ns, median(c.wall) * to_ns, c.output);
        os << line;
    }
}

int main(int argc, char **argv)
{
    const Settings s = parse(argc, argv);
    std::ofstream file;
    if (!s.out.empty())
    {
        file.open(s.out, s.header ? std::ios::trunc : std::ios::app);
        if (!file) { std::fprintf(stderr, "speed_native: cannot write %s\n", s.out.c_str()); return 1; }
    }
    std::ostream &os = s.out.empty() ? std::cout : file;
    if (s.header) os << "impl\tcase\tpoints\trounds\tcalls\tcpu_ns_per_point\twall_ns_per_point\tlibrary_ns_per_point\toutput\n";
    for (size_t n : s.sizes)
    {
        const auto pts = semicircle(n), ring = scan(n);
        if (!s.points_dir.empty())
        {
            writePoints(s.points_dir, "semicircle", pts);
            writePoints(s.points_dir, "scan", ring);
        }
        auto cases = makeCases(pts, ring);
        std::vector<size_t> calls;
        for (auto &c : cases)
        {
            c.output = c.run();   // warm-up: buffers sized, code and data in cache
            calls.push_back(batchCalls(c, n, s.batch));
        }
        for (int r = 0; r < s.rounds; ++r)
            for (size_t i = 0; i < cases.size(); ++i)
            {
                Case &c = cases[i];
                size_t out = 0;
                const auto t0 = std::chrono::steady_clock::now();
                const double c0 = threadCpuSeconds();
                for (size_t k = 0; k < calls[i]; ++k) out += c.run();
                c.cpu.push_back((threadCpuSeconds() - c0) / static_cast<double>(calls[i]));
                const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
                c.wall.push_back(t / static_cast<double>(calls[i]));
                rtl::bench::doNotOptimize(out);
            }
        for (size_t i = 0; i < cases.size(); ++i) writeRow(os, cases[i], n, s.rounds, calls[i]);
        os.flush();
        // The two segmenters compare the same neighbours with the same threshold: they must agree.
        if (cases[5].output != cases[6].output)
        {
            std::fprintf(stderr, "speed_native: CAR found %zu clusters, IA %zu at %zu points\n", cases[5].output,
                         cases[6].output, n);
            return 1;
        }
        std::fprintf(stderr, "speed_native: %zu points done\n", n);
    }
    return 0;
}
