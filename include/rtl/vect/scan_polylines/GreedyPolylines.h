// Greedy vertex removal on one chain of a range scan, by the radial (ray) error: the candidate-building step of
// probabilistic line extraction (Schaefer et al., IROS 2018), for one chain.
//
// Start: one polyline through every point of the chain (each point a vertex on its own beam, so every beam is
// explained exactly). Then, repeatedly, the vertex whose removal raises the chain's cost least is removed, down to no
// polyline at all. The chain's cost is the sum over its beams of
//   (r_i - r-hat_i)^2   for a beam between the polyline's first and last vertex (r-hat_i: the distance along beam i
//                       to the line of the segment whose vertices' beams enclose it; a vertex's own beam: 0),
//   c^2                 (the unexplained cost squared) for a beam before the first vertex or after the last, and for
//                       a beam whose segment line does not cross it in front of the sensor.
// Removing an inner vertex joins its neighbours; removing an end vertex leaves the beams up to the new end
// unexplained; removing a vertex of a two-vertex polyline removes the polyline (both vertices). So the polyline
// never splits: after every removal the chain holds one polyline (or none), and its vertex count falls by one (two
// for the last removal). The costs are the hit-tested costs of the scan's ray model (RayGeometry.h) on the chain's
// own beams provided that consecutive beams' directions differ by more than the hit test's widening (1e-3 rad for
// the model) and the chain spans less than pi: a segment between two point vertices then hits exactly the beams
// between them.
//
// Why: these candidates are chosen by the error the scan is scored by (radial), where the total-least-squares
// partitions are optimal for the orthogonal error; at grazing incidence the two differ most.
//
// A removal changes the removal costs of its two neighbours only (and, when two vertices remain, of both), so the
// sequence runs on a heap with lazy invalidation: O(n log n) heap work plus O(length) per recomputed segment cost,
// O(n) memory for a chain of n points.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "rtl/vect/scan_polylines/RayGeometry.h"

namespace rtl::detail
{
    class GreedyPolylines
    {
    public:
        //! One step of the removal sequence: the chain-local point removed (the lower one when a two-vertex polyline
        //! goes), how many vertices went (1, or 2 for the last step) and by how much the chain's cost rose.
        struct Removal
        {
            std::size_t vertex = 0;
            std::size_t removed = 1;
            double delta = 0;
        };

        //! Runs the whole removal sequence of a chain of n points (x, y: finite, not at the origin, in beam order)
        //! with the unexplained cost squared c2 (> 0). A chain of fewer than 2 points has no polyline and no step.
        //! O(n log n + sum of the recomputed segments' lengths).
        void run(const double *x, const double *y, std::size_t n, double c2)
        {
            n_ = n; c2_ = c2;
            x_.assign(x, x + n); y_.assign(y, y + n);
            ux_.resize(n); uy_.resize(n); r_.resize(n);
            for (std::size_t i = 0; i < n; ++i)
            {
                r_[i] = std::hypot(x[i], y[i]);
                ux_[i] = x[i] / r_[i]; uy_[i] = y[i] / r_[i];
            }
            removals_.clear();
            removed_at_.assign(n, kNone);
            cost_.clear();
            if (n < 2)
            {
                cost_.push_back(static_cast<double>(n) * c2);
                count_.assign(1, 0);
                return;
            }
            prev_.resize(n); next_.resize(n);
            for (std::size_t i = 0; i < n; ++i) { prev_[i] = i > 0 ? i - 1 : kNone; next_[i] = i + 1 < n ? i + 1 : kNone; }
            first_ = 0; last_ = n - 1; alive_ = n;
            seg_.assign(n, 0.0);
            double total = 0;
            for (std::size_t i = 0; i + 1 < n; ++i) { seg_[i] = segmentCost(i, i + 1); total += seg_[i]; }
            cost_.push_back(total);
            count_.assign(1, n);
            version_.assign(n, 0);
            merged_.assign(n, 0.0);
            heap_.clear();   // keeps its memory from call to call
            for (std::size_t i = 0; i < n; ++i) push(i);
            while (alive_ > 0)
            {
                std::pop_heap(heap_.begin(), heap_.end(), later);
                const Entry e = heap_.back();
                heap_.pop_back();
                if (e.version != version_[e.vertex] || removed_at_[e.vertex] != kNone) continue;   // stale entry
                remove(e.vertex, e.cost);
            }
        }

        //! The removal sequence, in order.
        [[nodiscard]] const std::vector<Removal> &removals() const { return removals_; }
        //! Number of states: the start and one after every removal (removals().size() + 1).
        [[nodiscard]] std::size_t states() const { return cost_.size(); }
        //! The chain's cost after s removals (s < states()).
        [[nodiscard]] double cost(std::size_t s) const { return cost_[s]; }
        //! Vertices of the polyline after s removals (0 once the polyline is gone; strictly falling in s).
        [[nodiscard]] std::size_t vertexCount(std::size_t s) const { return count_[s]; }

        //! The chain-local indices of the vertices after s removals, increasing, into `out` (its memory reused). O(n).
        void vertices(std::size_t s, std::vector<std::size_t> &out) const
        {
            out.clear();
            if (count_[s] == 0) return;
            for (std::size_t i = 0; i < n_; ++i)
                if (removed_at_[i] == kNone || removed_at_[i] >= s) out.push_back(i);
        }

    private:
        static constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
        struct Entry
        {
            double cost;
            std::size_t vertex;
            std::uint32_t version;
        };
        //! Heap order: the least cost on top, then the lowest vertex (a deterministic order among equal costs).
        static bool later(const Entry &a, const Entry &b)
        {
            return a.cost != b.cost ? a.cost > b.cost : a.vertex > b.vertex;
        }

        //! Sum over the beams strictly between points a < b of the squared radial error of the line through them.
        double segmentCost(std::size_t a, std::size_t b) const
        {
            double sum = 0;
            for (std::size_t i = a + 1; i < b; ++i)
            {
                const double t = scan_polylines::rangeAlongRay(ux_[i], uy_[i], x_[a], y_[a], x_[b], y_[b]);
                const double e = r_[i] - t;
                sum += std::isnan(t) ? c2_ : e * e;
            }
            return sum;
        }

        //! Rise of the chain's cost if vertex v went now (see the file comment); an inner vertex's joined segment
        //! cost is kept in merged_ for the removal.
        double removalCost(std::size_t v)
        {
            if (alive_ == 2) return static_cast<double>(last_ - first_ + 1) * c2_ - seg_[first_];
            if (v == first_) return static_cast<double>(next_[v] - v) * c2_ - seg_[v];
            if (v == last_) return static_cast<double>(v - prev_[v]) * c2_ - seg_[prev_[v]];
            merged_[v] = segmentCost(prev_[v], next_[v]);
            return merged_[v] - seg_[prev_[v]] - seg_[v];
        }

        void push(std::size_t v)
        {
            ++version_[v];
            heap_.push_back({removalCost(v), v, version_[v]});
            std::push_heap(heap_.begin(), heap_.end(), later);
        }

        void remove(std::size_t v, double delta)
        {
            const std::size_t step = removals_.size();
            Removal r;
            r.delta = delta;
            if (alive_ == 2)
            {
                r.vertex = first_; r.removed = 2;
                removed_at_[first_] = removed_at_[last_] = step;
                alive_ = 0;
            }
            else
            {
                r.vertex = v;
                removed_at_[v] = step;
                --alive_;
                const std::size_t p = prev_[v], q = next_[v];
                if (v == first_) { first_ = q; prev_[q] = kNone; }
                else if (v == last_) { last_ = p; next_[p] = kNone; }
                else { next_[p] = q; prev_[q] = p; seg_[p] = merged_[v]; }
                if (p != kNone) push(p);
                if (q != kNone) push(q);
                if (alive_ == 2) { push(first_); push(last_); }   // the two-vertex rule now applies to both
            }
            removals_.push_back(r);
            cost_.push_back(cost_.back() + delta);
            count_.push_back(alive_);
        }

        std::size_t n_ = 0, first_ = 0, last_ = 0, alive_ = 0;
        double c2_ = 0;
        std::vector<double> x_, y_, ux_, uy_, r_, seg_, merged_, cost_;
        std::vector<std::size_t> prev_, next_, removed_at_, count_;
        std::vector<std::uint32_t> version_;
        std::vector<Removal> removals_;
        std::vector<Entry> heap_;
    };
}
