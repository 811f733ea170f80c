// Cost of an enabled trace: ITLS, Douglas-Peucker and Reumann-Witkam with a TraceLog (ItlsTraceLog, DpTraceLog,
// RwTraceLog, cleared before each call) against the same vectorizer untraced, in the same run. Setting of
// bench/b_vect_2d.cpp: semicircle r = 8, noise 0.01, 1e5 points, sigma 0.03, epsilon 0.09. Ratio = traced time /
// untraced time; the event count is printed with it.
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "bench_semicircle.h"
#include "bench_util.h"
#include "rtl/Vectorization.h"

namespace
{
    using rtl::bench::semicircle;
    std::string events(size_t count) { return "events=" + std::to_string(count); }
}

int main(int argc, char **argv)
{
    const auto opt = rtl::bench::parseOptions(argc, argv);
    const size_t n = opt.smoke ? 1000 : 100000;
    const auto pts = semicircle(n, 42);
    const int reps = opt.repetitions;

    rtl::VectorizerITLSProjections2D<float, double> itls;
    rtl::VectorizerITLSProjections2D<float, double, rtl::ItlsTraceLog> itlsT;
    rtl::VectorizerDouglasPeucker2f dp(0.09f);
    rtl::VectorizerDouglasPeuckerND<2, float, rtl::DpTraceLog> dpT(0.09f);
    rtl::VectorizerReumannWitkam2f rw(0.09f);
    rtl::VectorizerReumannWitkamND<2, float, rtl::RwTraceLog> rwT(0.09f);
    rtl::ItlsTraceLog itlsLog;
    rtl::DpTraceLog dpLog;
    rtl::RwTraceLog rwLog;
    itls.setSigma(0.03f); itlsT.setSigma(0.03f);
    itls.setMaxSize(n); itlsT.setMaxSize(n); dp.setMaxSize(n); dpT.setMaxSize(n); rw.setMaxSize(n); rwT.setMaxSize(n);
    itlsT.setObserver(&itlsLog); dpT.setObserver(&dpLog); rwT.setObserver(&rwLog);
    std::vector<rtl::LineSegment2f> out;
    out.reserve(n);

    bool ok = true;
    const double t_itls = rtl::bench::medianSeconds([&] { ok &= itls(pts); }, reps);
    const double t_itlsT = rtl::bench::medianSeconds([&] { itlsLog.clear(); ok &= itlsT(pts); }, reps);
    const double t_dp = rtl::bench::medianSeconds([&] { dp(pts, out); }, reps);
    const double t_dpT = rtl::bench::medianSeconds([&] { dpLog.clear(); dpT(pts, out); }, reps);
    const double t_rw = rtl::bench::medianSeconds([&] { rw(pts, out); }, reps);
    const double t_rwT = rtl::bench::medianSeconds([&] { rwLog.clear(); rwT(pts, out); }, reps);

    rtl::bench::printHeader(("enabled TraceLog vs untraced (ratio), 2D semicircle r=8, noise 0.01, " + std::to_string(n) + " points").c_str());
    rtl::bench::printRow("incremental TLS sigma 0.03 (untraced)", n, t_itls, t_itls);
    rtl::bench::printRow("incremental TLS sigma 0.03 + ItlsTraceLog", n, t_itlsT, t_itls, events(itlsLog.size()));
    rtl::bench::printRow("Douglas-Peucker eps 0.09 (untraced)", n, t_dp, t_dp);
    rtl::bench::printRow("Douglas-Peucker eps 0.09 + DpTraceLog", n, t_dpT, t_dp, events(dpLog.size()));
    rtl::bench::printRow("Reumann-Witkam eps 0.09 (untraced)", n, t_rw, t_rw);
    rtl::bench::printRow("Reumann-Witkam eps 0.09 + RwTraceLog", n, t_rwT, t_rw, events(rwLog.size()));
    if (!ok)
    {
        std::printf("!! the incremental vectorizer returned false\n");
        return 1;
    }
    return 0;
}
