// Exact best partitions of one chain of points into k contiguous ranges (k = 1..K), each range of >= 2 points and
// costed by its total-least-squares (TLS) error: the sum of squared orthogonal distances to its best-fitting line.
//
// Range costs come in O(1) from prefix sums of x, y, x^2, xy, y^2 (taken about the chain's first point, so that a
// chain far from the origin keeps its precision), all in double. The dynamic programme over prefix lengths,
//   F[k][j] = min over i of F[k-1][i] + cost(points i..j-1),
// gives every k's optimum in one pass: at most O(n^2) range costs (each computed once, when first needed), then at
// most O(K n^2) additions (the scan over the last range stops as soon as that range's own error reaches the best total,
// see solve); O(n^2 + K n) memory.
//
// Optionally (setEndSkipCost) the ranges need not reach the chain's ends: points before the first range and after the
// last are left out at a fixed cost each, so a chain's clutter or curved ends are dropped when a line fits them worse
// than leaving them unexplained. The same programme, started from F[0][i] = i s and ended at min over j of
// F[k][j] + (n - j) s: no extra order of work.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace rtl::scan_polylines
{
    //! A TLS line n . p = d (|n| = 1) of a range, with its centroid and error.
    struct TlsFit
    {
        double nx = 0, ny = 0, d = 0;      //!< unit normal and offset
        double cx = 0, cy = 0;             //!< centroid
        double sse = 0;                    //!< sum of squared orthogonal distances
    };

    class ChainPartition
    {
    public:
        //! Prefix sums of a chain of n points (coordinates finite), each with weight w[i] > 0 (all 1 when w is null):
        //! the range cost is then the weighted TLS error, sum w_i d_i^2 about the weighted best line.
        void load(const double *x, const double *y, std::size_t n, const double *w = nullptr)
        {
            n_ = n;
            x0_ = n ? x[0] : 0; y0_ = n ? y[0] : 0;
            sums_.assign(6 * (n + 1), 0.0);
            for (std::size_t i = 0; i < n; ++i)
            {
                const double a = x[i] - x0_, b = y[i] - y0_, c = w ? w[i] : 1.0;
                const double *p = &sums_[6 * i];
                double *q = &sums_[6 * (i + 1)];
                q[0] = p[0] + c * a; q[1] = p[1] + c * b; q[2] = p[2] + c * a * a; q[3] = p[3] + c * a * b; q[4] = p[4] + c * b * b;
                q[5] = p[5] + c;
            }
        }

        [[nodiscard]] std::size_t size() const { return n_; }

        //! Cost per point left out before the first range or after the last (> 0; 0 or less, the default: ranges
        //! cover the whole chain). Takes effect at the next solve.
        void setEndSkipCost(double s) { skip_ = s; }

        //! TLS error of points first..last (inclusive, last > first).
        [[nodiscard]] double rangeCost(std::size_t first, std::size_t last) const { return rangeCostTo(first, &sums_[6 * (last + 1)]); }

    private:
        //! rangeCost(first, last) given b = &sums_[6 * (last + 1)] (the inner loop of solve keeps b for its column).
        [[nodiscard]] double rangeCostTo(std::size_t first, const double *b) const
        {
            const double *a = &sums_[6 * first];
            const double m = b[5] - a[5];
            const double sx = b[0] - a[0], sy = b[1] - a[1];
            const double mx = sx / m, my = sy / m;
            const double sxx = (b[2] - a[2]) - sx * mx, sxy = (b[3] - a[3]) - sx * my, syy = (b[4] - a[4]) - sy * my;
            const double h = 0.5 * (sxx - syy);
            return std::max(0.0, 0.5 * (sxx + syy) - std::sqrt(h * h + sxy * sxy));
        }

    public:
        //! TLS line of points first..last (inclusive, last > first). Coincident points give an arbitrary normal.
        [[nodiscard]] TlsFit fit(std::size_t first, std::size_t last) const
        {
            double sxx, sxy, syy, mx, my;
            moments(first, last, sxx, sxy, syy, mx, my);
            const double h = 0.5 * (sxx - syy);
            const double root = std::sqrt(h * h + sxy * sxy);
            const double lmin = 0.5 * (sxx + syy) - root;
            // Eigenvector of the smaller eigenvalue: the better conditioned of the two rows of (S - lmin I).
            double nx = sxy, ny = lmin - sxx;
            const double ax = lmin - syy, ay = sxy;
            if (ax * ax + ay * ay > nx * nx + ny * ny) { nx = ax; ny = ay; }
            double len = std::hypot(nx, ny);
            if (!(len > 0)) { nx = 1; ny = 0; len = 1; }
            TlsFit f;
            f.nx = nx / len; f.ny = ny / len;
            f.cx = mx + x0_; f.cy = my + y0_;
            f.d = f.nx * f.cx + f.ny * f.cy;
            f.sse = std::max(0.0, lmin);
            return f;
        }

        //! Runs the programme for k = 1..maxK segments (capped at n / 2). Afterwards cost(k) is the optimum (inf where
        //! no partition into k ranges exists) and ranges(k) its ranges as (first, last) inclusive.
        void solve(std::size_t maxK)
        {
            const std::size_t n = n_;
            K_ = std::min(maxK, n / 2);
            const std::size_t w = n + 1;
            // costs_[j * w + i] = cost of points i..j-1, contiguous in i for the inner loop below, filled on first use:
            // column j holds the ranges from low_[j] up to j - 2 (the scans run downward from j - 2 and stop early, so
            // most of the table is never needed; neither filled nor cleared in advance).
            costs_.resize(w * w);
            low_.resize(w);
            for (std::size_t j = 0; j <= n; ++j) low_[j] = j >= 1 ? j - 1 : 0;
            // Row k >= 1 is read only where it is written below (j >= 2k: a row-k prefix needs 2k points), so only
            // row 0 is initialised: no fill of the whole (K + 1) x (n + 1) tables per chain (they only grow: resizing
            // a shorter chain's tables back up would fill them again).
            if (best_.size() < (K_ + 1) * w) { best_.resize((K_ + 1) * w); from_.resize((K_ + 1) * w); }   // grow only
            best_[0] = 0;
            for (std::size_t i = 1; i <= n; ++i) best_[i] = skip_ > 0 ? static_cast<double>(i) * skip_ : kInf;
            for (std::size_t k = 1; k <= K_; ++k)
            {
                const double *prev = &best_[(k - 1) * w];
                double *cur = &best_[k * w];
                std::uint32_t *arg = &from_[k * w];
                if (k == 1 && !(skip_ > 0))
                {
                    // one range from the chain's first point (the only finite entry of row 0)
                    for (std::size_t j = 2; j <= n; ++j) { cur[j] = rangeCost(0, j - 1); arg[j] = 0; }
                    continue;
                }
                for (std::size_t j = 2 * k; j <= n; ++j)
                {
                    double *c = &costs_[j * w];
                    std::size_t &filled = low_[j];
                    // Last range i..j-1, scanned from the shortest: a longer last range contains a shorter one, so
                    // its TLS error is no smaller (c[i] grows as i falls), and once c[i] alone reaches the best total
                    // no longer range can win. Exact, and it cuts most of the work where the optimum is small.
                    // Two loops: over the entries already in the column, then over new ones, each computed, stored
                    // and tested at once (the same numbers and order as one loop that fills the column on demand,
                    // but with the fill test and the column's fill level out of the loop: 1.4x faster in wasm).
                    const std::size_t lo = 2 * (k - 1), hi = j - 1;
                    double m = kInf;
                    std::size_t at = hi - 1;
                    std::size_t i = hi;
                    const std::size_t known = std::max(filled, lo);
                    bool stopped = false;
                    while (i > known)
                    {
                        --i;
                        const double ci = c[i];
                        if (ci >= m) { stopped = true; break; }
                        const double v = prev[i] + ci;
                        if (v < m) { m = v; at = i; }
                    }
                    if (!stopped)
                    {
                        const double *b = &sums_[6 * j];
                        while (i > lo)
                        {
                            --i;
                            const double ci = rangeCostTo(i, b);
                            c[i] = ci;
                            if (ci >= m) break;
                            const double v = prev[i] + ci;
                            if (v < m) { m = v; at = i; }
                        }
                        if (i < filled) filled = i;
                    }
                    cur[j] = m;
                    arg[j] = static_cast<std::uint32_t>(at);
                }
            }
            // Where the last range ends: the chain's end, or (skipping) wherever the left-out tail costs least.
            end_.assign(K_ + 1, n);
            total_.assign(K_ + 1, kInf);
            for (std::size_t k = 0; k <= K_; ++k)
            {
                const double *row = &best_[k * w];
                total_[k] = row[n];
                if (skip_ > 0)
                    for (std::size_t j = 2 * k; j < n; ++j)
                    {
                        const double v = row[j] + static_cast<double>(n - j) * skip_;
                        if (v < total_[k]) { total_[k] = v; end_[k] = j; }
                    }
            }
        }

        [[nodiscard]] std::size_t maxSegments() const { return K_; }
        //! Optimum with k ranges, the left-out end points' cost included.
        [[nodiscard]] double cost(std::size_t k) const { return k <= K_ ? total_[k] : kInf; }

        [[nodiscard]] std::vector<std::pair<std::size_t, std::size_t>> ranges(std::size_t k) const
        {
            std::vector<std::pair<std::size_t, std::size_t>> out;
            ranges(k, out);
            return out;
        }

        //! ranges(k) into `out` (its memory reused).
        void ranges(std::size_t k, std::vector<std::pair<std::size_t, std::size_t>> &out) const
        {
            out.resize(k);
            std::size_t j = end_[k];
            for (std::size_t s = k; s > 0; --s)
            {
                const std::size_t i = from_[s * (n_ + 1) + j];
                out[s - 1] = {i, j - 1};
                j = i;
            }
        }

    private:
        static constexpr double kInf = std::numeric_limits<double>::infinity();

        void moments(std::size_t first, std::size_t last, double &sxx, double &sxy, double &syy, double &mx, double &my) const
        {
            const double *a = &sums_[6 * first], *b = &sums_[6 * (last + 1)];
            const double m = b[5] - a[5];
            const double sx = b[0] - a[0], sy = b[1] - a[1];
            mx = sx / m; my = sy / m;
            sxx = (b[2] - a[2]) - sx * mx;
            sxy = (b[3] - a[3]) - sx * my;
            syy = (b[4] - a[4]) - sy * my;
        }

        std::size_t n_ = 0, K_ = 0;
        double x0_ = 0, y0_ = 0, skip_ = 0;
        std::vector<std::size_t> end_, low_;
        std::vector<double> total_;
        std::vector<double> sums_, costs_, best_;
        std::vector<std::uint32_t> from_;
    };
}
