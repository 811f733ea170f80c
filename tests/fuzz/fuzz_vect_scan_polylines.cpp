// libFuzzer harness for whole-scan polylines at a vertex budget (rtl::ScanPolylines2D), float / double. The input is
// a range scan, as the class requires (beam directions turning one way): byte 0 picks the options (bit 0 float, bit 1
// the greedy family off, bit 2 its hit-consistent refinement, bit 3 end trimming, bit 4 point candidates on every
// chain, bit 5 two break candidates, bit 6 J's own plan refined only, bit 7 raw ranges); byte 1 the budget J (2 +
// byte); byte 2 the beam step (1 + byte/4 tenths of a degree, the sign of the scan from bit 0 of byte 3) and byte 3
// the unexplained cost and gap (bits 1-7: c = 0.05 * 2^(bits/16)); then one range per beam (at most max_beams):
// a big-endian 16-bit value, 0 for no return, else value / 1000 m; with bit 7 of byte 0, the range's own bytes
// (any bit pattern: NaN, inf, subnormal, huge, negative; a beam whose point is not finite or lies at the origin has
// no return; a negative range turns the beam round, so raw ranges are made positive). Checked (the header's
// contract):
// - false exactly when no beam is returned, with no polylines, NaN score and NaN expected ranges;
// - otherwise: at most J vertices over polylines of >= 2 finite vertices each; expectedRanges() one per beam, NaN for
//   the beams without a return; explainedBeams() the beams with a finite expected range; rmse(), explainedFraction()
//   and score() what those expected ranges give (f RMSE^2 + (1 - f) c^2), to rounding; every segment's line finite,
//   its covariance symmetric with a positive diagonal, never NaN (infinite where the points do not spread along
//   the line or an entry is beyond the element type's range, 0 in float where a variance is below it, as the
//   header says).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "rtl/Vectorization.h"
#include "fuzz_common.h"

namespace
{
    using fuzz::Bytes;
    using fuzz::require;

    constexpr std::size_t max_beams = 400;

    template<typename T>
    void run(Bytes in, std::uint8_t flags)
    {
        const std::size_t J = 2 + in.next();
        const double step = (1 + in.next() / 4.0) * 0.1 * M_PI / 180;
        const std::uint8_t b3 = in.next();
        const double sign = (b3 & 1) ? -1.0 : 1.0;
        const double cost = 0.05 * std::pow(2.0, (b3 >> 1) / 16.0);
        const bool raw = flags & 0x80;
        std::vector<rtl::VectorND<2, T>> beams;
        while (!in.empty() && beams.size() < max_beams)
        {
            double r;
            if (raw)
            {
                unsigned char b[sizeof(T)];
                for (auto &c : b) c = in.next();
                T x;
                std::memcpy(&x, b, sizeof(T));
                r = std::abs(static_cast<double>(x));
            }
            else
            {
                const unsigned v = static_cast<unsigned>(in.next()) << 8 | in.next();
                r = v == 0 ? std::numeric_limits<double>::quiet_NaN() : v / 1000.0;
            }
            const double a = sign * step * static_cast<double>(beams.size()) - sign * M_PI / 2;
            beams.emplace_back(static_cast<T>(r * std::cos(a)), static_cast<T>(r * std::sin(a)));
        }
        rtl::ScanPolylines2D<T> ex;
        ex.setMaxVertices(J);
        ex.setUnexplainedCost(static_cast<T>(cost));
        if (flags & 0x02) ex.setGreedyCandidates(false);
        if (flags & 0x04) ex.setGreedyCandidates(true, 5, rtl::ScanPolylines2D<T>::GreedyRefinement::Consistent);
        if (flags & 0x08) ex.setEndTrimming(true);
        if (flags & 0x10) ex.setPointCandidates(true, 5, 2);
        if (flags & 0x20) ex.setBreakCandidates(2);
        if (flags & 0x40) ex.setRefineEveryBudget(false);

        // what the class counts as a returned beam: a finite point of positive length
        std::vector<bool> returned(beams.size());
        std::size_t n_returned = 0;
        for (std::size_t i = 0; i < beams.size(); ++i)
        {
            const double x = static_cast<double>(beams[i][0]), y = static_cast<double>(beams[i][1]);
            const double len = std::hypot(x, y);
            returned[i] = std::isfinite(len) && len > 0;
            n_returned += returned[i] ? 1 : 0;
        }
        const bool ok = ex(beams);
        require(ok == (n_returned > 0));
        require(ex.expectedRanges().size() == beams.size());
        if (!ok)
        {
            require(ex.polylines().empty() && std::isnan(ex.score()));
            for (T e : ex.expectedRanges()) require(std::isnan(e));
            return;
        }
        std::size_t vertices = 0;
        for (const auto &p : ex.polylines())
        {
            require(p.size() >= 2);
            vertices += p.size();
            for (const auto &v : p) require(std::isfinite(v[0]) && std::isfinite(v[1]));
        }
        require(vertices == ex.vertexCount() && vertices <= J);
        require(ex.returnedBeams() == n_returned);
        // the score from the expected ranges, each beam's measured range as the class sees it (the point's length)
        std::size_t hit = 0;
        double sum = 0;
        for (std::size_t i = 0; i < beams.size(); ++i)
        {
            const double e = static_cast<double>(ex.expectedRanges()[i]);
            if (!returned[i]) { require(std::isnan(e)); continue; }
            if (std::isnan(e)) continue;
            require(std::isfinite(e) && e > 0);
            ++hit;
            const double r = std::hypot(static_cast<double>(beams[i][0]), static_cast<double>(beams[i][1]));
            sum += (r - e) * (r - e);
        }
        require(hit == ex.explainedBeams());
        const double c2 = static_cast<double>(static_cast<T>(cost)) * static_cast<double>(static_cast<T>(cost));
        const double score = (sum + static_cast<double>(n_returned - hit) * c2) / static_cast<double>(n_returned);
        // float expected ranges carry float rounding (relative 6e-8 of each range, so of the squared ranges' scale)
        double mean_r2 = 0;
        for (std::size_t i = 0; i < beams.size(); ++i)
            if (returned[i])
                mean_r2 += (static_cast<double>(beams[i][0]) * beams[i][0] + static_cast<double>(beams[i][1]) * beams[i][1]) / n_returned;
        const double tol = (sizeof(T) == 4 ? 1e-4 : 1e-9) * (score + c2) + (sizeof(T) == 4 ? 1e-6 : 1e-14) * mean_r2 + 1e-12;
        if (std::isfinite(score) && std::isfinite(ex.score())) require(std::abs(ex.score() - score) <= tol);
        for (const auto &s : ex.segments())
        {
            require(std::isfinite(s.r) && std::isfinite(s.theta) && !s.covariance.hasNaN());
            // positive variances (in float a variance below the type's range rounds to 0)
            const T zero = 0;
            require(sizeof(T) == 4 ? s.covariance(0, 0) >= zero && s.covariance(1, 1) >= zero
                                   : s.covariance(0, 0) > zero && s.covariance(1, 1) > zero);
            require(s.covariance(0, 1) == s.covariance(1, 0));
        }
    }
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    Bytes in{data, size};
    const std::uint8_t flags = in.next();
    if (flags & 0x01) run<float>(in, flags);
    else run<double>(in, flags);
    return 0;
}
