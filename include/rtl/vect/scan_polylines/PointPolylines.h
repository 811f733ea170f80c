// Optimal polygonal approximation of one chain of points by polylines whose vertices are points of the chain (the
// classic min-error formulation, Perez and Vidal 1994): for every k, the polyline through k + 1 of the chain's points,
// in chain order, whose chords leave the least sum of squared orthogonal distances of the in-between points.
//
// Why a second family beside the TLS partitions (ChainPartition.h): a vertex on a measured point lies on its own beam,
// so consecutive segments always join inside the chain's angular span (no corner outside the boundary wedge, no break
// costing an extra vertex), and a depth step keeps a vertex on each side of it.
//
// A chord's cost comes in O(1) from prefix sums of x, y, x^2, xy, y^2 (about the chain's first point): for the line
// through a and b, sum over the points p strictly between them of ((p - a) x (b - a))^2 / |b - a|^2. The programme
//   F[k][j] = min over i < j of F[k-1][i] + chord(i, j)
// gives every k's optimum in one pass: at most O(n^2) chord costs (each computed once, when first needed), then at
// most O(K n^2) additions (the scan over the last chord stops once the TLS error of the points it spans reaches the
// best total, see solve); O(n^2 + K n) memory.
// The first and last vertices are the chain's ends, or (setEndSkipCost) any points, the points before the first and
// after the last left out at a fixed cost each (started from F[0][i] = i s, ended at min over j of F[k][j] + (n-1-j) s).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace rtl::scan_polylines
{
    class PointPolylines
    {
    public:
        //! Prefix sums of a chain of n points (coordinates finite).
        void load(const double *x, const double *y, std::size_t n)
        {
            n_ = n;
            x0_ = n ? x[0] : 0; y0_ = n ? y[0] : 0;
            ax_.resize(n); ay_.resize(n);
            sums_.assign(5 * (n + 1), 0.0);
            for (std::size_t i = 0; i < n; ++i)
            {
                const double a = x[i] - x0_, b = y[i] - y0_;
                ax_[i] = a; ay_[i] = b;
                const double *p = &sums_[5 * i];
                double *q = &sums_[5 * (i + 1)];
                q[0] = p[0] + a; q[1] = p[1] + b; q[2] = p[2] + a * a; q[3] = p[3] + a * b; q[4] = p[4] + b * b;
            }
        }

        [[nodiscard]] std::size_t size() const { return n_; }

        //! Cost per point left out before the first vertex or after the last (> 0; 0 or less, the default: the
        //! polyline runs from the chain's first point to its last). Takes effect at the next solve.
        void setEndSkipCost(double s) { skip_ = s; }

        //! Sum of squared orthogonal distances of points i+1..j-1 to the line through points i and j (i < j); where
        //! points i and j coincide, the squared distances to that point.
        [[nodiscard]] double chordCost(std::size_t i, std::size_t j) const
        {
            if (j <= i + 1) return 0.0;
            const double *a = &sums_[5 * (i + 1)], *b = &sums_[5 * j];
            const double m = static_cast<double>(j - i - 1);
            const double sx = b[0] - a[0], sy = b[1] - a[1], sxx = b[2] - a[2], sxy = b[3] - a[3], syy = b[4] - a[4];
            const double px = ax_[i], py = ay_[i];
            const double dx = ax_[j] - px, dy = ay_[j] - py;
            const double len2 = dx * dx + dy * dy;
            // moments of the in-between points about a
            const double sxxa = sxx - 2 * px * sx + m * px * px, syya = syy - 2 * py * sy + m * py * py;
            const double sxya = sxy - px * sy - py * sx + m * px * py;
            if (!(len2 > 0)) return std::max(0.0, sxxa + syya);
            // (p - a) x d = dy p'x - dx p'y with p' = p - a, squared and summed
            const double cross2 = dy * dy * sxxa + dx * dx * syya - 2 * dx * dy * sxya;
            return std::max(0.0, cross2 / len2);
        }

        //! Least sum of squared orthogonal distances of points i+1..j-1 to any line (their TLS error; 0 for fewer
        //! than 3): a lower bound of chordCost(i, j) that never falls as i falls, which stops the programme's scans.
        [[nodiscard]] double lineBound(std::size_t i, std::size_t j) const
        {
            if (j <= i + 3) return 0.0;
            const double *a = &sums_[5 * (i + 1)], *b = &sums_[5 * j];
            const double m = static_cast<double>(j - i - 1);
            const double sx = b[0] - a[0], sy = b[1] - a[1];
            const double mx = sx / m, my = sy / m;
            const double sxx = (b[2] - a[2]) - sx * mx, sxy = (b[3] - a[3]) - sx * my, syy = (b[4] - a[4]) - sy * my;
            const double h = 0.5 * (sxx - syy);
            // slightly shrunk, so that rounding never makes the bound exceed the chord cost it bounds
            return std::max(0.0, 0.5 * (sxx + syy) - std::sqrt(h * h + sxy * sxy)) * (1 - 1e-9);
        }

        //! Runs the programme for k = 1..maxK segments (capped at n - 1). Afterwards cost(k) is the optimum and
        //! vertices(k) its k + 1 point indices.
        void solve(std::size_t maxK)
        {
            const std::size_t n = n_;
            K_ = n >= 2 ? std::min(maxK, n - 1) : 0;
            // costs_[j * n + i] = chord(i, j), contiguous in i for the inner loop below, filled on first use: column j
            // holds the chords from low_[j] up to j - 1 (the scans run downward from j - 1 and stop early, so most of
            // the table is never needed when maxK is small).
            costs_.resize(n * n);
            low_.assign(n, 0);
            for (std::size_t j = 0; j < n; ++j) low_[j] = j;
            best_.assign((K_ + 1) * n, kInf);
            from_.assign((K_ + 1) * n, 0);
            if (n == 0) return;
            best_[0] = 0;
            if (skip_ > 0)
                for (std::size_t i = 1; i < n; ++i) best_[i] = static_cast<double>(i) * skip_;
            for (std::size_t k = 1; k <= K_; ++k)
            {
                const double *prev = &best_[(k - 1) * n];
                double *cur = &best_[k * n];
                std::uint32_t *arg = &from_[k * n];
                const std::size_t lo = k - 1;   // row k - 1 is finite from index k - 1 on
                if (k == 1 && !(skip_ > 0))
                {
                    // from the chain's first point only
                    for (std::size_t j = 1; j < n; ++j) { cur[j] = chordCost(0, j); arg[j] = 0; }
                    continue;
                }
                for (std::size_t j = k; j < n; ++j)
                {
                    double *c = &costs_[j * n];
                    std::size_t &filled = low_[j];
                    double m = kInf;
                    std::size_t at = j - 1;
                    // Last chord from i, scanned from the shortest: once the TLS error of the points it spans (which
                    // only grows as i falls) reaches the best total, no earlier i can win. Exact; the bound (a square
                    // root) is tested every 8th chord only, which stops the scan at most 7 chords later.
                    for (std::size_t i = j; i-- > lo;)
                    {
                        if (((j - i) & 7) == 0 && m < kInf && lineBound(i, j) >= m) break;
                        if (!(prev[i] < m)) continue;   // no better through i (or row k - 1 has no polyline to i)
                        while (filled > i) { --filled; c[filled] = chordCost(filled, j); }   // keeps the column contiguous
                        const double v = prev[i] + c[i];
                        if (v < m) { m = v; at = i; }
                    }
                    cur[j] = m;
                    arg[j] = static_cast<std::uint32_t>(at);
                }
            }
            end_.assign(K_ + 1, n - 1);
            total_.assign(K_ + 1, kInf);
            for (std::size_t k = 1; k <= K_; ++k)
            {
                const double *row = &best_[k * n];
                total_[k] = row[n - 1];
                if (skip_ > 0)
                    for (std::size_t j = k; j + 1 < n; ++j)
                    {
                        const double v = row[j] + static_cast<double>(n - 1 - j) * skip_;
                        if (v < total_[k]) { total_[k] = v; end_[k] = j; }
                    }
            }
        }

        [[nodiscard]] std::size_t maxSegments() const { return K_; }
        //! Optimum with k segments (1 <= k <= maxSegments()), the left-out end points' cost included.
        [[nodiscard]] double cost(std::size_t k) const { return k >= 1 && k <= K_ ? total_[k] : kInf; }

        //! The k + 1 vertex indices of cost(k)'s polyline, increasing, into `out` (its memory reused).
        void vertices(std::size_t k, std::vector<std::size_t> &out) const
        {
            out.resize(k + 1);
            std::size_t j = end_[k];
            out[k] = j;
            for (std::size_t s = k; s > 0; --s)
            {
                j = from_[s * n_ + j];
                out[s - 1] = j;
            }
        }

    private:
        static constexpr double kInf = std::numeric_limits<double>::infinity();

        std::size_t n_ = 0, K_ = 0;
        double x0_ = 0, y0_ = 0, skip_ = 0;
        std::vector<double> ax_, ay_, sums_, costs_, best_, total_;
        std::vector<std::size_t> end_, low_;
        std::vector<std::uint32_t> from_;
    };
}
