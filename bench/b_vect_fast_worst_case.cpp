// FTLS/AFTLS 2D worst case against the typical case at the same n (issue 15 item 7): a corpus of 300 inputs like the
// fuzz corpus's (300-1,500 points: noisy polylines with random corners, arcs, steps and spikes; sigma 0.01-0.06,
// delta 0.05-3), each timed on a reused vectorizer (median of 3 calls, thread CPU time). Reported per vectorizer: the median and
// the maximum time per point over the corpus and their ratio, the five slowest inputs (with their generator
// parameters, to reproduce them), and how many inputs reach the exact search. The ratio is the figure: it compares
// inputs of the same sizes measured in the same run. --smoke: 20 inputs, one call each.
#include <algorithm>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "bench_util.h"
#include "rtl/Vectorization.h"

namespace
{
    struct Case
    {
        unsigned seed;
        int shape;   // 0 polyline, 1 arc + polyline, 2 steps, 3 polyline with spikes
        size_t n;
        double sigma, delta, noise, seg;
        std::vector<rtl::Vector2d> pts;
    };

    Case makeCase(unsigned seed)
    {
        std::mt19937 g(seed);
        std::uniform_real_distribution<double> u(0, 1);
        Case c;
        c.seed = seed;
        c.shape = static_cast<int>(g() % 4);
        c.n = 300 + g() % 1201;
        c.sigma = 0.01 + 0.05 * u(g);
        c.delta = std::exp(std::log(0.05) + (std::log(3.0) - std::log(0.05)) * u(g));
        c.noise = c.sigma * (0.2 + 1.6 * u(g));
        c.seg = 0.2 + 4 * u(g);   // mean segment length in length units
        const double step = 0.01 + 0.04 * u(g);
        std::normal_distribution<double> nd(0, c.noise);
        double x = 0, y = 0, a = 2 * M_PI * u(g), curv = 0;
        double left = c.seg;
        for (size_t i = 0; i < c.n; ++i)
        {
            c.pts.push_back(rtl::Vector2d(x + nd(g), y + nd(g)));
            if (c.shape == 3 && g() % 97 == 0)
                c.pts.back() = rtl::Vector2d(x + 10 * c.noise * (u(g) - 0.5) * 20, y + 10 * c.noise * (u(g) - 0.5) * 20);
            left -= step;
            if (left <= 0)
            {
                left = c.seg * (0.3 + 1.4 * u(g));
                if (c.shape == 2)
                {
                    x += (u(g) - 0.5) * 4 * c.delta;
                    y += (u(g) - 0.5) * 4 * c.delta;
                }
                else
                    a += (u(g) - 0.5) * 2.5;
                curv = c.shape == 1 && u(g) < 0.5 ? (u(g) - 0.5) * 0.2 : 0;
            }
            a += curv;
            x += step * std::cos(a);
            y += step * std::sin(a);
        }
        return c;
    }

    //! This thread's CPU time: on a shared, loaded machine wall time would count the other processes' turns.
    double cpuSeconds()
    {
        timespec ts{};
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
        return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
    }

    template<class V>
    double timePerPoint(V &v, const Case &c, int reps, bool &ok)
    {
        v.setSigma(c.sigma);
        v.setDelta(c.delta);
        std::vector<double> t;
        for (int r = 0; r < reps; ++r)
        {
            const double s = cpuSeconds();
            ok = v(c.pts);
            t.push_back(cpuSeconds() - s);
            rtl::bench::doNotOptimize(v.indices().size());
        }
        std::sort(t.begin(), t.end());
        return t[t.size() / 2] / static_cast<double>(c.n);
    }

    //! Counts the exact-search repairs (method 5) of a call.
    struct ExactCount
    {
        static constexpr bool enabled = true;
        size_t exact = 0;
        template<class E> void operator()(const E &) {}
        void operator()(const rtl::FtlsRepair &r) { exact += r.method == rtl::FtlsExactSearch; }
    };

    template<class V, class W>
    void run(const char *name, const std::vector<Case> &corpus, int reps)
    {
        V v;
        W w;
        ExactCount count;
        w.setObserver(&count);
        std::vector<double> tpp;
        std::vector<size_t> order;
        size_t exact_inputs = 0, true_calls = 0;
        for (const auto &c : corpus)
        {
            bool ok = false;
            tpp.push_back(timePerPoint(v, c, reps, ok));
            true_calls += ok;
            count.exact = 0;
            w.setSigma(c.sigma);
            w.setDelta(c.delta);
            w(c.pts);
            exact_inputs += count.exact > 0;
            order.push_back(order.size());
        }
        std::vector<double> sorted = tpp;
        std::sort(sorted.begin(), sorted.end());
        const double median = sorted[sorted.size() / 2], mx = sorted.back();
        std::printf("%-6s inputs %zu (true %zu, exact search in %zu): time/point median %.1f ns, max %.1f ns, max/median %.1f\n", name,
                    corpus.size(), true_calls, exact_inputs, median * 1e9, mx * 1e9, mx / median);
        std::sort(order.begin(), order.end(), [&](size_t p, size_t q) { return tpp[p] > tpp[q]; });
        for (size_t k = 0; k < std::min<size_t>(5, order.size()); ++k)
        {
            const Case &c = corpus[order[k]];
            std::printf("   slow: seed %u shape %d n %zu sigma %.4f delta %.4f noise %.4f seg %.2f: %.1f ns/point (%.2f ms)\n", c.seed, c.shape, c.n,
                        c.sigma, c.delta, c.noise, c.seg, tpp[order[k]] * 1e9, tpp[order[k]] * static_cast<double>(c.n) * 1e3);
        }
    }
}

int main(int argc, char **argv)
{
    const auto opt = rtl::bench::parseOptions(argc, argv);
    const size_t count = opt.smoke ? 20 : 300;
    const int reps = opt.smoke ? 1 : 3;
    std::vector<Case> corpus;
    for (unsigned s = 1; corpus.size() < count; ++s)
        corpus.push_back(makeCase(s));
    std::printf("FTLS/AFTLS 2D worst case over %zu inputs (300-1500 points), time per point of a reused vectorizer\n", corpus.size());
    run<rtl::VectorizerFTLSPolyline2D<double, double>, rtl::VectorizerFTLSPolyline2D<double, double, ExactCount>>("FTLS", corpus, reps);
    run<rtl::VectorizerAFTLSPolyline2D<double, double>, rtl::VectorizerAFTLSPolyline2D<double, double, ExactCount>>("AFTLS", corpus, reps);
    return 0;
}
