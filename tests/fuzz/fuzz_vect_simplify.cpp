// libFuzzer harness for the point-elimination vectorizers (Douglas-Peucker with line and segment distance,
// Reumann-Witkam), incremental TLS and simplifyCompatibleIndices, 2D / 3D, float / double. Input: byte 0 picks the
// type; byte 1 the epsilon (mantissa and exponent); byte 2 the coordinate scale (a power of two) or, with its top
// bit, raw coordinates (any bit pattern: NaN, inf, huge); then the points. Checked:
// - DP, RW: kept indices ascending, first and last kept, non-finite points never kept (DP), output finite for
//   finite input, each segment's direction the unit vector along it (however short or long; coincident end points
//   the first base vector); for finite input, equality with a brute-force long-double model of the documented rule whenever
//   the model decides the same at epsilon -+ a rounding margin (no near-tie);
// - simplifyCompatibleIndices: equal to a recursive transcription of simplify-js on doubles (no near-tie needed:
//   same arithmetic), std::invalid_argument exactly for non-finite input;
// - ITLS 2D/3D: true only for finite input, ranges consecutive with >= 2 points each, every range's mean squared
//   residual (long double) within sigma^2 up to rounding, finite segments.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <vector>

#include <Eigen/Eigenvalues>

#include "rtl/Vectorization.h"
#include "fuzz_common.h"

namespace
{
    using fuzz::Bytes;
    using fuzz::require;

    //! A segment's direction is the unit vector along end - beg (long double, rescaled so that subnormal and huge
    //! differences count), or the first base vector for coincident end points (the documented degenerate case).
    template<int d, typename T>
    bool directionAlong(const rtl::LineSegmentND<d, T> &s)
    {
        long double diff[d], m = 0, len2 = 0;
        for (int k = 0; k < d; ++k)
        {
            diff[k] = (long double)s.end()[k] - (long double)s.beg()[k];
            m = std::max(m, std::abs(diff[k]));
        }
        const auto dir = s.direction();
        if (m == 0)
        {
            for (int k = 0; k < d; ++k) if (dir[k] != (k == 0 ? T(1) : T(0))) return false;
            return true;
        }
        for (int k = 0; k < d; ++k) len2 += (diff[k] / m) * (diff[k] / m);
        const long double tol = sizeof(T) == 4 ? 1e-5L : 1e-13L;
        for (int k = 0; k < d; ++k)
            if (std::abs((long double)dir[k] - diff[k] / m / std::sqrt(len2)) > tol) return false;
        return true;
    }

    using LD = long double;

    template<int d, typename T>
    bool finite(const rtl::VectorND<d, T> &v)
    {
        for (int k = 0; k < d; ++k) if (!std::isfinite(v[k])) return false;
        return true;
    }

    //! Squared distance of p from line (segment) a-b in long double; a == b: from a.
    template<int d, typename T>
    LD dist2(const rtl::VectorND<d, T> &p, const rtl::VectorND<d, T> &a, const rtl::VectorND<d, T> &b, bool segment)
    {
        LD u[d], v[d], uu = 0, vu = 0;
        for (int k = 0; k < d; ++k)
        {
            u[k] = (LD)b[k] - (LD)a[k];
            v[k] = (LD)p[k] - (LD)a[k];
            uu += u[k] * u[k];
            vu += u[k] * v[k];
        }
        LD t = uu > 0 ? vu / uu : 0;
        if (segment) t = t < 0 ? 0 : (t > 1 ? 1 : t);
        LD r = 0;
        for (int k = 0; k < d; ++k) r += (v[k] - u[k] * t) * (v[k] - u[k] * t);
        return r;
    }

    //! DP in long double. `tied` is set where the documented rule leaves the decision to rounding: another point's
    //! distance within `margin` of the farthest one's (the library, measuring in Element, may pick either), or, for
    //! line distance, a chord shorter than 1e-140 of the chain's extent (documented: such lengths count as 0, so
    //! the library may measure from the first end point instead of the line; found by the 300 s fuzz run).
    template<int d, typename T>
    void dpModel(const std::vector<rtl::VectorND<d, T>> &p, size_t a, size_t b, LD eps, bool seg, LD margin, LD extent, std::vector<char> &keep, bool &tied)
    {
        std::vector<std::pair<size_t, size_t>> st{{a, b}};
        while (!st.empty())
        {
            auto [x, y] = st.back();
            st.pop_back();
            LD best = eps * eps, runner_up = -1;
            size_t far = 0;
            LD uu = 0;
            for (int k = 0; k < d; ++k) uu += ((LD)p[y][k] - (LD)p[x][k]) * ((LD)p[y][k] - (LD)p[x][k]);
            if (!seg && uu > 0 && std::sqrt(uu) < 1e-140L * extent) tied = true;
            for (size_t i = x + 1; i < y; ++i)
            {
                const LD q = dist2(p[i], p[x], p[y], seg);
                if (q > best) { runner_up = far ? best : runner_up; best = q; far = i; }
                else if (q > runner_up) runner_up = q;
            }
            if (far && runner_up >= 0 && std::sqrt(best) - std::sqrt(runner_up) <= margin) tied = true;
            if (far) { keep[far] = 1; st.emplace_back(x, far); st.emplace_back(far, y); }
        }
    }
    template<int d, typename T>
    std::vector<size_t> dpRef(const std::vector<rtl::VectorND<d, T>> &p, LD eps, bool seg, LD margin, LD extent, bool &tied)
    {
        std::vector<char> keep(p.size(), 0);
        keep.front() = keep.back() = 1;
        dpModel(p, 0, p.size() - 1, eps, seg, margin, extent, keep, tied);
        std::vector<size_t> out;
        for (size_t i = 0; i < p.size(); ++i) if (keep[i]) out.push_back(i);
        return out;
    }
    template<int d, typename T>
    std::vector<size_t> rwRef(const std::vector<rtl::VectorND<d, T>> &p, LD eps)
    {
        std::vector<size_t> keys{0};
        size_t k = 0, j = 1;
        while (j < p.size() && p[j] == p[k]) ++j;
        size_t through = j;
        for (size_t i = j + 1; i < p.size(); ++i)
            if (dist2(p[i], p[k], p[through], false) > eps * eps) { k = i - 1; keys.push_back(k); through = i; }
        if (keys.back() != p.size() - 1) keys.push_back(p.size() - 1);
        return keys;
    }

    //! Equal bit for bit (NaN == NaN): segment ends are copies of input points.
    template<int d, typename T>
    bool same(const rtl::VectorND<d, T> &a, const rtl::VectorND<d, T> &b)
    {
        for (int k = 0; k < d; ++k)
        {
            const T x = a[k], y = b[k];
            if (std::memcmp(&x, &y, sizeof(T)) != 0) return false;
        }
        return true;
    }

    //! Indices of the kept points from the output polyline (consecutive segment end points).
    template<int d, typename T, class Seg>
    std::vector<size_t> keysOf(const std::vector<rtl::VectorND<d, T>> &pts, const std::vector<Seg> &segs, bool &ok)
    {
        std::vector<size_t> out;
        size_t i = 0;
        ok = true;
        for (size_t s = 0; s <= segs.size() && !segs.empty(); ++s)
        {
            const auto target = s < segs.size() ? segs[s].beg() : segs.back().end();
            if (s > 0 && s < segs.size()) ok &= same(segs[s - 1].end(), target);
            // The chain's last point ends the last segment; among duplicates of it, the first match would be an
            // earlier one (a harness error, not the library's: found by the brief fuzz pass).
            if (s == segs.size() && i < pts.size() && same(pts.back(), target)) i = pts.size() - 1;
            while (i < pts.size() && !same(pts[i], target)) ++i;
            if (i == pts.size()) { ok = false; return out; }
            out.push_back(i);
            ++i;   // distinct indices, ascending
        }
        if (!out.empty()) --i;
        return out;
    }

    // simplify-js, transcribed recursively on doubles (volatile products: no contraction).
    double mul(double a, double b) { volatile double r = a * b; return r; }
    template<int d>
    double sjsSeg(const double *p, const double *a, const double *b)
    {
        double q[d], dd[d];
        for (int k = 0; k < d; ++k) { q[k] = a[k]; dd[k] = b[k] - a[k]; }
        bool nz = false;
        for (int k = 0; k < d; ++k) nz |= dd[k] != 0;
        if (nz)
        {
            double num = mul(p[0] - q[0], dd[0]), den = mul(dd[0], dd[0]);
            for (int k = 1; k < d; ++k) { num = num + mul(p[k] - q[k], dd[k]); den = den + mul(dd[k], dd[k]); }
            const double t = num / den;
            if (t > 1) for (int k = 0; k < d; ++k) q[k] = b[k];
            else if (t > 0) for (int k = 0; k < d; ++k) q[k] = q[k] + mul(dd[k], t);
        }
        double s = mul(p[0] - q[0], p[0] - q[0]);
        for (int k = 1; k < d; ++k) s = s + mul(p[k] - q[k], p[k] - q[k]);
        return s;
    }
    template<int d>
    void sjsStep(const std::vector<double> &p, size_t first, size_t last, double sq, std::vector<size_t> &out)
    {
        double mx = sq;
        size_t index = 0;
        for (size_t i = first + 1; i < last; ++i)
        {
            const double s = sjsSeg<d>(&p[i * d], &p[first * d], &p[last * d]);
            if (s > mx) { index = i; mx = s; }
        }
        if (mx > sq)
        {
            if (index - first > 1) sjsStep<d>(p, first, index, sq, out);
            out.push_back(index);
            if (last - index > 1) sjsStep<d>(p, index, last, sq, out);
        }
    }
    template<int d>
    std::vector<size_t> sjs(const std::vector<double> &flat, double tol, bool hq)
    {
        const size_t n = flat.size() / d;
        std::vector<size_t> idx;
        for (size_t i = 0; i < n; ++i) idx.push_back(i);
        if (n <= 2) return idx;
        const double sq = tol * tol;
        if (!hq)
        {
            idx = {0};
            size_t prev = 0;
            for (size_t i = 1; i < n; ++i)
            {
                double s = mul(flat[i * d] - flat[prev * d], flat[i * d] - flat[prev * d]);
                for (int k = 1; k < d; ++k) s = s + mul(flat[i * d + k] - flat[prev * d + k], flat[i * d + k] - flat[prev * d + k]);
                if (s > sq) { idx.push_back(i); prev = i; }
            }
            if (prev != n - 1) idx.push_back(n - 1);
        }
        std::vector<double> p;
        for (size_t i : idx) for (int k = 0; k < d; ++k) p.push_back(flat[i * d + k]);
        std::vector<size_t> local{0};
        sjsStep<d>(p, 0, idx.size() - 1, sq, local);
        local.push_back(idx.size() - 1);
        std::vector<size_t> out;
        for (size_t i : local) out.push_back(idx[i]);
        return out;
    }

    template<int d, typename T>
    void run(Bytes in, int eps_code, int scale_code)
    {
        const bool raw = scale_code & 0x80;
        const int max_exp = sizeof(T) == 4 ? 100 : 900;
        const int exp = (scale_code & 0x7f) - 64;
        const double scale = std::ldexp(1.0, exp * max_exp / 64);
        const auto pts = fuzz::readPoints<rtl::VectorND<d, T>, d>(in, raw, scale, 400);
        const size_t n = pts.size();
        const T eps = static_cast<T>((1 + (eps_code & 7)) * std::ldexp(1.0, ((eps_code >> 3) - 16) * max_exp / 16) * (raw ? 1 : scale * 64));
        bool all_finite = true, keep_going = true;
        LD extent = 0;
        for (const auto &p : pts)
        {
            all_finite &= finite(p);
            for (int k = 0; k < d; ++k) if (std::isfinite(p[k])) extent = std::max(extent, std::abs((LD)p[k]));
        }
        // Rounding margin of the library's arithmetic (Element differences and products), as a distance.
        const LD ulp = sizeof(T) == 4 ? 1e-6L : 1e-14L;
        const LD margin = ulp * (LD)std::abs(eps) + 16 * ulp * extent;
        const LD e = std::abs((LD)eps);
        bool duplicates = false;
        {
            std::vector<std::vector<LD>> sorted;
            for (const auto &p : pts) { std::vector<LD> c; for (int k = 0; k < d; ++k) c.push_back((LD)p[k]); sorted.push_back(c); }
            std::sort(sorted.begin(), sorted.end());
            for (size_t i = 1; i < sorted.size(); ++i) duplicates |= sorted[i] == sorted[i - 1];
        }
        if (n >= 2 && std::isfinite(eps))
            for (int algo = 0; algo < 3 && keep_going; ++algo)
            {
                std::vector<rtl::LineSegmentND<d, T>> segs;
                std::vector<size_t> model_lo, model_hi;
                bool tied = false;   // DP: a farthest point within rounding of another (found by the brief pass)
                if (algo < 2)
                {
                    rtl::VectorizerDouglasPeuckerND<d, T> dp(eps);
                    if (algo == 1) dp.setDistance(rtl::DpDistance::Segment);
                    dp(pts, segs);
                    if (all_finite)
                    {
                        model_lo = dpRef(pts, e > margin ? e - margin : 0, algo == 1, margin, extent, tied);
                        model_hi = dpRef(pts, e + margin, algo == 1, margin, extent, tied);
                    }
                }
                else
                {
                    rtl::VectorizerReumannWitkamND<d, T> rw(eps);
                    rw(pts, segs);
                    if (all_finite)
                    {
                        model_lo = rwRef(pts, e > margin ? e - margin : 0);
                        model_hi = rwRef(pts, e + margin);
                    }
                }
                bool ok = true;
                const auto keys = keysOf(pts, segs, ok);
                require(ok);
                require(keys.size() >= 2 && keys.front() == 0 && keys.back() == n - 1);
                for (size_t q = 1; q < keys.size(); ++q) require(keys[q] > keys[q - 1]);
                if (algo < 2)
                    for (size_t q = 1; q + 1 < keys.size(); ++q) require(finite(pts[keys[q]]));
                if (all_finite)
                {
                    for (const auto &s : segs) require(finite(s.beg()) && finite(s.end()) && directionAlong(s));
                    // Compared as vertex sequences: with duplicate points the indices matched back are ambiguous.
                    bool same = keys.size() == model_lo.size();
                    for (size_t q = 0; same && q < keys.size(); ++q) same = pts[keys[q]] == pts[model_lo[q]];
                    // At epsilon within rounding of 0 the decisions are the library's rounding: no model to compare.
                    if (e > 2 * margin && model_lo == model_hi && !tied && !same)
                    {
                        size_t q = 0;
                        while (q < keys.size() && q < model_lo.size() && pts[keys[q]] == pts[model_lo[q]]) ++q;
                        std::fprintf(stderr, "algorithm %d (0 DP, 1 DP segment, 2 RW), %zu points, eps %g: kept[%zu] = %zu, model %zu\n", algo, n,
                                     static_cast<double>(eps), q, q < keys.size() ? keys[q] : n, q < model_lo.size() ? model_lo[q] : n);
                        require(false);
                    }
                    if (algo < 2 && !duplicates)   // every dropped point within eps (+ margin) of its chord
                        for (size_t q = 0; q + 1 < keys.size(); ++q)
                            for (size_t i = keys[q] + 1; i < keys[q + 1]; ++i)
                                require(std::sqrt(dist2(pts[i], pts[keys[q]], pts[keys[q + 1]], algo == 1)) <= e + 2 * margin);
                }
            }
        // simplifyCompatibleIndices on the same coordinates.
        std::vector<T> flat;
        std::vector<double> flatd;
        for (const auto &p : pts) for (int k = 0; k < d; ++k) { flat.push_back(p[k]); flatd.push_back(static_cast<double>(p[k])); }
        for (bool hq : {false, true})
        {
            bool threw = false;
            std::vector<size_t> got;
            try { got = rtl::simplifyCompatibleIndices(flat.data(), n, d, eps, hq); }
            catch (const std::invalid_argument &) { threw = true; }
            require(threw == (!all_finite || std::isnan(eps)));
            if (!threw) require(got == sjs<d>(flatd, static_cast<double>(eps), hq));
        }
        // Incremental TLS.
        if constexpr (true)
        {
            using Vz = std::conditional_t<d == 2, rtl::VectorizerITLSProjections2D<T, double>, rtl::VectorizerITLSProjections3D<T, double>>;
            Vz itls;
            const T sigma = static_cast<T>(std::abs(eps) / 4);
            itls.setSigma(sigma);
            const bool ok = itls(pts);
            const bool valid = n >= 2 && all_finite && sigma > 0 && std::isfinite(sigma);
            if (!valid) require(!ok);
            if (ok)
            {
                const auto &idx = itls.indices();
                size_t prev_end = 0;
                for (size_t r = 0; r < idx.size(); ++r)
                {
                    require(idx[r].second <= n && idx[r].second >= idx[r].first + 2);
                    if (r > 0) require(idx[r].first == prev_end);
                    prev_end = idx[r].second;
                    // mean squared residual from the covariance, in long double, of the points divided by the
                    // chain's extent: in units of the extent the eigenvalues neither underflow nor overflow a double
                    // (raw coordinates near 1e-159 have squares below the smallest double: the solver's rounding
                    // then exceeded a tolerance that had underflowed to 0, for a 2-point range that fits exactly)
                    const size_t m = idx[r].second - idx[r].first;
                    const LD unit = extent > 0 ? extent : 1;
                    LD c[d] = {};
                    for (size_t i = idx[r].first; i < idx[r].second; ++i) for (int k = 0; k < d; ++k) c[k] += pts[i][k] / unit;
                    for (int k = 0; k < d; ++k) c[k] /= m;
                    Eigen::Matrix<double, d, d> cov = Eigen::Matrix<double, d, d>::Zero();
                    for (size_t i = idx[r].first; i < idx[r].second; ++i)
                        for (int a = 0; a < d; ++a) for (int b = 0; b < d; ++b)
                            cov(a, b) += static_cast<double>(((LD)pts[i][a] / unit - c[a]) * ((LD)pts[i][b] / unit - c[b]) / m);
                    Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, d, d>> es(cov);
                    const double err = d == 2 ? es.eigenvalues()(0) : es.eigenvalues()(0) + es.eigenvalues()(1);
                    const double s2 = static_cast<double>((LD)sigma / unit * ((LD)sigma / unit));
                    require(err <= s2 * (1 + 1e-3) + 1e-9);
                }
                for (const auto &s : itls.lineSegments()) require(finite(s.beg()) && finite(s.end()));
            }
        }
    }
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    Bytes in{data, size};
    const int type = in.next() & 3, eps_code = in.next(), scale_code = in.next();
    switch (type)
    {
    case 0: run<2, float>(in, eps_code, scale_code); break;
    case 1: run<2, double>(in, eps_code, scale_code); break;
    case 2: run<3, float>(in, eps_code, scale_code); break;
    default: run<3, double>(in, eps_code, scale_code); break;
    }
    return 0;
}
