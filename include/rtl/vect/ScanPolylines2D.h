// Whole-scan polyline extraction at a vertex budget: the line map of one 2D range scan that best explains the scan's
// beams with at most J vertices in total.
//
// Model. The sensor sits at the origin; beam i has direction u_i and measured range r_i. A segment hits a beam whose
// direction lies within the segment's angular span (widened by kSpanWiden on each side) and predicts r-hat_i = the
// distance along the beam to the segment's line; where several segments hit a beam, the later one (polyline after
// polyline, segment after segment) counts. The scan's score is the mean over the returned beams of
//   (r_i - r-hat_i)^2   for a hit beam,      c^2 (the unexplained cost squared)   for a beam no segment hits,
// i.e. f * RMSE^2 + (1 - f) * c^2 with f the hit fraction: a negative log-likelihood with Gaussian radial noise and a
// uniform outlier level, the measure of probabilistic line extraction (Schaefer et al., IROS 2018).
//
// Method (each step exact for its own model, in this order):
//  1. chains: the returned beams split at every beam without a return and wherever neighbouring points lie more
//     than maxGap apart (such beams never share a polyline);
//  2. per chain, the exact best partition into k total-least-squares ranges (>= 2 beams each) for every k up to
//     setPartitionSegments() (default 10), by dynamic programming over prefix sums (scan_polylines/ChainPartition.h);
//     each partition becomes polylines: end vertices
//     where the end lines cross their own end beams, inner vertices where consecutive lines cross, unless the lines
//     are near parallel or cross far from the boundary points (then the polyline breaks there, both new ends again
//     on their own beams) -- so a corner never spikes away from its points; optionally, besides each partition, up to
//     setBreakCandidates() variants in which the corners whose break would explain their boundary beams best become
//     breaks (one vertex each; at a depth step inside a chain a corner predicts one side's boundary beams by the other
//     side's line), priced by the partition's cost minus those local gains (only the boundary beams change line);
//     a second family, polylines whose vertices are measured points, the optimal polygonal approximation per k
//     (scan_polylines/PointPolylines.h), for chains of at most setShortChainPoints() beams (default 32: clutter
//     clusters, whose points a 2-beam-per-range partition cannot all reach), optionally (setPointCandidates) for all
//     chains, radially refined; they never break; a third family (setGreedyCandidates, default on), the states of
//     greedy vertex removal by the radial error from the polyline through all the chain's points
//     (scan_polylines/GreedyPolylines.h), the candidates probabilistic line extraction builds: the radial error is
//     what the score measures, and on long chains these beat the orthogonal TLS partitions where beams graze a wall;
//  3. the budget: every chain's candidates (vertex count, score contribution), plus leaving the chain out (all its
//     beams unexplained), allocated exactly under J by a multiple-choice knapsack (scan_polylines/BudgetAllocation.h)
//     (optionally once more after refining the candidates near each chain's choice, setNeighbourRefinement; optionally
//     each chosen partition's boundaries then moved within a few beams by the ranges' own radial errors,
//     setRadialRepartition);
//  4. radial refinement: Levenberg-Marquardt on each chosen polyline's vertices, minimising the radial error of the
//     beams it explains (scan_polylines/RadialRefinement.h); a refined scan whose score is not lower is discarded,
//     so refinement never raises the score. The plans of every budget J' <= J are refined and the best returned, so
//     that the score never rises with J (setRefineEveryBudget, default on; off refines J's own plan only); where
//     the best plan's whole map scores clearly worse than its chain costs say (a refined segment over another chain's
//     beams), the earlier improving plans are hit-tested in turn; then (setRefinedReallocation, default on) the plans
//     of every budget are walked again on the refined chain costs, their new candidates refined in turn.
// Complexity per scan of n beams in chains of n_c: O(sum n_c^2 (1 + K_c)) for the partitions (K_c = min(J - 1,
// n_c / 2, setPartitionSegments())), O(n_c log n_c) plus the recomputed segments' lengths for the greedy family, O(chains x J x K) for the budget, O(n x segments) for the final hit test; with setRefineEveryBudget,
// O(chains x J) more for the plans' backtracks and one refinement per distinct (chain, candidate) of the plans.
//
// Input: the scan's beams in beam order as points in the sensor frame; a beam with a non-finite coordinate, or at the
// origin, has no return. The beams' directions must turn one way (increasing or decreasing angle), as a rotating
// scanner's do. Bad parameters are rejected by the setters with std::invalid_argument.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "rtl/core/VectorND.h"
#include "rtl/vect/scan_polylines/BeamRangeRefinement.h"
#include "rtl/vect/scan_polylines/BudgetAllocation.h"
#include "rtl/vect/scan_polylines/ChainPartition.h"
#include "rtl/vect/scan_polylines/GreedyPolylines.h"
#include "rtl/vect/scan_polylines/PointPolylines.h"
#include "rtl/vect/scan_polylines/RadialRefinement.h"
#include "rtl/vect/scan_polylines/RayGeometry.h"
#include "rtl/vect/scan_polylines/ReassigningRefinement.h"

namespace rtl
{
    template<typename T>
    class ScanPolylines2D
    {
        static_assert(std::is_floating_point_v<T>, "ScanPolylines2D<T>: T is float or double");
    public:
        typedef T ElementType;
        typedef VectorND<2, T> VectorType;
        typedef std::pair<std::size_t, std::size_t> BeamRange;

        //! Half-width (radians) by which a segment's angular span is widened for the hit test.
        static constexpr double kSpanWiden = 1e-3;

        //! One segment of the result: its polyline, the beams it was fitted to, and its line in Hesse normal form
        //! x cos(theta) + y sin(theta) = r (r >= 0) with the 2x2 covariance of (r, theta) (order r, theta): symmetric,
        //! positive diagonal, never NaN; infinite variances and no correlation where the beams' points do not spread
        //! along the line (as far as a double resolves); computed in double, so an entry beyond the element type's
        //! range is infinite (the variance of theta grows as the noise over the segment's length squared: in float, a
        //! segment whose beams' points lie within ~1e-20 m of each other) and one below it 0.
        struct Segment
        {
            std::size_t polyline = 0;
            BeamRange beams{0, 0};              //!< first and last beam (inclusive) assigned to the segment
            T r{}, theta{};
            Eigen::Matrix<T, 2, 2> covariance = Eigen::Matrix<T, 2, 2>::Zero();
        };

        //! How a chosen candidate of the greedy family (setGreedyCandidates) is refined: inner vertices moved freely with
        //! each beam kept on its first segment (RadialRefinement), the same in single iterations with the beams
        //! re-assigned by the hit test after each (scan_polylines/ReassigningRefinement.h), or every vertex moved along
        //! its own beam (scan_polylines/BeamRangeRefinement.h: the beams each segment explains never change, so the
        //! cost minimised is the hit-tested one).
        //! AlongBeamsThenFree: along the beams, then one free iteration (each kept only where it lowers the cost).
        //! Consistent: inner vertices free but kept in their boundary beams' wedges, so the LM minimises the hit-tested
        //! cost, and boundaries shifted where a vertex rests on a wedge edge (RadialRefinement::refineConsistent, with
        //! `iterations` LM iterations and 3 passes of shifts).
        enum class GreedyRefinement { FreeVertices = 0, Reassigning = 1, AlongBeams = 2, AlongBeamsThenFree = 3, Consistent = 4 };

        //! Vertices over the whole scan (>= 2; default 50). std::invalid_argument below 2.
        void setMaxVertices(std::size_t j)
        {
            if (j < 2) throw std::invalid_argument("ScanPolylines2D::setMaxVertices: J must be >= 2");
            max_vertices_ = j;
        }
        //! Neighbouring beams farther apart than this (metres) never share a polyline (default 1). Finite and > 0,
        //! else std::invalid_argument.
        void setMaxGap(T m) { max_gap_ = checkedPositive(m, "ScanPolylines2D::setMaxGap"); }
        //! The radial error (metres) at which a beam is as well left unexplained (default 0.5). Finite and > 0, else
        //! std::invalid_argument.
        void setUnexplainedCost(T c) { cost_ = checkedPositive(c, "ScanPolylines2D::setUnexplainedCost"); }
        //! Partition ranges costed by radially weighted TLS, or plain TLS (default).
        void setRadialWeights(bool on) { radial_weights_ = on; }
        //! Iterations of radial refinement applied to every candidate before the budget is allocated (default 0).
        void setCandidateRefinement(int iterations) { refine_candidates_ = iterations; }
        //! Extra candidates per partition in which up to this many corners become breaks (one vertex each), the corners
        //! whose break explains their boundary beams best first (default 0: none; with the greedy family on they changed
        //! the benchmark's means by under 3 %, and the greedy family covers what they were for: depth steps in a chain).
        void setBreakCandidates(int n) { break_rounds_ = n; }
        //! Break candidates scored by their own hit test (true) or by the partition's cost minus the local gains
        //! (false, default; cheaper).
        void setExactBreakCosts(bool on) { exact_breaks_ = on; }
        //! Before the final allocation, candidates within this many vertices of each chain's first choice are refined
        //! and the budget allocated again on their refined costs (default 0: off).
        void setNeighbourRefinement(std::size_t window) { neighbour_window_ = window; }
        //! Partitions may leave a chain's end beams out (each at the unexplained cost squared) when a line fits them
        //! worse: clutter and curved ends at no vertex (true), or every partition spans its whole chain (false, default).
        void setEndTrimming(bool on) { trim_ends_ = on; }
        //! A second candidate family per chain (default off): for every k, the polyline through k + 1 of the chain's
        //! measured points with the least squared orthogonal distances of the points between its vertices
        //! (scan_polylines/PointPolylines.h), offered to the budget beside the TLS partitions; its vertices lie on their
        //! own beams, so it never breaks. With `window` >= 0, the family is built after a first allocation of the TLS
        //! candidates, for each chain only up to `window` vertices beyond its choice there, and the budget allocated
        //! again; with `window` < 0, in full before the only allocation. With refinement on, the polylines within
        //! `window` vertices of the first choice (all, when `window` < 0) are refined radially (at most `iterations`
        //! LM iterations; 0: none) before they are offered.
        void setPointCandidates(bool on, int iterations = 20, int window = 2)
        {
            point_candidates_ = on; point_iterations_ = iterations; point_window_ = window;
        }
        //! Chains of at most this many beams also offer the point-vertex family (see setPointCandidates; built in full
        //! before the allocation, not refined until a plan chooses them; O(n^3) per such chain at most). A TLS range
        //! needs two beams, so a chain of n beams has at most n / 2 ranges: a 3-beam clutter cluster whose middle
        //! point is off its line can only be one segment, while the polyline through its 3 points explains it exactly
        //! (default 32; 0: off).
        void setShortChainPoints(std::size_t maxBeams) { short_points_ = maxBeams; }
        //! A third candidate family per chain (default on, 20 iterations, AlongBeamsThenFree): the states of greedy vertex
        //! removal by the radial error
        //! (scan_polylines/GreedyPolylines.h: from the polyline through all the chain's points, the vertex whose removal
        //! raises the chain's hit-tested cost least goes first, as probabilistic line extraction builds its map), each
        //! state of at most maxVertices() vertices offered with its chain cost, beside the TLS partitions;
        //! its vertices are measured points on their own beams, so it never breaks. Built in full before the only
        //! allocation (so plans of every budget stay comparable) and refined only when a plan chooses it. O(n log n)
        //! plus the recomputed segments' lengths per chain of n beams, O(n) per offered state.
        //! `iterations`: at most this many LM iterations (or rounds) when a plan of the every-budget refinement chooses
        //! one; `refinement`: how (see GreedyRefinement). With the free-vertex LM, 1 iteration scored better on the
        //! benchmark than 2, 3 and 20 (the fixed beam assignment drifts from the hit test); AlongBeamsThenFree with 20
        //! scored best at the least time; Consistent scores 0-2 % better again at 1.5-2x the time. (With
        //! setRefineEveryBudget(false), J's own plan is refined by the free LM as before.)
        void setGreedyCandidates(bool on, int iterations = 20, GreedyRefinement refinement = GreedyRefinement::AlongBeamsThenFree)
        {
            greedy_candidates_ = on; greedy_iterations_ = iterations; greedy_refinement_ = refinement;
        }
        //! The TLS partition family only up to this many ranges per chain (default 10; 0: up to maxVertices() - 1). With
        //! the greedy family on, the partitions matter for few-segment chains only: on the benchmark, a cap of 10 left
        //! every mean unchanged to 4 digits and took a third off the time (the partition DP is O(n^2 K) per chain).
        void setPartitionSegments(std::size_t k) { partition_segments_ = k; }
        //! With the every-budget refinement: a second walk over the plans of every budget, allocated on the refined
        //! chain costs of the candidates the first walk refined (the offered costs elsewhere), its new candidates
        //! refined in turn (default on).
        void setRefinedReallocation(bool on) { refined_reallocation_ = on; }
        //! After the allocation, each chain's chosen TLS partition is re-partitioned with every range boundary moved by
        //! at most `window` beams, minimising the sum over ranges of the squared radial errors of the range's own TLS
        //! line (exact within the window, O(n (2 window + 1)^2) per chain); kept when its polylines need no more
        //! vertices and score lower on the chain's beams (default 0: off).
        void setRadialRepartition(std::size_t window) { radial_window_ = window; }
        //! Radial refinement on (default) or off.
        void setRefinement(bool on) { refine_ = on; }
        //! With refinement on: refine the knapsack's optimal plan of every budget J' <= J (true, default; each distinct
        //! (chain, candidate) once: consecutive plans differ in one or two chains, so typically O(chains + J) candidate
        //! refinements instead of one per chosen chain) and return the plan whose refined chain costs sum least, or
        //! only the plan of J itself (false: faster, but refinement gains differ between plans, so a larger J can then
        //! return a worse map than a smaller one although a plan within J' is within J). With true it never does,
        //! up to the slight interactions between chains at their borders, which the chain costs leave out, as long as
        //! the candidates do not depend on J's first allocation (point candidates with `window` >= 0 and neighbour
        //! refinement do; radial re-partition does not).
        void setRefineEveryBudget(bool on) { every_budget_ = on; }
        //! Lower bound (metres) of the per-point noise used for the segment covariances (default 0.01). Finite and > 0.
        void setPointSigma(T s) { point_sigma_ = checkedPositive(s, "ScanPolylines2D::setPointSigma"); }

        [[nodiscard]] std::size_t maxVertices() const { return max_vertices_; }
        [[nodiscard]] T maxGap() const { return static_cast<T>(max_gap_); }
        [[nodiscard]] T unexplainedCost() const { return static_cast<T>(cost_); }

        //! Extracts the polylines of one scan. Returns false, with no polylines, all expected ranges NaN and the score
        //! NaN, when no beam has a return (this includes empty input); true otherwise.
        bool operator()(const std::vector<VectorType> &beams)
        {
            clear(beams.size());
            loadBeams(beams);
            if (returned_count_ == 0) return false;
            findChains();
            std::vector<std::vector<scan_polylines::BudgetOption>> options(chains_.size());
            if (candidates_.size() < chains_.size()) candidates_.resize(chains_.size());   // kept: their memory is reused
            candidate_count_.assign(chains_.size(), 0);
            for (std::size_t c = 0; c < chains_.size(); ++c) buildCandidates(c, options[c]);
            std::vector<std::size_t> chosen = scan_polylines::allocateBudget(options, max_vertices_);
            if (point_candidates_ && point_window_ >= 0 && !chosen.empty())
            {
                // The point-vertex family near each chain's first choice (up to `window` vertices more), refined within
                // `window` of it, then the budget allocated again with them.
                const std::size_t w = static_cast<std::size_t>(point_window_);
                for (std::size_t c = 0; c < chains_.size(); ++c)
                {
                    const std::size_t v0 = options[c][chosen[c]].vertices;
                    if (v0 + w >= 2) buildPointCandidates(c, options[c], v0 + w - 1, v0 > w ? v0 - w : 0, v0 + w);
                }
                chosen = scan_polylines::allocateBudget(options, max_vertices_);
            }
            if (refine_ && neighbour_window_ > 0 && !chosen.empty())
            {
                // Refine the candidates near each chain's choice, then allocate again on their refined costs.
                for (std::size_t c = 0; c < chains_.size(); ++c)
                {
                    const std::size_t v0 = options[c][chosen[c]].vertices;
                    for (std::size_t o = 1; o < options[c].size(); ++o)
                    {
                        const std::size_t v = options[c][o].vertices;
                        if (v + neighbour_window_ < v0 || v > v0 + neighbour_window_) continue;
                        options[c][o].cost = refineCandidate(c, o - 1, 20, options[c][o].cost);
                    }
                }
                chosen = scan_polylines::allocateBudget(options, max_vertices_);
            }
            if (refine_ && every_budget_ && !chosen.empty())
            {
                refineEveryBudget(options, chosen);
                return true;
            }
            if (radial_window_ > 0)
                for (std::size_t c = 0; c < chains_.size() && !chosen.empty(); ++c)
                    if (chosen[c] > 0) radialRepartition(c, candidates_[c][chosen[c] - 1], options[c][chosen[c]].cost);
            std::vector<Polyline> map;
            for (std::size_t c = 0; c < chains_.size() && !chosen.empty(); ++c)
                if (chosen[c] > 0)
                {
                    const Candidate &cand = candidates_[c][chosen[c] - 1];
                    map.insert(map.end(), cand.polylines.begin(), cand.polylines.begin() + static_cast<long>(cand.used));
                }
            std::vector<double> rhat = expected(map);
            scan_polylines::RayScore score = scan_polylines::scoreExpected(range_, returned_, rhat);
            if (refine_ && !map.empty())
            {
                // Each chosen candidate refined as the every-budget refinement refines it (its family's refiner), so
                // that J's own plan refined is one of the maps that refinement compares.
                std::vector<Polyline> refined;
                for (std::size_t c = 0; c < chains_.size(); ++c)
                    if (chosen[c] > 0)
                    {
                        const std::size_t o = chosen[c];
                        const Candidate &cand = candidates_[c][o - 1];
                        const double before = cand.stale_cost ? chainCost(cand, chains_[c].first, chains_[c].second) : options[c][o].cost;
                        refineCandidate(c, o - 1, cand.iterations, before);
                        const Candidate &now = candidates_[c][o - 1];
                        refined.insert(refined.end(), now.polylines.begin(), now.polylines.begin() + static_cast<long>(now.used));
                    }
                std::vector<double> rhat2 = expected(refined);
                const scan_polylines::RayScore score2 = scan_polylines::scoreExpected(range_, returned_, rhat2);
                if (score2.score(cost_) < score.score(cost_)) { map.swap(refined); rhat.swap(rhat2); score = score2; }
            }
            publish(map, rhat, score);
            return true;
        }

        //! Vertex lists of the polylines (each >= 2 vertices), in beam order.
        [[nodiscard]] const std::vector<std::vector<VectorType>> &polylines() const { return polylines_; }
        //! r-hat of every input beam (NaN where no segment hits it, and for beams without a return).
        [[nodiscard]] const std::vector<T> &expectedRanges() const { return expected_; }
        //! Every segment, polyline after polyline.
        [[nodiscard]] const std::vector<Segment> &segments() const { return segments_; }
        //! Total vertices of polylines() (<= maxVertices()).
        [[nodiscard]] std::size_t vertexCount() const { return vertex_count_; }
        [[nodiscard]] std::size_t returnedBeams() const { return score_.returned; }
        [[nodiscard]] std::size_t explainedBeams() const { return score_.hit; }
        //! Mean per returned beam of the squared radial error or the unexplained cost squared (see the file comment).
        [[nodiscard]] double score() const { return score_.score(cost_); }
        //! Root mean square radial error over the explained beams (NaN when none).
        [[nodiscard]] double rmse() const { return score_.rmse(); }
        //! Explained beams / returned beams (NaN when none is returned).
        [[nodiscard]] double explainedFraction() const { return score_.explained(); }

    private:
        struct Polyline
        {
            std::vector<double> x, y;           // vertices
            std::vector<BeamRange> segs;        // beams of each segment (scan indices)
        };
        //! The polylines of one partition of a chain; polylines[0, used) are valid (the rest keep their memory for the
        //! next call, so that building candidates does not allocate once the buffers have grown).
        struct Candidate
        {
            std::vector<Polyline> polylines;
            std::size_t used = 0;
            bool partition = false;             // a plain TLS partition (no forced breaks) of `ranges`
            bool stale_cost = false;            // its offered cost is an estimate, or from before a re-partition
            int iterations = 20;                // LM iterations when a plan of the every-budget refinement chooses it
            int refiner = 0;                    // 0: RadialRefinement; 1: re-assigning rounds; 2: along the vertices' beams;
                                                // 3: 2, then one iteration of 0
            std::vector<BeamRange> ranges;      // its ranges, chain-local

            Polyline &next()
            {
                if (used == polylines.size()) polylines.emplace_back();
                Polyline &p = polylines[used++];
                p.x.clear(); p.y.clear(); p.segs.clear();
                return p;
            }
        };

        static double checkedPositive(T v, const char *what)
        {
            const double d = static_cast<double>(v);
            if (!(d > 0) || !std::isfinite(d)) throw std::invalid_argument(std::string(what) + ": must be finite and > 0");
            return d;
        }

        void clear(std::size_t n)
        {
            polylines_.clear(); segments_.clear(); chains_.clear();
            expected_.assign(n, std::numeric_limits<T>::quiet_NaN());
            score_ = {};
            vertex_count_ = 0;
        }

        void loadBeams(const std::vector<VectorType> &beams)
        {
            const std::size_t n = beams.size();
            px_.assign(n, 0); py_.assign(n, 0); ux_.assign(n, 0); uy_.assign(n, 0); range_.assign(n, 0);
            angle_.assign(n, scan_polylines::kNaN); returned_.assign(n, false);
            cos_angle_.assign(n, scan_polylines::kNaN); sin_angle_.assign(n, scan_polylines::kNaN);
            returned_count_ = 0;
            for (std::size_t i = 0; i < n; ++i)
            {
                const double x = static_cast<double>(beams[i][0]), y = static_cast<double>(beams[i][1]);
                const double r = std::hypot(x, y);
                if (!std::isfinite(r) || !(r > 0)) continue;
                px_[i] = x; py_[i] = y; range_[i] = r; ux_[i] = x / r; uy_[i] = y / r;
                angle_[i] = std::atan2(y, x);
                cos_angle_[i] = std::cos(angle_[i]); sin_angle_[i] = std::sin(angle_[i]);
                returned_[i] = true;
                ++returned_count_;
            }
        }

        void findChains()
        {
            const std::size_t n = px_.size();
            std::size_t i = 0;
            while (i < n)
            {
                if (!returned_[i]) { ++i; continue; }
                std::size_t j = i;
                while (j + 1 < n && returned_[j + 1] && scan_polylines::withinDistance(px_[j + 1] - px_[j], py_[j + 1] - py_[j], max_gap_)) ++j;
                chains_.push_back({i, j});
                i = j + 1;
            }
        }

        //! The point where line `f` crosses beam i when that lies within the unexplained cost of the measured range;
        //! else the measured point (an end vertex always lies on its own beam).
        void endOnBeam(const scan_polylines::TlsFit &f, std::size_t i, double &x, double &y) const
        {
            const double t = f.d / (f.nx * ux_[i] + f.ny * uy_[i]);
            const double r = (std::isfinite(t) && t > 0 && std::abs(t - range_[i]) <= cost_) ? t : range_[i];
            x = r * ux_[i]; y = r * uy_[i];
        }

        //! The angular span from beam a's direction to beam b's (both returned): AngularSpan::of their points, from
        //! the directions computed once per scan (the same atan2 of the same coordinates, so the same numbers).
        scan_polylines::AngularSpan wedge(std::size_t a, std::size_t b) const
        {
            scan_polylines::AngularSpan s;
            s.start = angle_[a];
            s.width = scan_polylines::wrapAngle(angle_[b] - angle_[a]);
            return s;
        }

        //! Whether the direction of (x, y) lies in wedge(a, b), by cross products (scan_polylines::DirectionSpan: the
        //! same test up to rounding, without an atan2 per corner); a wedge wider than pi / 2 by wedge() itself.
        bool inWedge(std::size_t a, std::size_t b, double x, double y) const
        {
            static const scan_polylines::Widening none(0.0);
            const auto span = scan_polylines::DirectionSpan::of(ux_[a], uy_[a], ux_[b], uy_[b], none);
            const double c2 = x * x + y * y;
            if (span.by_angle || !(c2 > scan_polylines::kPlainSquaredMin && c2 < scan_polylines::kPlainSquaredMax))
                return wedge(a, b).contains(std::atan2(y, x), 0);
            return span.contains(x, y, 0.0, none);
        }

        //! Crossing of lines f and g when it is well defined and within `reach` of both boundary points a and b.
        static bool corner(const scan_polylines::TlsFit &f, const scan_polylines::TlsFit &g, double ax, double ay, double bx, double by,
                           double reach, double &x, double &y)
        {
            const double det = f.nx * g.ny - f.ny * g.nx;
            if (std::abs(det) < 1e-6) return false;
            x = (f.d * g.ny - g.d * f.ny) / det;
            y = (f.nx * g.d - g.nx * f.d) / det;
            return scan_polylines::withinDistance(x - ax, y - ay, reach) && scan_polylines::withinDistance(x - bx, y - by, reach);
        }

        void buildCandidates(std::size_t c, std::vector<scan_polylines::BudgetOption> &opts)
        {
            const auto [cf, cl] = chains_[c];
            const std::size_t n = cl - cf + 1;
            opts.push_back({0, static_cast<double>(n) * cost_ * cost_});
            if (n < 2) return;
            radialWeights(cf, cl);
            part_.load(&px_[cf], &py_[cf], n, radial_weights_ ? weight_.data() : nullptr);
            part_.setEndSkipCost(trim_ends_ ? cost_ * cost_ : 0.0);
            part_.solve(partition_segments_ > 0 ? std::min(max_vertices_ - 1, partition_segments_) : max_vertices_ - 1);
            std::vector<scan_polylines::TlsFit> &fits = fits_;
            std::vector<BeamRange> &ranges = ranges_;
            for (std::size_t k = 1; k <= part_.maxSegments(); ++k)
            {
                part_.ranges(k, ranges);
                fits.clear();
                for (const auto &r : ranges) fits.push_back(part_.fit(r.first, r.second));
                forced_.assign(k, 0);
                Candidate &plain = newCandidate(c);
                const std::size_t vertices = assemble(c, plain, &corners_);
                if (vertices > max_vertices_) continue;
                plain.partition = true;
                plain.ranges = ranges;
                const double base = offerCandidate(c, vertices, opts, scan_polylines::kNaN);
                if (break_rounds_ == 0 || corners_.empty()) continue;
                // Corners whose break would explain the boundary beams better, best first: each conversion costs one
                // vertex, and the knapsack decides whether it is worth it (a corner at a depth step predicts one
                // side's boundary beams by the other side's line).
                std::sort(corners_.begin(), corners_.end(), [](const auto &u, const auto &v) { return u.second > v.second; });
                // Their cost is the partition's minus the local gains (a break changes only which line predicts the
                // boundary beams), so they need no hit test of their own; the chosen map is hit-tested in full.
                double cost = base;
                for (std::size_t b = 0; b < corners_.size() && b < static_cast<std::size_t>(break_rounds_); ++b)
                {
                    if (!(corners_[b].second > 0) || vertices + b + 1 > max_vertices_) break;
                    forced_[corners_[b].first] = 1;
                    cost -= corners_[b].second;
                    offerCandidate(c, assemble(c, newCandidate(c), nullptr), opts, exact_breaks_ ? scan_polylines::kNaN : cost);
                }
            }
            if (point_candidates_ && point_window_ < 0) buildPointCandidates(c, opts, max_vertices_ - 1, 0, max_vertices_);
            else if (n <= short_points_) buildPointCandidates(c, opts, max_vertices_ - 1, 1, 0);   // unrefined here
            if (greedy_candidates_) buildGreedyCandidates(c, opts);
        }

        //! The greedy-removal family of chain c (see setGreedyCandidates): every state of at most max_vertices_
        //! vertices, offered unrefined at the greedy's cost.
        void buildGreedyCandidates(std::size_t c, std::vector<scan_polylines::BudgetOption> &opts)
        {
            const auto [cf, cl] = chains_[c];
            greedy_.run(&px_[cf], &py_[cf], cl - cf + 1, cost_ * cost_);
            bool listed = false;
            for (std::size_t s = 0; s < greedy_.states(); ++s)
            {
                const std::size_t k1 = greedy_.vertexCount(s);   // vertices, falling with s
                if (k1 > max_vertices_) continue;
                if (k1 < 2) break;
                // the first state within the budget listed in full, each later one by its removal (O(J) each)
                if (!listed) { greedy_.vertices(s, vertex_index_); listed = true; }
                else
                    vertex_index_.erase(std::find(vertex_index_.begin(), vertex_index_.end(), greedy_.removals()[s - 1].vertex));
                Candidate &cand = newCandidate(c);
                cand.iterations = greedy_iterations_;
                cand.refiner = static_cast<int>(greedy_refinement_);
                Polyline &p = cand.next();
                p.x.reserve(k1); p.y.reserve(k1); p.segs.reserve(k1);   // one allocation at most, not a growth series
                for (std::size_t v = 0; v < k1; ++v)
                {
                    const std::size_t i = cf + vertex_index_[v];
                    p.x.push_back(px_[i]); p.y.push_back(py_[i]);
                }
                // Segment s explains the beams from its first vertex's up to the next vertex's (the last one both).
                for (std::size_t v = 0; v + 1 < k1; ++v)
                    p.segs.push_back({cf + vertex_index_[v], cf + vertex_index_[v + 1] - (v + 2 < k1 ? 1 : 0)});
                // The greedy's own cost is the hit-tested one where beams lie farther apart than the hit test's
                // widening; offered as an estimate all the same, so a plan that chooses it hit-tests it first.
                offerCandidate(c, k1, opts, greedy_.cost(s));
            }
        }

        //! Sum of squared radial errors of chain-local beams a..b predicted by their own TLS line (part_ loaded with the
        //! chain starting at beam cf).
        double radialRangeCost(std::size_t cf, std::size_t a, std::size_t b) const
        {
            const scan_polylines::TlsFit f = part_.fit(a, b);
            double sum = 0;
            for (std::size_t i = a; i <= b; ++i) sum += lineError(f, cf + i);
            return sum;
        }

        //! See setRadialRepartition: `cand` (chosen for chain c at `cost`) replaced by the better re-partition, if any.
        void radialRepartition(std::size_t c, Candidate &cand, double cost)
        {
            if (!cand.partition || cand.ranges.size() < 2) return;
            const auto [cf, cl] = chains_[c];
            const std::size_t n = cl - cf + 1, k = cand.ranges.size(), w = radial_window_, W = 2 * w + 1;
            part_.load(&px_[cf], &py_[cf], n);
            const std::size_t first = cand.ranges.front().first, last = cand.ranges.back().second;
            // start of range s (1 <= s < k) with offset d in [0, W): the original start moved by d - w
            auto start = [&](std::size_t s, std::size_t d) -> long {
                return static_cast<long>(cand.ranges[s].first) + static_cast<long>(d) - static_cast<long>(w);
            };
            const double inf = std::numeric_limits<double>::infinity();
            repart_cost_.assign(k * W, inf);
            repart_from_.assign(k * W, 0);
            for (std::size_t d = 0; d < W; ++d)
            {
                const long b = start(1, d);
                if (b >= static_cast<long>(first) + 2 && b + 1 <= static_cast<long>(last))
                    repart_cost_[W + d] = radialRangeCost(cf, first, static_cast<std::size_t>(b) - 1);
            }
            for (std::size_t s = 2; s < k; ++s)
                for (std::size_t d = 0; d < W; ++d)
                {
                    const long b = start(s, d);
                    if (b + 1 > static_cast<long>(last)) continue;
                    for (std::size_t e = 0; e < W; ++e)
                    {
                        const double prev = repart_cost_[(s - 1) * W + e];
                        const long a = start(s - 1, e);
                        if (!(prev < inf) || b < a + 2) continue;
                        const double v = prev + radialRangeCost(cf, static_cast<std::size_t>(a), static_cast<std::size_t>(b) - 1);
                        if (v < repart_cost_[s * W + d]) { repart_cost_[s * W + d] = v; repart_from_[s * W + d] = e; }
                    }
                }
            double best = inf;
            std::size_t at = 0;
            for (std::size_t d = 0; d < W; ++d)
            {
                const double prev = repart_cost_[(k - 1) * W + d];
                const long a = start(k - 1, d);
                if (!(prev < inf) || static_cast<long>(last) < a + 1) continue;
                const double v = prev + radialRangeCost(cf, static_cast<std::size_t>(a), last);
                if (v < best) { best = v; at = d; }
            }
            if (!(best < inf)) return;
            ranges_.assign(k, {0, 0});
            ranges_.back().second = last;
            for (std::size_t s = k - 1; s >= 1; --s)
            {
                const std::size_t b = static_cast<std::size_t>(start(s, at));
                ranges_[s].first = b;
                ranges_[s - 1].second = b - 1;
                at = repart_from_[s * W + at];
            }
            ranges_.front().first = first;
            if (ranges_ == cand.ranges) return;
            fits_.clear();
            for (const auto &r : ranges_) fits_.push_back(part_.fit(r.first, r.second));
            forced_.assign(k, 0);
            std::size_t old_vertices = 0;
            for (std::size_t q = 0; q < cand.used; ++q) old_vertices += cand.polylines[q].x.size();
            repart_.used = 0;
            if (assemble(c, repart_, nullptr) > old_vertices) return;
            if (chainCost(repart_, cf, cl) < cost)
            {
                std::swap(cand.polylines, repart_.polylines);
                std::swap(cand.used, repart_.used);
                cand.ranges = ranges_;
                cand.stale_cost = true;
            }
        }

        //! The point-vertex family of chain c (see setPointCandidates) with up to maxSegments segments, each polyline
        //! hit-tested, refined when its vertex count lies in [refineLo, refineHi], and offered.
        void buildPointCandidates(std::size_t c, std::vector<scan_polylines::BudgetOption> &opts, std::size_t maxSegments,
                                  std::size_t refineLo, std::size_t refineHi)
        {
            const auto [cf, cl] = chains_[c];
            const std::size_t n = cl - cf + 1;
            if (n < 2 || maxSegments == 0) return;
            points_.load(&px_[cf], &py_[cf], n);
            points_.setEndSkipCost(trim_ends_ ? cost_ * cost_ : 0.0);
            points_.solve(std::min(maxSegments, max_vertices_ - 1));
            for (std::size_t k = 1; k <= points_.maxSegments(); ++k)
            {
                points_.vertices(k, vertex_index_);
                Candidate &cand = newCandidate(c);
                Polyline &p = cand.next();
                for (std::size_t v = 0; v <= k; ++v)
                {
                    const std::size_t i = cf + vertex_index_[v];
                    p.x.push_back(px_[i]); p.y.push_back(py_[i]);
                }
                // Segment s explains the beams from its first vertex's up to the next vertex's (the last one both).
                for (std::size_t s = 0; s < k; ++s)
                    p.segs.push_back({cf + vertex_index_[s], cf + vertex_index_[s + 1] - (s + 1 < k ? 1 : 0)});
                double cost = chainCost(cand, cf, cl);
                if (refine_ && point_iterations_ > 0 && k + 1 >= refineLo && k + 1 <= refineHi) cost = refineCandidate(c, candidate_count_[c], point_iterations_, cost);
                opts.push_back({k + 1, cost});
                ++candidate_count_[c];
            }
        }

        Candidate &newCandidate(std::size_t c)
        {
            if (candidate_count_[c] == candidates_[c].size()) candidates_[c].emplace_back();
            Candidate &cand = candidates_[c][candidate_count_[c]];
            cand.used = 0;
            cand.partition = false;
            cand.stale_cost = false;
            cand.iterations = 20;
            cand.refiner = 0;
            return cand;
        }

        //! Offers the candidate last made by newCandidate(c) to the budget with the given cost, or (when it is NaN)
        //! its hit-tested cost; returns the cost offered.
        double offerCandidate(std::size_t c, std::size_t vertices, std::vector<scan_polylines::BudgetOption> &opts, double known)
        {
            const auto [cf, cl] = chains_[c];
            Candidate &cand = candidates_[c][candidate_count_[c]];
            double cost = std::isnan(known) ? chainCost(cand, cf, cl) : known;
            cand.stale_cost = !std::isnan(known);
            if (refine_candidates_ > 0) cost = refineCandidate(c, candidate_count_[c], refine_candidates_, cost);
            opts.push_back({vertices, cost});
            ++candidate_count_[c];   // option index o > 0 is candidates_[c][o - 1]
            return cost;
        }

        //! See setRefineEveryBudget. `chosen` is the plan of J (option indices into `options`, per chain). The plan of
        //! J before refinement (radially re-partitioned when that is on) is kept as the fallback, so the result never
        //! scores worse than the unrefined plan of J; otherwise the hit-tested map of the plan with the least refined
        //! chain-cost sum is returned (chains interact only where one's segments hit another's beams, which the chain
        //! costs leave out; the fallback's comparison is hit-tested in full).
        void refineEveryBudget(const std::vector<std::vector<scan_polylines::BudgetOption>> &options,
                               const std::vector<std::size_t> &chosen)
        {
            const std::size_t C = chains_.size();
            refined_cost_.resize(C);
            repartitioned_.resize(C);
            for (std::size_t c = 0; c < C; ++c)
            {
                refined_cost_[c].assign(options[c].size(), scan_polylines::kNaN);
                repartitioned_[c].assign(options[c].size(), 0);
            }
            // Candidate o of chain c as it enters refinement: re-partitioned once (when that is on).
            auto prepare = [&](std::size_t c, std::size_t o) -> Candidate & {
                Candidate &cand = candidates_[c][o - 1];
                if (radial_window_ > 0 && !repartitioned_[c][o]) radialRepartition(c, cand, options[c][o].cost);
                repartitioned_[c][o] = 1;
                return cand;
            };
            std::vector<Polyline> fallback;
            for (std::size_t c = 0; c < C; ++c)
                if (chosen[c] > 0)
                {
                    const Candidate &cand = prepare(c, chosen[c]);
                    fallback.insert(fallback.end(), cand.polylines.begin(), cand.polylines.begin() + static_cast<long>(cand.used));
                }
            // The plans of all budgets, the cheapest after refinement; equal sums keep the smaller budget's plan.
            improving_plans_.clear();   // the plans that lowered the best sum, in budget order, C entries each
            improving_sums_.clear();
            double best = std::numeric_limits<double>::infinity();
            // Pass 1 walks the plans of every budget on the offered costs; pass 2 (setRefinedReallocation) the plans
            // of a table on the refined costs where pass 1 refined a candidate, the offered ones elsewhere.
            std::vector<std::vector<scan_polylines::BudgetOption>> reoptions;
            for (int pass = 0; pass < (refined_reallocation_ ? 2 : 1); ++pass)
            {
                if (pass == 1)
                {
                    reoptions = options;
                    for (std::size_t c = 0; c < C; ++c)
                        for (std::size_t o = 1; o < reoptions[c].size(); ++o)
                            if (!std::isnan(refined_cost_[c][o])) reoptions[c][o].cost = refined_cost_[c][o];
                }
                const scan_polylines::BudgetTable table(pass == 0 ? options : reoptions, max_vertices_);
                std::vector<std::size_t> prev;
                for (std::size_t b = 0; b <= max_vertices_; ++b)
                {
                    std::vector<std::size_t> plan = table.plan(b);
                    if (plan.empty() || plan == prev) continue;
                    double sum = 0;
                    for (std::size_t c = 0; c < C; ++c)
                    {
                        const std::size_t o = plan[c];
                        if (o > 0 && std::isnan(refined_cost_[c][o]))
                        {
                            // hit-tested before refinement where the option's cost is not (a break candidate's estimate)
                            Candidate &cand = prepare(c, o);
                            const double before = cand.stale_cost ? chainCost(cand, chains_[c].first, chains_[c].second) : options[c][o].cost;
                            refined_cost_[c][o] = refineCandidate(c, o - 1, cand.iterations, before);
                        }
                        sum += o > 0 ? refined_cost_[c][o] : options[c][0].cost;
                    }
                    if (sum < best)
                    {
                        best = sum;
                        improving_sums_.push_back(sum);
                        const std::size_t at = improving_plans_.size();
                        improving_plans_.resize(at + C);
                        std::copy(plan.begin(), plan.end(), improving_plans_.begin() + static_cast<long>(at));
                    }
                    prev.swap(plan);
                }
            }
            std::vector<double> rhat = expected(fallback);
            scan_polylines::RayScore score = scan_polylines::scoreExpected(range_, returned_, rhat);
            // The chain costs leave out where one chain's segments hit another chain's beams (a refined inner vertex
            // may carry a segment's span over a neighbouring chain). The last improving plan is hit-tested as a whole
            // map; where that scores clearly worse than its sum, the earlier improving plans are tried, latest first,
            // until one scores as its sum says; the best hit-tested of those visited is kept. A larger budget's
            // improving plans extend the smaller budget's (same table rows), and it visits the smaller budget's
            // visited plans too unless it stops earlier at a plan that scores as its (lower) sum: monotone in J.
            std::vector<Polyline> map, best_map;
            std::vector<double> rhat2, best_rhat;
            scan_polylines::RayScore best_score;
            double best_value = std::numeric_limits<double>::infinity();
            const double returned = static_cast<double>(std::max<std::size_t>(1, score.returned));
            for (std::size_t q = improving_sums_.size(); q-- > 0;)
            {
                const std::size_t *plan = &improving_plans_[q * C];
                map.clear();
                for (std::size_t c = 0; c < C; ++c)
                    if (plan[c] > 0)
                    {
                        const Candidate &cand = candidates_[c][plan[c] - 1];
                        map.insert(map.end(), cand.polylines.begin(), cand.polylines.begin() + static_cast<long>(cand.used));
                    }
                rhat2 = expected(map);
                const scan_polylines::RayScore score2 = scan_polylines::scoreExpected(range_, returned_, rhat2);
                const double value = score2.score(cost_);
                if (value < best_value) { best_value = value; best_map.swap(map); best_rhat.swap(rhat2); best_score = score2; }
                if (value <= improving_sums_[q] / returned * (1 + kInteractionTolerance)) break;
            }
            if (best_value < score.score(cost_)) publish(best_map, best_rhat, best_score);
            else publish(fallback, rhat, score);
        }

        //! Radially refines candidate `index` of chain c (at most `iterations` LM iterations per polyline) and keeps the
        //! result when its hit-tested cost is below `cost`; returns the candidate's cost.
        double refineCandidate(std::size_t c, std::size_t index, int iterations, double cost)
        {
            const int refiner = candidates_[c][index].refiner;
            if (refiner != 3) return refineWith(c, index, iterations, cost, refiner);
            // along the beams first, then one free iteration from the better of the start and that
            cost = refineWith(c, index, iterations, cost, 2);
            return refineWith(c, index, 1, cost, 0);
        }

        //! refineCandidate with refiner `mode` (see Candidate::refiner; 0-2, 4).
        double refineWith(std::size_t c, std::size_t index, int iterations, double cost, int mode)
        {
            const auto [cf, cl] = chains_[c];
            Candidate &cand = candidates_[c][index];
            Candidate &refined = refine_scratch_;   // a member: its buffers are reused from call to call
            refined.used = 0;
            for (std::size_t p = 0; p < cand.used; ++p) refined.next() = cand.polylines[p];
            refined.partition = cand.partition;
            refined.ranges = cand.ranges;
            refined.stale_cost = false;
            refined.iterations = cand.iterations;
            refined.refiner = cand.refiner;
            lm_.setMaxIterations(iterations);
            const scan_polylines::BeamArrays arrays{ux_.data(), uy_.data(), range_.data()};
            for (std::size_t p = 0; p < refined.used; ++p)
            {
                Polyline &pl = refined.polylines[p];
                if (mode == 1) reassigning_(pl.x, pl.y, pl.segs, arrays, angle_.data(), cost_ * cost_, iterations, kSpanWiden);
                else if (mode == 2)
                {
                    // vertex v on the first beam of segment v (the last vertex: the last segment's last beam)
                    beam_rho_.clear(); beam_index_.clear();
                    for (std::size_t v = 0; v < pl.x.size(); ++v)
                    {
                        beam_index_.push_back(v < pl.segs.size() ? pl.segs[v].first : pl.segs.back().second);
                        beam_rho_.push_back(std::hypot(pl.x[v], pl.y[v]));
                    }
                    along_beams_.setMaxIterations(iterations);
                    along_beams_(beam_rho_, beam_index_, arrays, cost_ * cost_);
                    for (std::size_t v = 0; v < pl.x.size(); ++v)
                    {
                        pl.x[v] = beam_rho_[v] * ux_[beam_index_[v]]; pl.y[v] = beam_rho_[v] * uy_[beam_index_[v]];
                    }
                }
                else if (mode == 4) lm_.refineConsistent(pl.x, pl.y, pl.segs, arrays, cost_ * cost_, 3);
                else lm_(pl.x, pl.y, pl.segs, arrays, cost_ * cost_);
            }
            const double c2 = chainCost(refined, cf, cl);
            if (c2 < cost) { cost = c2; std::swap(cand, refined); }
            return cost;
        }

        //! Squared radial error of beam i predicted by line f (the unexplained cost squared where f does not cross
        //! the beam in front of the sensor).
        double lineError(const scan_polylines::TlsFit &f, std::size_t i) const
        {
            const double t = f.d / (f.nx * ux_[i] + f.ny * uy_[i]);
            if (!(std::isfinite(t) && t > 0)) return cost_ * cost_;
            return (range_[i] - t) * (range_[i] - t);
        }

        //! Local gain of a break instead of the corner (x, y) between ranges ending at beam a and starting at beam b:
        //! only the beams within one of the boundary change line (the corner stays in that wedge).
        double breakGain(const scan_polylines::TlsFit &f, const scan_polylines::TlsFit &g, std::size_t a, std::size_t b,
                         std::size_t cf, std::size_t cl, double x, double y) const
        {
            const double dir = ux_[a] * uy_[b] - uy_[a] * ux_[b] > 0 ? 1.0 : -1.0;
            double gain = 0;
            for (std::size_t i = a > cf ? a - 1 : a; i <= std::min(cl, b + 1); ++i)
            {
                const bool before = (ux_[i] * y - uy_[i] * x) * dir > 0;   // on the first range's side of the corner
                const bool own = i <= a;                                   // the break predicts i by its own range's line
                if (before == own) continue;
                gain += (before ? lineError(f, i) : lineError(g, i)) - (own ? lineError(f, i) : lineError(g, i));
            }
            return gain;
        }

        //! Builds the polylines of the partition ranges_ / fits_ of chain c into `cand` (breaks at boundaries where
        //! forced_ is set, and wherever no usable corner exists); returns the vertex count. When `corners` is given,
        //! it receives every corner's boundary index and the local gain of a break there.
        std::size_t assemble(std::size_t c, Candidate &cand, std::vector<std::pair<std::size_t, double>> *corners)
        {
            const auto [cf, cl] = chains_[c];
            const std::vector<BeamRange> &ranges = ranges_;
            const std::vector<scan_polylines::TlsFit> &fits = fits_;
            const std::size_t k = ranges.size();
            if (corners) corners->clear();
            Polyline *cur = &cand.next();
            double x, y;
            endOnBeam(fits[0], cf + ranges[0].first, x, y);
            cur->x.push_back(x); cur->y.push_back(y);
            std::size_t vertices = 1;
            for (std::size_t s = 0; s < k; ++s)
            {
                cur->segs.push_back({cf + ranges[s].first, cf + ranges[s].second});
                if (s + 1 == k)
                {
                    endOnBeam(fits[s], cf + ranges[s].second, x, y);
                    cur->x.push_back(x); cur->y.push_back(y); ++vertices;
                    break;
                }
                const std::size_t a = cf + ranges[s].second, b = cf + ranges[s + 1].first;
                const double reach = cost_ + scan_polylines::distance(px_[b] - px_[a], py_[b] - py_[a]);
                // A corner stays in the wedge of the boundary beams and their outer neighbours (within the chain):
                // farther round, it would fold its segments over other beams, or hide beams of other chains.
                const std::size_t wa = a > cf ? a - 1 : a, wb = b < cl ? b + 1 : b;
                if (!forced_[s] && corner(fits[s], fits[s + 1], px_[a], py_[a], px_[b], py_[b], reach, x, y)
                    && inWedge(wa, wb, x, y))
                {
                    if (corners) corners->push_back({s, breakGain(fits[s], fits[s + 1], a, b, cf, cl, x, y)});
                    cur->x.push_back(x); cur->y.push_back(y); ++vertices;
                    continue;
                }
                endOnBeam(fits[s], a, x, y);
                cur->x.push_back(x); cur->y.push_back(y); ++vertices;
                cur = &cand.next();   // a break: the next range starts a new polyline
                endOnBeam(fits[s + 1], b, x, y);
                cur->x.push_back(x); cur->y.push_back(y); ++vertices;
            }
            return vertices;
        }

        //! Weights that turn a point's squared orthogonal distance into its squared radial error, 1 / cos^2 of the
        //! angle between its beam and the surface normal, the normal taken from the points' TLS line over the
        //! neighbours within 2 beams (cos kept >= 0.2, so the weight stays <= 25).
        void radialWeights(std::size_t cf, std::size_t cl)
        {
            const std::size_t n = cl - cf + 1;
            weight_.assign(n, 1.0);
            if (!radial_weights_ || n < 3) return;
            part_.load(&px_[cf], &py_[cf], n);
            for (std::size_t i = 0; i < n; ++i)
            {
                const std::size_t lo = i >= 2 ? i - 2 : 0, hi = std::min(n - 1, i + 2);
                const scan_polylines::TlsFit f = part_.fit(lo, hi);
                const double c = std::max(0.2, std::abs(f.nx * ux_[cf + i] + f.ny * uy_[cf + i]));
                weight_[i] = 1.0 / (c * c);
            }
        }

        //! Score contribution (sum over the chain's beams) of a candidate, hit-tested against its own segments only.
        double chainCost(const Candidate &cand, std::size_t cf, std::size_t cl)
        {
            local_.assign(cl - cf + 1, scan_polylines::kNaN);
            static const scan_polylines::Widening widening(kSpanWiden);
            for (std::size_t q = 0; q < cand.used; ++q)
            {
                const Polyline &p = cand.polylines[q];
                for (std::size_t s = 0; s < p.segs.size(); ++s)
                {
                    const double ax = p.x[s], ay = p.y[s], bx = p.x[s + 1], by = p.y[s + 1];
                    const auto span = scan_polylines::DirectionSpan::of(ax, ay, bx, by, widening);
                    auto test = [&](std::size_t i) {
                        if (!span.contains(ux_[i], uy_[i], angle_[i], widening)) return false;
                        const double t = scan_polylines::rangeAlongRay(ux_[i], uy_[i], ax, ay, bx, by);
                        if (!std::isnan(t)) local_[i - cf] = t;
                        return true;
                    };
                    for (std::size_t i = p.segs[s].first; i <= p.segs[s].second; ++i) test(i);
                    for (std::size_t i = p.segs[s].first; i-- > cf && test(i);) {}
                    for (std::size_t i = p.segs[s].second + 1; i <= cl && test(i); ++i) {}
                }
            }
            double sum = 0;
            for (std::size_t i = cf; i <= cl; ++i)
            {
                const double e = range_[i] - local_[i - cf];
                sum += std::isnan(e) ? cost_ * cost_ : e * e;
            }
            return sum;
        }

        std::vector<double> expected(const std::vector<Polyline> &map) const
        {
            std::vector<std::vector<Eigen::Vector2d>> verts(map.size());
            for (std::size_t p = 0; p < map.size(); ++p)
                for (std::size_t v = 0; v < map[p].x.size(); ++v) verts[p].emplace_back(map[p].x[v], map[p].y[v]);
            return scan_polylines::expectedRangesOf(angle_, cos_angle_.data(), sin_angle_.data(), verts, kSpanWiden);
        }

        void publish(const std::vector<Polyline> &map, const std::vector<double> &rhat, const scan_polylines::RayScore &score)
        {
            score_ = score;
            for (std::size_t i = 0; i < rhat.size(); ++i) expected_[i] = static_cast<T>(rhat[i]);
            for (std::size_t p = 0; p < map.size(); ++p)
            {
                const Polyline &pl = map[p];
                std::vector<VectorType> out;
                for (std::size_t v = 0; v < pl.x.size(); ++v) out.emplace_back(static_cast<T>(pl.x[v]), static_cast<T>(pl.y[v]));
                vertex_count_ += out.size();
                polylines_.push_back(std::move(out));
                for (std::size_t s = 0; s < pl.segs.size(); ++s) segments_.push_back(segmentOf(p, pl, s));
            }
        }

        //! Line of segment s through its two vertices, and the covariance of (r, theta) of a line fitted to the
        //! segment's points with noise sigma^2 = max(point sigma^2, residual variance): the inverse normal matrix
        //! sigma^2 [[m, -sum s_i], [-sum s_i, sum s_i^2]]^-1, s_i the points' coordinates along the line (a segment
        //! that owns one beam: that point and the next beam's).
        Segment segmentOf(std::size_t p, const Polyline &pl, std::size_t s) const
        {
            Segment seg;
            seg.polyline = p;
            seg.beams = pl.segs[s];
            const double dx = pl.x[s + 1] - pl.x[s], dy = pl.y[s + 1] - pl.y[s];
            const double len = std::hypot(dx, dy);
            double nx = len > 0 ? -dy / len : scan_polylines::kNaN, ny = len > 0 ? dx / len : scan_polylines::kNaN;
            double r = nx * pl.x[s] + ny * pl.y[s];
            if (r < 0) { r = -r; nx = -nx; ny = -ny; }
            const double tx = -ny, ty = nx;
            double m = 0, ss = 0, ss2 = 0, res2 = 0;
            // A segment of the point-vertex family may own a single beam (its first vertex's): its line is then fitted
            // to that point and the next beam's, the segment's other vertex, so the covariance stays finite.
            std::size_t last = seg.beams.second;
            if (last == seg.beams.first && last + 1 < returned_.size() && returned_[last + 1]) ++last;
            for (std::size_t i = seg.beams.first; i <= last; ++i)
            {
                const double si = px_[i] * tx + py_[i] * ty, di = px_[i] * nx + py_[i] * ny - r;
                m += 1; ss += si; ss2 += si * si; res2 += di * di;
            }
            const double var = std::max(point_sigma_ * point_sigma_, m > 2 ? res2 / (m - 2) : 0.0);
            const double det = m * ss2 - ss * ss, scale = var / det;
            Eigen::Matrix2d cov;
            cov << ss2, ss, ss, m;
            // points that do not spread along the line (or spread below what a double resolves): nothing is known of
            // the line's angle or offset, so both variances are infinite and the correlation 0, never NaN
            if (det > 0 && std::isfinite(scale)) cov *= scale;
            else cov << std::numeric_limits<double>::infinity(), 0.0, 0.0, std::numeric_limits<double>::infinity();
            seg.r = static_cast<T>(r);
            seg.theta = static_cast<T>(std::atan2(ny, nx));
            seg.covariance = cov.cast<T>();
            return seg;
        }

        std::size_t max_vertices_ = 50;
        double max_gap_ = 1.0, cost_ = 0.5, point_sigma_ = 0.01;
        bool refine_ = true, radial_weights_ = false, every_budget_ = true;
        std::vector<std::vector<double>> refined_cost_;
        std::vector<std::vector<char>> repartitioned_;
        Candidate refine_scratch_;
        scan_polylines::RadialRefinement lm_;
        int refine_candidates_ = 0;
        int break_rounds_ = 0;
        bool trim_ends_ = false;
        std::size_t neighbour_window_ = 0;
        bool exact_breaks_ = false;
        std::size_t radial_window_ = 0;
        std::vector<double> repart_cost_;
        std::vector<std::size_t> repart_from_;
        Candidate repart_;
        bool point_candidates_ = false;
        int point_iterations_ = 20, point_window_ = 2;
        std::size_t short_points_ = 32;
        std::vector<std::size_t> improving_plans_;
        std::vector<double> improving_sums_;
        //! A plan's whole-map score may exceed its chain-cost sum by this fraction before earlier plans are tried.
        static constexpr double kInteractionTolerance = 1e-3;
        scan_polylines::PointPolylines points_;
        bool greedy_candidates_ = true;
        int greedy_iterations_ = 20;
        GreedyRefinement greedy_refinement_ = GreedyRefinement::AlongBeamsThenFree;
        std::size_t partition_segments_ = 10;
        bool refined_reallocation_ = true;
        detail::ReassigningRefinement reassigning_;
        detail::BeamRangeRefinement along_beams_;
        std::vector<double> beam_rho_;
        std::vector<std::size_t> beam_index_;
        detail::GreedyPolylines greedy_;
        std::vector<std::size_t> vertex_index_;
        std::vector<char> forced_;
        std::vector<std::pair<std::size_t, double>> corners_;

        std::vector<double> px_, py_, ux_, uy_, range_, angle_, local_, weight_;
        std::vector<double> cos_angle_, sin_angle_;   // of angle_, for the hit test's rays (NaN without a return)
        std::vector<bool> returned_;
        std::size_t returned_count_ = 0;
        std::vector<BeamRange> chains_;
        std::vector<std::vector<Candidate>> candidates_;
        std::vector<std::size_t> candidate_count_;
        std::vector<scan_polylines::TlsFit> fits_;
        std::vector<BeamRange> ranges_;
        scan_polylines::ChainPartition part_;

        std::vector<std::vector<VectorType>> polylines_;
        std::vector<T> expected_;
        std::vector<Segment> segments_;
        scan_polylines::RayScore score_;
        std::size_t vertex_count_ = 0;
    };

    using ScanPolylines2f = ScanPolylines2D<float>;
    using ScanPolylines2d = ScanPolylines2D<double>;
}
