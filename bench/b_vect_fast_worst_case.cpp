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

#include "../tests/vect/t_fast_corpus.h"
#include "bench_util.h"
#include "rtl/Vectorization.h"

namespace
{
    using rtl::fast_corpus::Case;
    using rtl::fast_corpus::makeCase;

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
