// PLE's own method replicated from the paper's description (Schaefer et al., IROS 2018), to check the benchmark's
// metric against PLE's published figures and to see where PLE+'s accuracy comes from: per scan, one polyline through
// all points of every chain (chains as rtl::ScanPolylines2D forms them: split at beams without a return and where
// neighbouring points lie more than maxGap apart; a one-point chain has no segment), then the vertex anywhere in the
// scan whose removal raises the scan's cost least is removed (rtl::detail::GreedyPolylines, one chain each; a
// chain's next removal is always its own greedy's next, so the scan's greedy picks, among the chains, the least
// next rise), until at most J vertices remain. "PLE+ (ours)" then refines that map's polylines with the extractor's
// radial Levenberg-Marquardt (kept when the whole map then scores lower, as the extractor does).
#pragma once

#include <cmath>
#include <cstddef>
#include <functional>
#include <queue>
#include <utility>
#include <vector>

#include "ple/ple_protocol.h"
#include "rtl/vect/scan_polylines/GreedyPolylines.h"
#include "rtl/vect/scan_polylines/BeamRangeRefinement.h"
#include "rtl/vect/scan_polylines/RadialRefinement.h"
#include "rtl/vect/scan_polylines/ReassigningRefinement.h"

namespace rtl::ple
{
    class GreedyExtractor
    {
    public:
        //! PLE+ (ours) refined by rounds of single LM iterations with the beams re-assigned by the hit test after each
        //! (detail::ReassigningRefinement; 0: RadialRefinement's fixed assignment, 20 iterations).
        void setReassignRounds(int rounds) { reassign_rounds_ = rounds; }
        //! PLE+ (ours) refined with every vertex moved along its own beam (detail::BeamRangeRefinement, 20 iterations).
        void setBeamRangeRefinement(bool on) { beam_range_ = on; }
        //! PLE+ (ours) refined hit-consistently (RadialRefinement::refineConsistent: inner vertices kept in their
        //! boundary beams' wedges, boundaries shifted where a vertex rests on a wedge edge) with this many passes of
        //! shifts; 0: off.
        void setConsistentRounds(int rounds) { consistent_rounds_ = rounds; }

        typedef std::vector<std::vector<VectorND<2, double>>> Map;

        //! PLE's map of `scan` within J vertices (unexplained cost c, chains split at gaps over maxGap); with `refine`,
        //! radially refined as PLE+ (ours).
        Map operator()(const Scan &scan, std::size_t J, bool refine, double c = 0.5, double maxGap = 1.0)
        {
            const std::size_t n = scan.points.size();
            ux_.assign(n, 0); uy_.assign(n, 0); r_.assign(n, 0); angle_.assign(n, 0);
            std::vector<std::pair<std::size_t, std::size_t>> chains;
            for (std::size_t i = 0; i < n;)
            {
                if (!valid(scan, i)) { ++i; continue; }
                std::size_t j = i;
                while (j + 1 < n && valid(scan, j + 1)
                       && std::hypot(scan.points[j + 1][0] - scan.points[j][0], scan.points[j + 1][1] - scan.points[j][1]) <= maxGap) ++j;
                chains.push_back({i, j});
                i = j + 1;
            }
            for (std::size_t i = 0; i < n; ++i)
                if (valid(scan, i))
                {
                    r_[i] = std::hypot(scan.points[i][0], scan.points[i][1]);
                    ux_[i] = scan.points[i][0] / r_[i]; uy_[i] = scan.points[i][1] / r_[i];
                    angle_[i] = std::atan2(scan.points[i][1], scan.points[i][0]);
                }
            if (greedy_.size() < chains.size()) greedy_.resize(chains.size());
            std::vector<std::size_t> step(chains.size(), 0);
            typedef std::pair<double, std::size_t> Next;   // (rise of the chain's next removal, chain)
            std::priority_queue<Next, std::vector<Next>, std::greater<Next>> heap;
            std::size_t total = 0;
            for (std::size_t c_ = 0; c_ < chains.size(); ++c_)
            {
                const auto [cf, cl] = chains[c_];
                xs_.clear(); ys_.clear();
                for (std::size_t i = cf; i <= cl; ++i) { xs_.push_back(scan.points[i][0]); ys_.push_back(scan.points[i][1]); }
                greedy_[c_].run(xs_.data(), ys_.data(), xs_.size(), c * c);
                total += greedy_[c_].vertexCount(0);
                if (!greedy_[c_].removals().empty()) heap.push({greedy_[c_].removals()[0].delta, c_});
            }
            while (total > J && !heap.empty())
            {
                const std::size_t c_ = heap.top().second;
                heap.pop();
                const auto &rem = greedy_[c_].removals();
                total -= rem[step[c_]].removed;
                if (++step[c_] < rem.size()) heap.push({rem[step[c_]].delta, c_});
            }
            Map map;
            std::vector<Piece> pieces;
            for (std::size_t c_ = 0; c_ < chains.size(); ++c_)
            {
                if (greedy_[c_].vertexCount(step[c_]) < 2) continue;
                greedy_[c_].vertices(step[c_], index_);
                Piece p;
                const std::size_t cf = chains[c_].first;
                for (std::size_t v = 0; v < index_.size(); ++v)
                {
                    p.x.push_back(scan.points[cf + index_[v]][0]); p.y.push_back(scan.points[cf + index_[v]][1]);
                    if (v + 1 < index_.size())
                        p.segs.push_back({cf + index_[v], cf + index_[v + 1] - (v + 2 < index_.size() ? 1 : 0)});
                }
                pieces.push_back(std::move(p));
            }
            map = toMap(pieces);
            if (!refine || pieces.empty()) return map;
            const scan_polylines::BeamArrays arrays{ux_.data(), uy_.data(), r_.data()};
            for (auto &p : pieces)
            {
                if (beam_range_)
                {
                    rho_.clear(); vb_.clear();
                    for (std::size_t v = 0; v < p.x.size(); ++v)
                    {
                        const std::size_t b = v < p.segs.size() ? p.segs[v].first : p.segs.back().second;
                        vb_.push_back(b); rho_.push_back(std::hypot(p.x[v], p.y[v]));
                    }
                    blm_(rho_, vb_, arrays, c * c);
                    for (std::size_t v = 0; v < p.x.size(); ++v) { p.x[v] = rho_[v] * ux_[vb_[v]]; p.y[v] = rho_[v] * uy_[vb_[v]]; }
                }
                else if (consistent_rounds_ > 0) lm_.refineConsistent(p.x, p.y, p.segs, arrays, c * c, consistent_rounds_);
                else if (reassign_rounds_ > 0) rlm_(p.x, p.y, p.segs, arrays, angle_.data(), c * c, reassign_rounds_);
                else lm_(p.x, p.y, p.segs, arrays, c * c);
            }
            Map refined = toMap(pieces);
            return score(scan, refined).score(c) < score(scan, map).score(c) ? refined : map;
        }

    private:
        struct Piece
        {
            std::vector<double> x, y;
            std::vector<std::pair<std::size_t, std::size_t>> segs;
        };

        static bool valid(const Scan &scan, std::size_t i)
        {
            const double x = scan.points[i][0], y = scan.points[i][1];
            return std::isfinite(x) && std::isfinite(y) && (x != 0 || y != 0);
        }

        static Map toMap(const std::vector<Piece> &pieces)
        {
            Map map;
            for (const auto &p : pieces)
            {
                map.emplace_back();
                for (std::size_t v = 0; v < p.x.size(); ++v) map.back().emplace_back(p.x[v], p.y[v]);
            }
            return map;
        }

        std::vector<detail::GreedyPolylines> greedy_;
        detail::ReassigningRefinement rlm_;
        scan_polylines::RadialRefinement lm_;
        std::vector<double> ux_, uy_, r_, angle_, xs_, ys_;
        std::vector<std::size_t> index_;
        int reassign_rounds_ = 0;
        int consistent_rounds_ = 0;
        bool beam_range_ = false;
        detail::BeamRangeRefinement blm_;
        std::vector<double> rho_;
        std::vector<std::size_t> vb_;
    };
}
