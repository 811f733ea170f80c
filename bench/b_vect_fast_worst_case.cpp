// FTLS/AFTLS 2D worst case against the typical case at the same n: a corpus of 300 inputs like the
// fuzz corpus's (300-1,500 points: noisy polylines with random corners, arcs, steps and spikes; sigma 0.01-0.06,
// delta 0.05-3), each timed on a reused vectorizer (median of 3 calls, thread CPU time). Reported per vectorizer: the median and
// the maximum time per point over the corpus and their ratio, the five slowest inputs (with their generator
// parameters, to reproduce them), and how many inputs reach the exact search. The ratio is the figure: it compares
// inputs of the same sizes measured in the same run.
// The corpus splits in two by the work done: inputs the extractor and the continuity repairs answer, and inputs that
// need the exact search (PartitionSearch2D: a valid partition whenever one exists, false only when none does). Each
// group's median and maximum are reported too, and, for the slowest inputs, two cost scales measured in the same run:
// enumerating every fitting range (the fit test of each [x, y), skipping the ends and stopping where no range from x
// can fit, as the search does) and the same enumeration building each fitting range's line (the search corner-tests lines).
// --smoke: 20 inputs, one call each.
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

    //! The sum array and line type of the 2D vectorizers (double points, double sums).
    typedef rtl::PrecArrayBlocked<2, double, double> Sums;
    typedef rtl::ApproximationTlsLine2D<double, double> Line;

    //! Time per point of enumerating every fitting range of c (fit test of [x, y) for y from x + 2 on, skipping and
    //! stopping as PartitionSearch2D's scanFits does), building each fitting range's line when `lines`; `fitting`: how
    //! many fit. The scale of visiting each fitting range once (the backward pass enumerates them all; budgeted
    //! rounds skip the ranges their budget excludes).
    double enumerationPerPoint(const Case &c, bool lines, int reps, size_t &fitting)
    {
        Sums a;
        a.resize(c.pts.size());
        a.precompute(c.pts);
        const double s2 = c.sigma * c.sigma;
        const size_t n = c.pts.size();
        std::vector<double> t;
        for (int r = 0; r < reps; ++r)
        {
            const double s = cpuSeconds();
            size_t count = 0;
            double acc = 0;
            for (size_t x = 0; x + 2 <= n; ++x)
                for (size_t y = x + 2; y <= n; ++y)
                {
                    const auto sums = a.sums(x, y);
                    if (y - x == 2 || Line::errorBelow(sums, s2))
                    {
                        ++count;
                        if (lines)
                            acc += Line(sums).direction().x();
                    }
                    else
                    {
                        // As the search: past this total no range from x fits; ends whose range it exceeds are skipped.
                        const double total = Line::errorSquaredCompute(sums) * static_cast<double>(y - x);
                        if (total > 1.01 * s2 * static_cast<double>(n - x))
                            break;
                        const double reach = total / (1.01 * s2);
                        if (reach > static_cast<double>(y - x + 1))
                            y = std::max(y, x + std::min(static_cast<size_t>(reach), n - x) - 1);
                    }
                }
            t.push_back(cpuSeconds() - s);
            rtl::bench::doNotOptimize(acc);
            fitting = count;
        }
        std::sort(t.begin(), t.end());
        return t[t.size() / 2] / static_cast<double>(n);
    }

    double medianOf(std::vector<double> v)
    {
        if (v.empty())
            return 0;
        std::sort(v.begin(), v.end());
        return v[v.size() / 2];
    }
    double maxOf(const std::vector<double> &v) { return v.empty() ? 0 : *std::max_element(v.begin(), v.end()); }

    //! Counts the exact-search repairs (method 5) of a call.
    struct ExactCount
    {
        static constexpr bool enabled = true;
        size_t exact = 0;
        template<class E> void operator()(const E &) {}
        void operator()(const rtl::FtlsRepair &r) { exact += r.method == rtl::FtlsExactSearch; }
    };

    //! The vectorizer with its exact searches' work counters (PartitionSearch2D::Work) in view.
    template<class V0>
    struct Counted : V0
    {
        size_t searchWork() const
        {
            const auto w = this->pipeline.searchWork();
            return w.fits + w.states + w.corners;
        }
    };

    template<class V0, class W>
    void run(const char *name, const std::vector<Case> &corpus, int reps)
    {
        Counted<V0> v;
        W w;
        ExactCount count;
        w.setObserver(&count);
        std::vector<double> tpp;
        std::vector<size_t> order;
        std::vector<double> searched, answered;   // time per point of the inputs that do / do not run the exact search
        size_t exact_inputs = 0, true_calls = 0;
        for (const auto &c : corpus)
        {
            bool ok = false;
            const size_t work_before = v.searchWork();
            tpp.push_back(timePerPoint(v, c, reps, ok));
            (v.searchWork() != work_before ? searched : answered).push_back(tpp.back());
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
        std::printf("   answered without the exact search: %zu inputs, median %.1f ns, max %.1f ns (max/median %.1f)\n", answered.size(),
                    medianOf(answered) * 1e9, maxOf(answered) * 1e9, maxOf(answered) / medianOf(answered));
        std::printf("   exact search run (true or false): %zu inputs, median %.1f ns, max %.1f ns (max/median %.1f; its median / corpus median %.1f)\n",
                    searched.size(), medianOf(searched) * 1e9, maxOf(searched) * 1e9, maxOf(searched) / medianOf(searched), medianOf(searched) / median);
        std::sort(order.begin(), order.end(), [&](size_t p, size_t q) { return tpp[p] > tpp[q]; });
        for (size_t k = 0; k < std::min<size_t>(5, order.size()); ++k)
        {
            const Case &c = corpus[order[k]];
            size_t fitting = 0;
            const double fits = enumerationPerPoint(c, false, reps, fitting), with_lines = enumerationPerPoint(c, true, reps, fitting);
            std::printf("   slow: seed %u shape %d n %zu sigma %.4f delta %.4f noise %.4f seg %.2f: %.1f ns/point (%.2f ms); %.1f fitting ranges/point: "
                        "fit tests %.1f ns/point (%.1f x median), with their lines %.1f ns/point (%.1f x median)\n", c.seed, c.shape, c.n, c.sigma,
                        c.delta, c.noise, c.seg, tpp[order[k]] * 1e9, tpp[order[k]] * static_cast<double>(c.n) * 1e3,
                        static_cast<double>(fitting) / static_cast<double>(c.n), fits * 1e9, fits / median, with_lines * 1e9, with_lines / median);
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
