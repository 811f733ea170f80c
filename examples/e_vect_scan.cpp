// Vectorizing a real laser scan: a scan of the CSAIL log (361 beams) is cut into chains of consecutive returns
// (split at max-range beams and at jumps over 0.5 m), and each chain becomes a polyline with AFTLS (sigma 3 cm,
// delta 0.5 m). Prints the segments and compares the segment counts of all 2D vectorizers.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "rtl/Vectorization.h"
#include "rtl/io/CarmenLog.h"

int main()
{
    const auto scans = rtl::readCarmenLogFile<float>(std::string(RTL_EXAMPLE_DATA_DIR) + "/csail.log");
    if (scans.empty())
        return 1;
    const auto &scan = scans[scans.size() / 2];

    std::vector<std::vector<rtl::Vector2f>> chains;
    std::vector<rtl::Vector2f> cur;
    const auto flush = [&] {
        if (cur.size() >= 10)
            chains.push_back(cur);
        cur.clear();
    };
    for (const auto &p : scan.points)
    {
        if (p.hasNaN()) { flush(); continue; }                      // max-range beam: no return
        if (!cur.empty() && (p - cur.back()).length() > 0.5f) flush();
        cur.push_back(p);
    }
    flush();
    std::printf("scan at line %zu: %zu beams, %zu chains of >= 10 points\n", scan.line, scan.points.size(), chains.size());

    rtl::VectorizerAFTLSPolyline2D<float, double> aftls;
    aftls.setSigma(0.03f);
    aftls.setDelta(0.5f);
    size_t total = 0;
    for (size_t c = 0; c < chains.size(); ++c)
    {
        if (!aftls(chains[c]))
        {
            // failure(): the corner no partition can meet within delta (strict mode, RTL's behaviour);
            // setSplitAtInfeasibleCorners(true) would break the polyline there instead.
            if (const auto &f = aftls.failure())
                std::printf("chain %zu: no valid polyline (the lines cross %.3f m from boundary %zu, delta %.3f m)\n", c,
                            f->crossingDistance, f->boundary, f->delta);
            else
                std::printf("chain %zu: no valid polyline\n", c);
            continue;
        }
        std::printf("chain %zu (%zu points):\n", c, chains[c].size());
        const auto segments = aftls.lineSegments();
        for (size_t i = 0; i < segments.size(); ++i)
        {
            const auto &r = aftls.indices()[i];
            std::printf("  [%3zu, %3zu)  (%7.3f, %7.3f) -> (%7.3f, %7.3f)  length %.3f m, rms %.4f m\n", r.first, r.second,
                        segments[i].beg().x(), segments[i].beg().y(), segments[i].end().x(), segments[i].end().y(),
                        segments[i].length(), std::sqrt(aftls.approximations()[i].errSquared()));
        }
        total += segments.size();
    }

    // The same chains with the other vectorizers (Douglas-Peucker and Reumann-Witkam with epsilon = 3 sigma).
    rtl::VectorizerFTLSPolyline2D<float, double> ftls;
    rtl::VectorizerITLSProjections2D<float, double> itls;
    rtl::VectorizerDouglasPeucker2f dp(0.09f);
    rtl::VectorizerReumannWitkam2f rw(0.09f);
    ftls.setSigma(0.03f);
    ftls.setDelta(0.5f);
    itls.setSigma(0.03f);
    size_t n_ftls = 0, n_itls = 0, n_dp = 0, n_rw = 0;
    std::vector<rtl::LineSegment2f> out;
    for (const auto &c : chains)
    {
        if (ftls(c)) n_ftls += ftls.indices().size();
        if (itls(c)) n_itls += itls.indices().size();
        dp(c, out);
        n_dp += out.size();
        rw(c, out);
        n_rw += out.size();
    }
    std::printf("segments: AFTLS %zu, FTLS %zu, incremental %zu, Douglas-Peucker %zu, Reumann-Witkam %zu\n", total, n_ftls,
                n_itls, n_dp, n_rw);
    return total > 0 ? 0 : 1;
}
