// FTLS/AFTLS on every cluster of real CARMEN logs: segment each scan with
// CAR (step 2, bounds 0.1 .. 0.5 m: the package defaults), vectorize every cluster of >= 3 points at sigma 0.03,
// delta 0.3 (the package defaults) and count
//   - false returns, split by the exact feasibility search's verdict (feasible = a valid partition exists),
//   - chains where AFTLS ends with a larger total squared error than FTLS (goal 0),
//   - segments per method, and strict vs split mode: share of clusters with no segments, segments per cluster,
//     RMS orthogonal residual over the vectorized points (a point shared by two ranges of split mode's cover
//     counts in both), and the clusters split mode covers with ranges that share points (no partition exists).
// Usage: b_vect_eval [log ...] (plain-text CARMEN logs; default: the logs of tests/data). --smoke: tests/data only.
// Built with -DRTL_EVAL_BASELINE against older headers (plus PartitionSearch2D.h for the verdict), it measures the
// algorithm before the fix: then split mode is skipped.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "rtl/Segmentation.h"
#include "rtl/Vectorization.h"
#include "rtl/io/CarmenLog.h"
#include "rtl/vect/PartitionSearch2D.h"

namespace
{
    typedef rtl::ApproximationTlsLine2D<float, double> Line;

    struct Counts
    {
        size_t ok = 0, false_feasible = 0, false_infeasible = 0, segments = 0, points = 0, empty = 0;
        double sse = 0, seconds = 0;
    };

    template<class V>
    double totalError(const V &v)
    {
        double s = 0;
        for (const auto &l : v.approximations())
            s += l.errSquaredCompute() * l.count();
        return s;
    }

    template<class V>
    bool run(V &v, const std::vector<rtl::Vector2f> &c, Counts &k, bool feasible)
    {
        const auto t0 = std::chrono::steady_clock::now();
        const bool ok = v(c);
        k.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (ok)
        {
            ++k.ok;
            k.segments += v.approximations().size();
            for (const auto &r : v.indices())   // a point shared by two ranges (split mode's cover) counts twice
                k.points += r.second - r.first;
            k.sse += totalError(v);
        }
        else
        {
            ++k.empty;
            ++(feasible ? k.false_feasible : k.false_infeasible);
        }
        return ok;
    }

    void print(const char *name, const Counts &k, size_t clusters)
    {
        std::printf("  %-14s ok %zu  false %zu (feasible %zu, infeasible %zu)  no-segment share %.4f  segments %zu"
                    "  per cluster %.3f (per non-empty %.3f)  RMS %.5f m  time %.3f s\n",
                    name, k.ok, k.false_feasible + k.false_infeasible, k.false_feasible, k.false_infeasible,
                    static_cast<double>(k.empty) / static_cast<double>(clusters), k.segments,
                    static_cast<double>(k.segments) / static_cast<double>(clusters),
                    k.ok ? static_cast<double>(k.segments) / static_cast<double>(k.ok) : 0.0,
                    k.points ? std::sqrt(k.sse / static_cast<double>(k.points)) : 0.0, k.seconds);
    }
}

int main(int argc, char **argv)
{
    std::vector<std::string> logs;
    for (int i = 1; i < argc; ++i)
        if (std::strncmp(argv[i], "--", 2) != 0)
            logs.emplace_back(argv[i]);
    if (logs.empty())
        for (const char *name : {"intel.log", "csail.log"})
            logs.push_back(std::string(RTL_TEST_DATA_DIR) + "/" + name);

    const float sigma = 0.03f, delta = 0.3f;
    for (const auto &log : logs)
    {
        const auto scans = rtl::readCarmenLogFile<float>(log);
        rtl::CAR_Segmenter<rtl::Vector2f> seg(2, 0.1f, 0.5f);
        rtl::VectorizerFTLSPolyline2D<float, double> ftls;
        rtl::VectorizerAFTLSPolyline2D<float, double> aftls;
        ftls.setSigma(sigma); ftls.setDelta(delta);
        aftls.setSigma(sigma); aftls.setDelta(delta);
#ifndef RTL_EVAL_BASELINE
        rtl::VectorizerFTLSPolyline2D<float, double> ftls_split;
        rtl::VectorizerAFTLSPolyline2D<float, double> aftls_split;
        ftls_split.setSigma(sigma); ftls_split.setDelta(delta); ftls_split.setSplitAtInfeasibleCorners(true);
        aftls_split.setSigma(sigma); aftls_split.setDelta(delta); aftls_split.setSplitAtInfeasibleCorners(true);
        Counts fs, as;
        size_t breaks = 0, multi = 0, shared = 0, covered = 0, no_partition = 0;
        rtl::PartitionSearch2D<rtl::PrecArray2D<float, double>, Line> split_search;
        split_search.setSigma(sigma);
        split_search.setDelta(delta);
        split_search.setAllowBreaks(true);
#endif
        rtl::PrecArray2D<float, double> prec;
        rtl::PartitionSearch2D<rtl::PrecArray2D<float, double>, Line> search;
        search.setSigma(sigma);
        search.setDelta(delta);
        std::vector<Line> lines;
        std::vector<std::pair<size_t, size_t>> idx;

        Counts f, a;
        size_t clusters = 0, points = 0, infeasible = 0, worse = 0, worse_same_count = 0;
        double worst_ratio = 1;
        for (const auto &scan : scans)
        {
            seg.loadData(scan.points);
            while (seg.clustersAvailable() > 0)
            {
                const auto c = seg.grabCluster();
                if (c.size() < 3)
                    continue;
                ++clusters;
                points += c.size();
                prec.precompute(c);
                const bool feasible = search(c, prec, lines, idx);
                infeasible += feasible ? 0 : 1;
                const bool okf = run(ftls, c, f, feasible), oka = run(aftls, c, a, feasible);
                if (okf && oka)
                {
                    const double ef = totalError(ftls), ea = totalError(aftls);
                    if (ea > ef * (1 + 1e-12) + 1e-18)
                    {
                        ++worse;
                        worse_same_count += ftls.indices().size() == aftls.indices().size() ? 1 : 0;
                        if (ef > 0) worst_ratio = std::max(worst_ratio, ea / ef);
                    }
                }
#ifndef RTL_EVAL_BASELINE
                run(ftls_split, c, fs, feasible);
                run(aftls_split, c, as, feasible);
                breaks += ftls_split.breaks().size();
                multi += ftls_split.polylineOffsets().size() > 2 ? 1 : 0;
                // Clusters with no partition into fitting ranges at all: split mode's cover shares points there.
                no_partition += split_search(c, prec, lines, idx) ? 0 : 1;
                size_t k = 0;
                for (size_t i = 1; i < ftls_split.indices().size(); ++i)
                    k += ftls_split.indices()[i].first < ftls_split.indices()[i - 1].second ? 1 : 0;
                shared += k;
                covered += k > 0 ? 1 : 0;
#endif
            }
        }
        std::printf("%s: %zu scans, %zu clusters of >= 3 points (%zu points); CAR step 2, bounds 0.1..0.5; sigma %.2f, delta %.2f\n",
                    log.c_str(), scans.size(), clusters, points, static_cast<double>(sigma), static_cast<double>(delta));
        std::printf("  exact search: %zu clusters have no valid partition (strict)\n", infeasible);
        print("FTLS strict", f, clusters);
        print("AFTLS strict", a, clusters);
        std::printf("  AFTLS > FTLS total squared error: %zu (%zu with the same segment count), worst ratio %.4f\n",
                    worse, worse_same_count, worst_ratio);
#ifndef RTL_EVAL_BASELINE
        print("FTLS split", fs, clusters);
        print("AFTLS split", as, clusters);
        std::printf("  split mode: %zu breaks in %zu clusters (FTLS); %zu clusters have no partition into ranges fitting sigma,"
                    " %zu clusters covered with %zu shared points (FTLS)\n", breaks, multi, no_partition, covered, shared);
#endif
    }
    return 0;
}
