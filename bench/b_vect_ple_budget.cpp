// ScanPolylines2D on the protocol of probabilistic line extraction (PLE, Schaefer et al., IROS 2018): 20 scans of each
// of intel and csail, a budget of J = 10..50 vertices per scan, scored by PLE's ray metric (see bench/ple/README.md),
// beside PLE's and PLE+'s published per-log means. Prints, per log and J: mean RMSE, mean f, mean score, median and
// max time per scan, for the extractor without radial refinement (DP), with it (DP+LM, defaults: J's own plan
// refined) and with the plans of every budget J' <= J refined (DP+LM all, setRefineEveryBudget(true), priced against
// DP+LM in the same run), and for the library's existing pipeline
// (CAR + FTLS split, one sigma per scan) as the baseline; n = scans in the mean (a scan without a hit is left out, as
// PLE does; for the baseline also a scan where no sigma fits J).
//
// Data: the full logs intel-corrected.log.gz and csail-corrected.log.gz from --data=DIR, else $RTL_FULL_DATA_DIR,
// else ../shared/data beside the repository. --smoke: the excerpts in tests/data (the first 30 scans), J = 10 and 50.
#include <algorithm>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "ple/ple_greedy.h"
#include "ple/ple_protocol.h"
#include "rtl/Segmentation.h"
#include "rtl/Vectorization.h"
#include "rtl/vect/ScanPolylines2D.h"

namespace
{
    struct Published { double rmse, f; };
    // PLE's published per-log means (RMSE m / f), J = 10, 20, 30, 40, 50: PLE, then PLE+.
    const Published kIntelPle[5] = {{0.097, 0.861}, {0.063, 0.961}, {0.030, 0.981}, {0.017, 0.986}, {0.010, 0.986}};
    const Published kIntelPlePlus[5] = {{0.070, 0.861}, {0.044, 0.961}, {0.022, 0.981}, {0.013, 0.986}, {0.008, 0.986}};
    const Published kCsailPle[5] = {{0.102, 0.819}, {0.082, 0.905}, {0.064, 0.937}, {0.051, 0.954}, {0.040, 0.965}};
    const Published kCsailPlePlus[5] = {{0.075, 0.819}, {0.062, 0.905}, {0.050, 0.937}, {0.040, 0.954}, {0.032, 0.965}};

    //! CPU time of this thread: the machines here are shared, and wall time per scan would count other processes.
    double threadMicroseconds()
    {
        timespec ts{};
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
        return static_cast<double>(ts.tv_sec) * 1e6 + static_cast<double>(ts.tv_nsec) * 1e-3;
    }

    struct Row
    {
        double rmse = 0, f = 0, score = 0, median_us = 0, max_us = 0;
        std::size_t scored = 0, max_vertices = 0;

        //! One scan's metric into the sums (a scan without a hit is left out of the means, as PLE's).
        void add(const rtl::ple::Metric &m)
        {
            if (m.hit == 0) return;
            ++scored;
            rmse += m.rmse(); f += m.explained(); score += m.score(0.5);
        }
        //! The sums to means, and the median and maximum of the per-scan times.
        Row &finish(std::vector<double> &times)
        {
            if (scored) { rmse /= static_cast<double>(scored); f /= static_cast<double>(scored); score /= static_cast<double>(scored); }
            std::sort(times.begin(), times.end());
            median_us = times.empty() ? 0 : times[times.size() / 2];
            max_us = times.empty() ? 0 : times.back();
            return *this;
        }
    };

    //! Extractor settings chosen on the command line, to measure variants against the defaults (-1: default).
    int g_break_candidates = -1, g_exact_breaks = -1, g_window = -1, g_trim = -1, g_points = -1, g_point_iterations = 20, g_point_window = 2;
    int g_radial = -1, g_short = -1, g_greedy = -1, g_greedy_iterations = 20, g_reassign = 0, g_beam_lm = -1, g_partition_k = -1, g_realloc = -1, g_consistent = 0;
    double g_cost = -1;   // setUnexplainedCost for the extractor (the score printed stays PLE's, c = 0.5)

    //! The extractor with the command line's settings.
    void configure(rtl::ScanPolylines2D<double> &ex, std::size_t J, bool refine, bool every_budget)
    {
        ex.setMaxVertices(J);
        ex.setRefinement(refine);
        ex.setRefineEveryBudget(every_budget);
        if (g_break_candidates >= 0) ex.setBreakCandidates(g_break_candidates);
        if (g_exact_breaks >= 0) ex.setExactBreakCosts(g_exact_breaks > 0);
        if (g_window >= 0) ex.setNeighbourRefinement(static_cast<std::size_t>(g_window));
        if (g_trim >= 0) ex.setEndTrimming(g_trim > 0);
        if (g_points >= 0) ex.setPointCandidates(g_points > 0, g_point_iterations, g_point_window);
        if (g_cost > 0) ex.setUnexplainedCost(g_cost);
        if (g_radial >= 0) ex.setRadialRepartition(static_cast<std::size_t>(g_radial));
        if (g_short >= 0) ex.setShortChainPoints(static_cast<std::size_t>(g_short));
        if (g_realloc >= 0) ex.setRefinedReallocation(g_realloc > 0);
        if (g_partition_k >= 0) ex.setPartitionSegments(static_cast<std::size_t>(g_partition_k));
        if (g_greedy >= 0 || g_consistent > 0 || g_beam_lm >= 0 || g_reassign > 0 || g_greedy_iterations != 20)
            ex.setGreedyCandidates(g_greedy != 0, g_greedy_iterations,
                                                  g_consistent > 0 ? rtl::ScanPolylines2D<double>::GreedyRefinement::Consistent
                                                  : g_reassign > 0 ? rtl::ScanPolylines2D<double>::GreedyRefinement::Reassigning
                                                  : g_beam_lm == 0 ? rtl::ScanPolylines2D<double>::GreedyRefinement::FreeVertices
                                                  : g_beam_lm == 1 ? rtl::ScanPolylines2D<double>::GreedyRefinement::AlongBeams
                                                                   : rtl::ScanPolylines2D<double>::GreedyRefinement::AlongBeamsThenFree);
    }

    Row evaluate(const std::vector<rtl::ple::Scan> &scans, std::size_t J, bool refine, int reps, bool every_budget = false)
    {
        rtl::ScanPolylines2D<double> ex;
        configure(ex, J, refine, every_budget);
        Row row;
        std::vector<double> times;
        for (const auto &scan : scans)
        {
            double best = 1e300;
            for (int r = 0; r < reps; ++r)
            {
                const double t0 = threadMicroseconds();
                ex(scan.points);
                best = std::min(best, threadMicroseconds() - t0);
            }
            times.push_back(best);
            row.max_vertices = std::max(row.max_vertices, ex.vertexCount());
            const rtl::ple::Metric m = rtl::ple::score(scan, ex.polylines());
            row.add(m);
        }
        return row.finish(times);
    }

    //! The library's existing pipeline as the baseline: CAR clusters (consecutive points within PLE's 1 m link
    //! distance), FTLS in split mode (delta = 3 sigma) on every cluster of >= 2 points, one sigma per scan: the
    //! smallest (bisection over log sigma in [1e-4, 10] m, 40 steps) whose polylines have <= J vertices in total.
    std::vector<std::vector<rtl::Vector2d>> baselinePolylines(const rtl::ple::Scan &scan, std::size_t J)
    {
        rtl::CAR_Segmenter<rtl::Vector2d> car(2, 1.0, 1.0);
        car.loadData(scan.points);
        std::vector<std::vector<rtl::Vector2d>> clusters;
        while (car.clustersAvailable() > 0)
        {
            auto c = car.grabCluster();
            if (c.size() >= 2) clusters.push_back(std::move(c));
        }
        rtl::VectorizerFTLSPolyline2D<double, double> ftls;
        ftls.setDelta(3);
        ftls.setSplitAtInfeasibleCorners(true);
        auto run = [&](double sigma, std::vector<std::vector<rtl::Vector2d>> *out) {
            ftls.setSigma(sigma);
            std::size_t vertices = 0;
            for (const auto &c : clusters)
            {
                if (!ftls(c)) continue;
                const auto &v = ftls.vertices();
                const auto &o = ftls.polylineOffsets();
                for (std::size_t p = 0; p + 1 < o.size(); ++p)
                {
                    const std::size_t first = o[p] + p, last = o[p + 1] + p;
                    vertices += last - first + 1;
                    if (out) out->emplace_back(v.begin() + static_cast<long>(first), v.begin() + static_cast<long>(last) + 1);
                }
            }
            return vertices;
        };
        double lo = std::log(1e-4), hi = std::log(10.0);
        if (run(std::exp(hi), nullptr) > J) return {};
        for (int it = 0; it < 40; ++it)
        {
            const double mid = 0.5 * (lo + hi);
            (run(std::exp(mid), nullptr) <= J ? hi : lo) = mid;
        }
        std::vector<std::vector<rtl::Vector2d>> out;
        run(std::exp(hi), &out);
        return out;
    }

    Row evaluateBaseline(const std::vector<rtl::ple::Scan> &scans, std::size_t J)
    {
        Row row;
        std::vector<double> times;
        for (const auto &scan : scans)
        {
            const double t0 = threadMicroseconds();
            const auto polys = baselinePolylines(scan, J);
            times.push_back(threadMicroseconds() - t0);
            std::size_t v = 0;
            for (const auto &p : polys) v += p.size();
            row.max_vertices = std::max(row.max_vertices, v);
            const rtl::ple::Metric m = rtl::ple::score(scan, polys);
            row.add(m);
        }
        return row.finish(times);
    }

    //! PLE replicated (rtl::ple::GreedyExtractor): its greedy removal, and with `refine` our LM on its map (PLE+ ours).
    Row evaluateGreedy(const std::vector<rtl::ple::Scan> &scans, std::size_t J, bool refine, int reps)
    {
        rtl::ple::GreedyExtractor ex;
        ex.setReassignRounds(g_reassign);
        ex.setBeamRangeRefinement(g_beam_lm > 0);   // PLE+ ours: our LM unless --beam-lm=1|2
        ex.setConsistentRounds(g_consistent);
        Row row;
        std::vector<double> times;
        for (const auto &scan : scans)
        {
            double best = 1e300;
            rtl::ple::GreedyExtractor::Map map;
            for (int r = 0; r < reps; ++r)
            {
                const double t0 = threadMicroseconds();
                map = ex(scan, J, refine);
                best = std::min(best, threadMicroseconds() - t0);
            }
            times.push_back(best);
            std::size_t v = 0;
            for (const auto &p : map) v += p.size();
            row.max_vertices = std::max(row.max_vertices, v);
            const rtl::ple::Metric m = rtl::ple::score(scan, map);
            row.add(m);
        }
        return row.finish(times);
    }

    //! The search over the unexplained cost c of rows 6-8: `reaches(c)` runs the extractor with c, keeps its result if
    //! it is the best so far among those that reach the row's target, and says whether it reached it. Tries `grid`
    //! values of c log-spaced over [c_min, c_max] and, between each two neighbours of which one reaches the target
    //! and the other not, 10 bisection steps towards the border: the target (a hit count, a mean f) is not monotone
    //! in c, as the knapsack switches whole polylines, and the least error tends to lie just where the target is met.
    void searchCost(double c_min, double c_max, int grid, const std::function<bool(double)> &reaches)
    {
        const double lo = std::log(c_min), hi = std::log(c_max);
        std::vector<double> log_c(static_cast<std::size_t>(std::max(grid, 1)));
        std::vector<bool> ok(log_c.size());
        for (std::size_t k = 0; k < log_c.size(); ++k)
        {
            log_c[k] = grid > 1 ? lo + (hi - lo) * static_cast<double>(k) / (grid - 1) : hi;
            ok[k] = reaches(std::exp(log_c[k]));
        }
        for (std::size_t k = 0; k + 1 < log_c.size(); ++k)
        {
            if (ok[k] == ok[k + 1]) continue;
            double yes = ok[k] ? log_c[k] : log_c[k + 1], no = ok[k] ? log_c[k + 1] : log_c[k];
            for (int it = 0; it < 10; ++it)
            {
                const double mid = 0.5 * (yes + no);
                (reaches(std::exp(mid)) ? yes : no) = mid;
            }
        }
    }

    //! The extractor (the DP+LM all row's settings) at PLE's own f, scan by scan: per scan, the least RMSE among the
    //! maps of the c searched (`searchCost` over [0.02, 4] m, twice the grid of rows 7 and 8: one scan's
    //! hit count is coarser in c than a mean) that explain at least as many beams as PLE's map of that
    //! scan (PLE+'s refinement keeps PLE's hits); so every scan's f is >= PLE's and PLE+'s, and the row's RMSE is the
    //! error at that f. A scan where no c explains enough keeps the map that explains most. Time: the whole search.
    Row evaluateMatched(const std::vector<rtl::ple::Scan> &scans, std::size_t J, int grid)
    {
        rtl::ple::GreedyExtractor ple;
        rtl::ScanPolylines2D<double> ex;
        configure(ex, J, true, true);
        Row row;
        std::vector<double> times;
        for (const auto &scan : scans)
        {
            const double t0 = threadMicroseconds();
            const std::size_t target = rtl::ple::score(scan, ple(scan, J, false)).hit;
            bool found = false;
            rtl::ple::Metric best{};
            searchCost(0.02, 4.0, grid, [&](double c) {
                ex.setUnexplainedCost(c);
                ex(scan.points);
                row.max_vertices = std::max(row.max_vertices, ex.vertexCount());
                const rtl::ple::Metric m = rtl::ple::score(scan, ex.polylines());
                if (m.hit < target)
                {
                    if (!found && m.hit > best.hit) best = m;   // until one does: the map that explains most
                    return false;
                }
                if (!found || m.rmse() < best.rmse()) best = m;
                found = true;
                return true;
            });
            times.push_back(threadMicroseconds() - t0);
            row.add(best);
        }
        return row.finish(times);
    }

    //! The extractor (the DP+LM all row's settings) with one unexplained cost c for all scans of a log, chosen for a
    //! mean f: the least mean RMSE among the c searched (`searchCost` over [0.05, 2] m) whose mean f is at least
    //! `f_target`. The c found is returned in `c_out` (NaN, with an infinite RMSE, when no c reaches the target).
    Row evaluateAtMeanF(const std::vector<rtl::ple::Scan> &scans, std::size_t J, double f_target, int grid, double &c_out)
    {
        Row best;
        best.rmse = std::numeric_limits<double>::infinity();
        c_out = std::nan("");
        const double command_line_cost = g_cost;
        searchCost(0.05, 2.0, grid, [&](double c) {
            g_cost = c;
            const Row r = evaluate(scans, J, true, 1, true);
            if (r.f < f_target) return false;
            if (r.rmse < best.rmse) { best = r; c_out = c; }
            return true;
        });
        g_cost = command_line_cost;
        return best;
    }

    //! PLE's mean f on these scans (PLE ours, unrounded): what PLE+ explains, as its refinement keeps PLE's hits.
    double pleMeanF(const std::vector<rtl::ple::Scan> &scans, std::size_t J)
    {
        rtl::ple::GreedyExtractor ple;
        Row row;
        std::vector<double> no_times;
        for (const auto &scan : scans) row.add(rtl::ple::score(scan, ple(scan, J, false)));
        return row.finish(no_times).f;
    }

    double plePlusScore(const Published &p) { return p.f * p.rmse * p.rmse + (1 - p.f) * 0.25; }
}

int main(int argc, char **argv)
{
    bool smoke = false, frontier = false;
    int reps = 5, c_grid = 40;
    std::string dir, only_log, methods = "0123";   // --log=NAME and --J=N restrict the run; --methods= the rows (bench/ple/README.md)
    std::size_t only_j = 0;
    std::string dump;   // --dump=DIR: write each scan's beams to DIR/<log>_<line>.f64 (interleaved x, y; NaN: no return) and stop
    if (const char *e = std::getenv("RTL_FULL_DATA_DIR")) dir = e;
    for (int i = 1; i < argc; ++i)
    {
        if (std::strcmp(argv[i], "--smoke") == 0) { smoke = true; reps = 1; }
        else if (std::strncmp(argv[i], "--data=", 7) == 0) dir = argv[i] + 7;
        else if (std::strncmp(argv[i], "--reps=", 7) == 0) reps = std::max(1, std::atoi(argv[i] + 7));
        else if (std::strncmp(argv[i], "--breaks=", 9) == 0) g_break_candidates = std::atoi(argv[i] + 9);
        else if (std::strncmp(argv[i], "--trim=", 7) == 0) g_trim = std::atoi(argv[i] + 7);
        else if (std::strncmp(argv[i], "--window=", 9) == 0) g_window = std::atoi(argv[i] + 9);
        else if (std::strncmp(argv[i], "--points=", 9) == 0) g_points = std::atoi(argv[i] + 9);
        else if (std::strncmp(argv[i], "--point-lm=", 11) == 0) g_point_iterations = std::atoi(argv[i] + 11);
        else if (std::strncmp(argv[i], "--point-window=", 15) == 0) g_point_window = std::atoi(argv[i] + 15);
        else if (std::strcmp(argv[i], "--frontier") == 0) frontier = true;
        else if (std::strncmp(argv[i], "--radial=", 9) == 0) g_radial = std::atoi(argv[i] + 9);
        else if (std::strncmp(argv[i], "--exact-breaks=", 15) == 0) g_exact_breaks = std::atoi(argv[i] + 15);
        else if (std::strncmp(argv[i], "--log=", 6) == 0) only_log = argv[i] + 6;
        else if (std::strncmp(argv[i], "--dump=", 7) == 0) dump = argv[i] + 7;
        else if (std::strncmp(argv[i], "--short=", 8) == 0) g_short = std::atoi(argv[i] + 8);
        else if (std::strncmp(argv[i], "--greedy=", 9) == 0) g_greedy = std::atoi(argv[i] + 9);
        else if (std::strncmp(argv[i], "--greedy-lm=", 12) == 0) g_greedy_iterations = std::atoi(argv[i] + 12);
        else if (std::strncmp(argv[i], "--reassign=", 11) == 0) g_reassign = std::atoi(argv[i] + 11);
        else if (std::strncmp(argv[i], "--beam-lm=", 10) == 0) g_beam_lm = std::atoi(argv[i] + 10);
        else if (std::strncmp(argv[i], "--consistent=", 13) == 0) g_consistent = std::atoi(argv[i] + 13);
        else if (std::strncmp(argv[i], "--partition-k=", 14) == 0) g_partition_k = std::atoi(argv[i] + 14);
        else if (std::strncmp(argv[i], "--realloc=", 10) == 0) g_realloc = std::atoi(argv[i] + 10);
        else if (std::strncmp(argv[i], "--J=", 4) == 0) only_j = static_cast<std::size_t>(std::atoi(argv[i] + 4));
        else if (std::strncmp(argv[i], "--methods=", 10) == 0) methods = argv[i] + 10;
        else if (std::strncmp(argv[i], "--cost=", 7) == 0) g_cost = std::atof(argv[i] + 7);
        else if (std::strncmp(argv[i], "--c-grid=", 9) == 0) c_grid = std::max(1, std::atoi(argv[i] + 9));
        else { std::fprintf(stderr, "unknown argument %s\n", argv[i]); return 2; }
    }
    if (dir.empty()) dir = std::string(RTL_TEST_DATA_DIR) + "/../../../shared/data";

    struct LogCase { const char *name; const char *full; const char *excerpt; std::vector<std::size_t> lines; const Published *ple, *plus; };
    const LogCase cases[] = {
        {"intel", "intel-corrected.log.gz", "intel.log", {633, 653, 385, 636, 30, 555, 881, 62, 96, 242, 82, 295, 708, 581, 483, 595, 746, 139, 290, 370},
         kIntelPle, kIntelPlePlus},
        {"csail", "csail-corrected.log.gz", "csail.log", {142, 55, 331, 59, 73, 58, 105, 369, 252, 324, 352, 34, 107, 235, 223, 1, 346, 314, 162, 175},
         kCsailPle, kCsailPlePlus},
    };
    std::printf("PLE protocol: mean over scans with a hit of ray RMSE (m), f, score = f RMSE^2 + (1 - f) 0.5^2; CPU time per scan"
                " (thread CPU time, min of %d runs), median / max over the scans\n", reps);
    std::printf("%-6s %3s %-10s %3s %8s %7s %9s %9s %9s %6s | %-14s %-14s %9s\n", "log", "J", "method", "n", "RMSE", "f", "score",
                "med us", "max us", "maxV", "PLE", "PLE+", "PLE+score");
    for (const auto &c : cases)
    {
        if (!only_log.empty() && only_log != c.name) continue;
        std::vector<rtl::ple::Scan> scans;
        try
        {
            if (smoke)
            {
                const rtl::ple::Log log = rtl::ple::readLog(std::string(RTL_TEST_DATA_DIR) + "/" + c.excerpt, false);
                scans = log.scans;
            }
            else
            {
                const rtl::ple::Log log = rtl::ple::readLog(dir + "/" + c.full, true);
                for (std::size_t l : c.lines)
                {
                    if (l >= log.scans.size()) throw std::runtime_error("scan index out of range");
                    scans.push_back(log.scans[l]);
                }
            }
        }
        catch (const std::exception &e)
        {
            std::fprintf(stderr, "%s: %s (give --data=DIR or RTL_FULL_DATA_DIR)\n", c.name, e.what());
            return 1;
        }
        if (!dump.empty())
        {
            for (std::size_t q = 0; q < scans.size(); ++q)
            {
                const std::string file = dump + "/" + c.name + "_" + std::to_string(smoke ? q : c.lines[q]) + ".f64";
                std::ofstream out(file, std::ios::binary);
                for (const auto &p : scans[q].points)
                {
                    const double xy[2] = {p[0], p[1]};
                    out.write(reinterpret_cast<const char *>(xy), sizeof xy);
                }
                if (!out) { std::fprintf(stderr, "cannot write %s\n", file.c_str()); return 1; }
            }
            std::printf("%s: %zu scans written to %s\n", c.name, scans.size(), dump.c_str());
            continue;
        }
        if (frontier)
        {
            // The (RMSE, f) trade-off of DP+LM over the unexplained cost c the extractor optimises (scored with PLE's
            // c = 0.5 all the same), and where PLE+'s point lies against it: our RMSE at PLE+'s f, interpolated
            // linearly in f between the neighbouring c (NaN when PLE+'s f is outside our range).
            for (std::size_t J = 10, j = 0; J <= 50; J += smoke ? 40 : 10, j += smoke ? 4 : 1)
            {
                std::vector<std::pair<double, double>> curve;   // (f, RMSE)
                for (double cost : {0.2, 0.3, 0.4, 0.5})
                {
                    g_cost = cost;
                    const Row r = evaluate(scans, J, true, reps);
                    curve.push_back({r.f, r.rmse});
                    std::printf("%-6s %3zu c=%.1f      %3zu %8.4f %7.4f %9.5f %9.1f %9.1f %6zu | %.3f / %.3f  %.3f / %.3f  %9.5f\n", c.name, J, cost,
                                r.scored, r.rmse, r.f, r.score, r.median_us, r.max_us, r.max_vertices, c.ple[j].rmse, c.ple[j].f,
                                c.plus[j].rmse, c.plus[j].f, plePlusScore(c.plus[j]));
                }
                g_cost = -1;
                std::sort(curve.begin(), curve.end());
                double at = std::nan("");
                const double fp = c.plus[j].f;
                for (std::size_t q = 0; q + 1 < curve.size(); ++q)
                    if (curve[q].first <= fp && fp <= curve[q + 1].first)
                    {
                        const double span = curve[q + 1].first - curve[q].first;
                        const double t = span > 0 ? (fp - curve[q].first) / span : 0.0;
                        at = curve[q].second + t * (curve[q + 1].second - curve[q].second);
                        break;
                    }
                std::printf("%-6s %3zu frontier: at PLE+'s f = %.3f our RMSE %.4f against PLE+'s %.3f: %s\n", c.name, J, fp, at,
                            c.plus[j].rmse, std::isnan(at) ? "f outside our range" : at <= c.plus[j].rmse ? "PLE+ dominated" : "PLE+ ahead");
            }
            continue;
        }
        for (std::size_t J = 10, j = 0; J <= 50; J += smoke ? 40 : 10, j += smoke ? 4 : 1)
            for (int method = 0; method < 9; ++method)
            {
                if ((only_j && J != only_j) || methods.find(static_cast<char>('0' + method)) == std::string::npos) continue;
                double c_found = std::nan(""), f_target = method == 8 ? pleMeanF(scans, J) : c.plus[j].f;
                const Row r = method == 0 ? evaluateBaseline(scans, J)
                              : method >= 7 ? evaluateAtMeanF(scans, J, f_target, c_grid, c_found)
                              : method == 6 ? evaluateMatched(scans, J, 2 * c_grid)
                              : method >= 4 ? evaluateGreedy(scans, J, method == 5, reps)
                                            : evaluate(scans, J, method >= 2, reps, method == 3);
                if (method >= 7 && std::isnan(c_found))
                {
                    std::printf("%-6s %3zu %-10s   no c in [0.05, 2] m reaches f >= %.4f\n", c.name, J, method == 7 ? "c for PLE+ f" : "c for PLE f", f_target);
                    continue;
                }
                if (r.max_vertices > J || (method > 0 && r.scored == 0)) { std::fprintf(stderr, "budget exceeded or nothing scored\n"); return 1; }
                char note[64] = "";
                if (method >= 7) std::snprintf(note, sizeof note, "  c = %.3f for f >= %.4f", c_found, f_target);
                std::printf("%-6s %3zu %-10s %3zu %8.5f %7.5f %9.5f %9.1f %9.1f %6zu | %.3f / %.3f  %.3f / %.3f  %9.5f%s\n", c.name, J,
                            method == 0 ? "CAR+FTLS" : method == 2 ? "DP+LM" : method == 3 ? "DP+LM all" : method == 4 ? "PLE ours" : method == 5 ? "PLE+ ours" : method == 6 ? "at PLE's f" : method == 7 ? "c for PLE+ f" : method == 8 ? "c for PLE f" : "DP", r.scored, r.rmse, r.f, r.score, r.median_us, r.max_us, r.max_vertices,
                            c.ple[j].rmse, c.ple[j].f, c.plus[j].rmse, c.plus[j].f, plePlusScore(c.plus[j]), note);
            }
    }
    return 0;
}
