// libFuzzer harness for the prefix-sum vectorizers: FTLS and AFTLS 2D polylines (strict and split mode), FTLS /
// AFTLS 3D lines and AFTLS 3D planes, float / double. Input: byte 0 picks the vectorizer (bits 0-2), split mode
// (bit 3; 3D AFTLS: planes instead of lines), runs of repeated points (bit 4: each point is followed by a byte, the
// number of further copies of it) and extreme parameters (bit 5: sigma and delta anywhere in the element type's
// range, subnormal and huge included, instead of relative to the coordinate scale); byte 1 sigma and byte 2 delta
// (mantissa and exponent); byte 3 the coordinate scale (a power of two) or, with its top bit, raw coordinates (any
// bit pattern: NaN, inf, subnormal, huge); then the points (at most max_points = 600; 1,600 with runs). Checked
// (what the API documents):
// - false for fewer than 2 points, a non-finite point, sigma or delta not positive and finite;
// - strict mode true: indices() partition [0, N) in order, >= 2 points each, every range's mean squared residual
//   (long double) below sigma^2 up to rounding, one polyline of segments + 1 finite vertices, and every vertex
//   (a crossing) within delta of its corner's boundary midpoint up to rounding; AFTLS's total squared error never
//   above FTLS's on the same input; split mode: ranges in order, adjoining or sharing one point, true for every
//   valid input at moderate coordinates, polylineOffsets consistent with breaks();
// - 3D: a partition whose ranges fit sigma, finite segments or polygons and finite errSquared() (a result the
//   element type cannot hold is rejected);
// - linear work where every range fits: a chain that one range fits (a run of identical points, or any chain
//   that fits sigma with a margin at moderate coordinates) costs the exact search at most 4 N + 64 fits;
// - the work budget (deterministic, not a time): the exact search's corner work stays within a log factor of its
//   fits (testing every incoming line against every candidate range broke this once), the search
//   runs at most once per FTLS call and once per AFTLS call (both branches share it), and at moderate coordinates
//   its states stay within what PartitionSearch2D guarantees: each round pushes every fitting range at most once
//   (F of them, counted here in long double), the first round stops past 2 N + 1024 states, then at most two
//   bounded rounds, the backward pass (F ranges), at most two rounds on its bound (each stopping past
//   5 N + 1024), the unbounded round (the first one continued) and one split round, so at most 12 N + 3072 + 5 F. F itself is up to N x the
//   longest range that fits sigma (the cliff that remains, see PartitionSearch2D.h); inputs are capped at 600
//   points, so that it stays within the time limit under the sanitizers.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <vector>

#include <Eigen/Eigenvalues>

#include "rtl/Vectorization.h"
#include "fuzz_common.h"

namespace
{
    using fuzz::Bytes;
    using fuzz::require;
    using LD = long double;

    template<int d, typename T>
    bool finite(const rtl::VectorND<d, T> &v)
    {
        for (int k = 0; k < d; ++k) if (!std::isfinite(v[k])) return false;
        return true;
    }

    //! Mean squared orthogonal residual of points [b, e) in long double (2D: minor eigenvalue; 3D lines: the two
    //! minor ones).
    template<int d, typename T>
    double meanSquared(const std::vector<rtl::VectorND<d, T>> &p, size_t b, size_t e)
    {
        const size_t m = e - b;
        LD c[d] = {};
        for (size_t i = b; i < e; ++i) for (int k = 0; k < d; ++k) c[k] += p[i][k];
        for (int k = 0; k < d; ++k) c[k] /= m;
        Eigen::Matrix<double, d, d> cov = Eigen::Matrix<double, d, d>::Zero();
        for (size_t i = b; i < e; ++i)
            for (int x = 0; x < d; ++x) for (int y = 0; y < d; ++y)
                cov(x, y) += static_cast<double>(((LD)p[i][x] - c[x]) * ((LD)p[i][y] - c[y]) / m);
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, d, d>> es(cov);
        return d == 2 ? es.eigenvalues()(0) : es.eigenvalues()(0) + es.eigenvalues()(1);
    }

    constexpr size_t max_points = 600;
    //! With runs of repeated points (byte 0 bit 4): the cliffs of identical points showed from ~1,000 points on.
    constexpr size_t max_repeated_points = 1600;

    //! A parameter anywhere in T's positive range: (1 + mantissa) * 2^exponent, the exponent spread over the
    //! smallest subnormal (code 0) to the largest binade (float: 2^-149 .. 2^127; double: 2^-1074 .. 2^1023).
    template<typename T>
    T extreme(int code)
    {
        const int lo = sizeof(T) == 4 ? -146 : -1071, hi = sizeof(T) == 4 ? 127 : 1023;
        return static_cast<T>(std::ldexp(static_cast<double>(1 + (code & 7)) / 8, lo + ((code >> 3) * (hi - lo)) / 31));
    }

    template<int d, typename T>
    bool oneRun(const std::vector<rtl::VectorND<d, T>> &p)
    {
        for (const auto &q : p) if (!(q == p.front())) return false;
        return true;
    }

    //! Ranges [b, e) of >= 2 points that fit sigma (2 points, or mean squared orthogonal residual, long double,
    //! below sigma^2 with the same tolerance as the range check below): an upper bound on the states of one round.
    template<typename T>
    size_t fittingRanges(const std::vector<rtl::VectorND<2, T>> &p, double s2, double tol)
    {
        size_t f = 0;
        for (size_t b = 0; b + 2 <= p.size(); ++b)
        {
            LD sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;   // about p[b], against cancellation
            for (size_t e = b; e < p.size(); ++e)
            {
                const LD x = (LD)p[e][0] - p[b][0], y = (LD)p[e][1] - p[b][1];
                sx += x; sy += y; sxx += x * x; sxy += x * y; syy += y * y;
                const size_t m = e + 1 - b;
                if (m < 2) continue;
                if (m == 2) { ++f; continue; }
                const LD a = sxx / m - (sx / m) * (sx / m), c = syy / m - (sy / m) * (sy / m), d = sxy / m - (sx / m) * (sy / m);
                const LD minor = (a + c) / 2 - std::sqrt((a - c) * (a - c) / 4 + d * d);
                f += minor <= (LD)s2 * (1 + 1e-3L) + (LD)tol;
            }
        }
        return f;
    }

    //! Counts the exact-search repairs (method 5) of a call.
    struct Exact
    {
        static constexpr bool enabled = true;
        size_t count = 0;
        template<class E> void operator()(const E &) {}
        void operator()(const rtl::FtlsRepair &r) { count += r.method == rtl::FtlsExactSearch; }
    };
    template<typename T>
    struct Ftls : rtl::VectorizerFTLSPolyline2D<T, double, Exact>
    {
        auto work() const { return this->pipeline.searchWork(); }
    };
    template<typename T>
    struct Aftls : rtl::VectorizerAFTLSPolyline2D<T, double, Exact>
    {
        auto work() const { return this->pipeline.searchWork(); }
    };

    template<class V>
    double totalError(const V &v)
    {
        double s = 0;
        for (const auto &l : v.approximations()) s += static_cast<double>(l.errSquaredCompute()) * static_cast<double>(l.count());
        return s;
    }

    //! One call of a 2D vectorizer with its invariants and work budget; the total squared error if true, else -1.
    template<class V, typename T>
    double check2D(V &v, const std::vector<rtl::VectorND<2, T>> &pts, T sigma, T delta, bool split, bool valid, bool moderate, LD extent)
    {
        Exact exact;
        v.setObserver(&exact);
        v.setSigma(sigma);
        v.setDelta(delta);
        v.setSplitAtInfeasibleCorners(split);
        const auto before = v.work();
        const bool ok = v(pts);
        const auto after = v.work();
        const size_t n = pts.size();
        if (!valid) require(!ok);
        if (split && valid && moderate) require(ok);
        // Work budget: the exact search's corner work within a log factor of its fits (each fit is a candidate
        // range; testing every incoming line against each was the cubic cliff).
        const size_t fits = after.fits - before.fits, lg = 2 + static_cast<size_t>(std::log2(static_cast<double>(n + 1)));
        require(after.corners - before.corners <= 64 * (fits + n) * lg);
        require(exact.count <= 2);
        const size_t states = after.states - before.states;
        if (moderate && states > 2 * n + 1024)
        {
            const double s2 = static_cast<double>(sigma) * static_cast<double>(sigma);
            // The search's sums are in double for float points too.
            require(states <= 12 * n + 3072 + 5 * fittingRanges(pts, s2, 64e-14 * static_cast<double>(extent * extent)));
        }
        // Linear where one range fits: copies of one point (residual exactly 0 whatever the sums' rounding, when
        // sigma^2 is not 0), or at moderate coordinates a chain that fits sigma with a margin.
        if (valid && n >= 2)
        {
            const double s2c = static_cast<double>(sigma) * static_cast<double>(sigma);
            const bool one_fits = (oneRun(pts) && s2c > 0) ||
                                  (moderate && meanSquared(pts, 0, n) < s2c * (1 - 1e-3) - 64e-14 * static_cast<double>(extent * extent));
            if (one_fits) require(fits <= 4 * n + 64);
        }
        const auto &idx = v.indices();
        const auto &off = v.polylineOffsets();
        if (!ok)
        {
            require(idx.empty() && off.size() == 2 && off[0] == 0 && off[1] == 0);
            return -1;
        }
        require(!idx.empty() && idx.front().first == 0 && idx.back().second == n);
        const double s2 = static_cast<double>(sigma) * static_cast<double>(sigma);
        const double ulp = sizeof(T) == 4 ? 1e-6 : 1e-14;
        for (size_t r = 0; r < idx.size(); ++r)
        {
            require(idx[r].second >= idx[r].first + 2);
            if (r > 0)
            {
                if (split) require(idx[r].first == idx[r - 1].second || idx[r].first + 1 == idx[r - 1].second);
                else require(idx[r].first == idx[r - 1].second);
            }
            if (idx[r].second - idx[r].first > 2)
                require(meanSquared(pts, idx[r].first, idx[r].second) <= s2 * (1 + 1e-3) + 64 * ulp * static_cast<double>(extent * extent));
        }
        const auto segs = v.lineSegments();
        const auto &verts = v.vertices();
        require(segs.size() == idx.size() && !off.empty() && off.front() == 0 && off.back() == idx.size());
        require(verts.size() == idx.size() + off.size() - 1);
        require(v.breaks().size() + 2 == off.size());
        for (const auto &x : verts) require(finite(x));
        if (!split)
        {
            require(off.size() == 2);
            // Every inner vertex is the crossing at a corner: within delta of the boundary midpoint.
            for (size_t r = 1; r < idx.size(); ++r)
            {
                const size_t b = idx[r].first;
                const LD mx = ((LD)pts[b - 1][0] + pts[b][0]) / 2, my = ((LD)pts[b - 1][1] + pts[b][1]) / 2;
                const LD dx = (LD)verts[r][0] - mx, dy = (LD)verts[r][1] - my;
                const LD dist = std::sqrt(dx * dx + dy * dy);
                require(dist <= (LD)delta * (1 + 1e-4L) + 1e3L * (LD)ulp * (extent + std::abs((LD)verts[r][0]) + std::abs((LD)verts[r][1])));
            }
        }
        return totalError(v);
    }

    template<typename T>
    void run2D(Bytes in, int mode, int sigma_code, int delta_code, int scale_code)
    {
        const bool raw = scale_code & 0x80, split = mode & 8;
        const int max_exp = sizeof(T) == 4 ? 100 : 900;
        const double scale = std::ldexp(1.0, ((scale_code & 0x7f) - 64) * max_exp / 64);
        const bool runs = mode & 16;
        const auto pts = fuzz::readPoints<rtl::VectorND<2, T>, 2>(in, raw, scale, runs ? max_repeated_points : max_points, runs);
        // sigma and delta: (1 + mantissa) * 2^exponent times the coordinate unit (raw: times 1); extreme: anywhere.
        const double unit = raw ? 1.0 : scale * 64;
        const T sigma = mode & 32 ? extreme<T>(sigma_code) : static_cast<T>((1 + (sigma_code & 7)) * std::ldexp(1.0, (sigma_code >> 3) - 24) * unit);
        const T delta = mode & 32 ? extreme<T>(delta_code) : static_cast<T>((1 + (delta_code & 7)) * std::ldexp(1.0, (delta_code >> 3) - 20) * unit);
        bool all_finite = true;
        LD extent = 0;
        for (const auto &p : pts)
        {
            all_finite &= finite(p);
            for (int k = 0; k < 2; ++k) if (std::isfinite(p[k])) extent = std::max(extent, std::abs((LD)p[k]));
        }
        auto okParam = [](T x) { return x > 0 && std::isfinite(x); };
        const bool valid = pts.size() >= 2 && all_finite && okParam(sigma) && okParam(delta);
        // Moderate: integer coordinates well inside the element type, sigma and delta not sub-normal against them.
        const bool moderate = !raw && !(mode & 32) && std::abs(std::log2(scale)) < (sizeof(T) == 4 ? 40 : 300) && sigma_code >= 40 &&
                              delta_code >= 40;
        if (mode & 2)
        {
            Aftls<T> a;
            const double ea = check2D(a, pts, sigma, delta, split, valid, moderate, extent);
            if (!split)
            {
                Ftls<T> f;
                const double ef = check2D(f, pts, sigma, delta, split, valid, moderate, extent);
                require(ef < 0 || ea >= 0);   // AFTLS keeps FTLS's result when its own fails
                if (ea >= 0 && ef >= 0) require(ea <= ef * (1 + 1e-9) + 1e-300);
            }
        }
        else
        {
            Ftls<T> f;
            check2D(f, pts, sigma, delta, split, valid, moderate, extent);
        }
    }

    //! A 3D vectorizer's output (segments or polygons) finite.
    template<class V>
    auto outputFinite(const V &v) -> decltype(v.lineSegments(), bool())
    {
        for (const auto &s : v.lineSegments()) if (!finite(s.beg()) || !finite(s.end())) return false;
        return v.lineSegments().size() == v.indices().size();
    }
    template<class V>
    auto outputFinite(const V &v) -> decltype(v.polygons(), bool())
    {
        for (const auto &p : v.polygons())
        {
            if (!std::isfinite(p.distance())) return false;
            for (const auto &q : p.points()) if (!finite(q)) return false;
        }
        return v.polygons().size() == v.indices().size();
    }

    template<typename T, bool optimize, bool planes>
    void run3D(Bytes in, int mode, int sigma_code, int scale_code)
    {
        const bool raw = scale_code & 0x80;
        const int max_exp = sizeof(T) == 4 ? 60 : 300;   // squared moments stay finite in double
        const double scale = std::ldexp(1.0, ((scale_code & 0x7f) - 64) * max_exp / 64);
        const bool runs = mode & 16;
        const auto pts = fuzz::readPoints<rtl::VectorND<3, T>, 3>(in, raw, scale, runs ? max_repeated_points : max_points, runs);
        const T sigma = mode & 32 ? extreme<T>(sigma_code)
                                  : static_cast<T>((1 + (sigma_code & 7)) * std::ldexp(1.0, (sigma_code >> 3) - 24) * (raw ? 1.0 : scale * 64));
        LD extent = 0;
        bool all_finite = true;
        for (const auto &p : pts)
        {
            all_finite &= finite(p);
            for (int k = 0; k < 3; ++k) if (std::isfinite(p[k])) extent = std::max(extent, std::abs((LD)p[k]));
        }
        std::conditional_t<planes, rtl::VectorizerAFTLSPlaneProjections3D<T, double>,
                           std::conditional_t<optimize, rtl::VectorizerAFTLSProjections3D<T, double>, rtl::VectorizerFTLSProjections3D<T, double>>> v;
        v.setSigma(sigma);
        const bool ok = v(pts);
        const bool valid = pts.size() >= 2 && all_finite && sigma > 0 && std::isfinite(sigma);
        if (!valid) require(!ok);
        if (!ok)
        {
            require(v.indices().empty() && v.approximations().empty());
            return;
        }
        // What the element type cannot hold is rejected, never returned (float points beyond ~1.8e19).
        for (const auto &a : v.approximations()) require(std::isfinite(a.errSquared()));
        require(outputFinite(v));
        const auto &idx = v.indices();
        require(!idx.empty() && idx.front().first == 0 && idx.back().second == pts.size());
        const double s2 = static_cast<double>(sigma) * static_cast<double>(sigma);
        const double ulp = sizeof(T) == 4 ? 1e-6 : 1e-14;
        for (size_t r = 0; r < idx.size(); ++r)
        {
            require(idx[r].second >= idx[r].first + 2);
            if (r > 0) require(idx[r].first == idx[r - 1].second);
            // The residual model is the lines' (two minor eigenvalues), at coordinates whose squares double holds.
            if (!planes && !raw && idx[r].second - idx[r].first > 2)
                require(meanSquared(pts, idx[r].first, idx[r].second) <= s2 * (1 + 1e-3) + 64 * ulp * static_cast<double>(extent * extent));
        }
    }
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    Bytes in{data, size};
    const int mode = in.next(), sigma_code = in.next(), delta_code = in.next(), scale_code = in.next();
    switch (mode & 7)
    {
    case 0: case 2: run2D<float>(in, mode, sigma_code, delta_code, scale_code); break;
    case 1: case 3: run2D<double>(in, mode, sigma_code, delta_code, scale_code); break;
    case 4: run3D<float, false, false>(in, mode, sigma_code, scale_code); break;
    case 5: run3D<double, false, false>(in, mode, sigma_code, scale_code); break;
    case 6:
        if (mode & 8) run3D<float, true, true>(in, mode, sigma_code, scale_code);
        else run3D<float, true, false>(in, mode, sigma_code, scale_code);
        break;
    default:
        if (mode & 8) run3D<double, true, true>(in, mode, sigma_code, scale_code);
        else run3D<double, true, false>(in, mode, sigma_code, scale_code);
        break;
    }
    return 0;
}
