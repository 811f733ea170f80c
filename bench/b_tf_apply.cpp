// Applying a RigidTfND<3, float> to 1M points, against a hand-written Eigen Isometry3f loop in the same run
// (goal: within 1.1x of it). A second baseline is the plain Eigen loop R * v + t (Matrix3f, Vector3f), which is what
// RigidTfND computes. Extra rows: the in-place form, a GeneralTf (run-time dispatch per point) and a squashed TfChain.
//
// The machines are shared and loaded: the cases are timed in interleaved rounds (one run of every case per round)
// and each case reports its median, so that load changes hit all cases alike.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <list>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include "bench_util.h"
#include "rtl/Core.h"
#include "rtl/Transformation.h"

namespace
{
    struct Case
    {
        std::string name;
        std::function<void()> run;
        std::vector<double> seconds;
    };

    double median(std::vector<double> v)
    {
        std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
        return v[v.size() / 2];
    }

    void runInterleaved(std::vector<Case> &cases, int rounds)
    {
        for (Case &c : cases)
            c.run();    // warm-up: page in every buffer
        for (int r = 0; r < rounds; ++r)
            for (Case &c : cases)
            {
                const auto start = std::chrono::steady_clock::now();
                c.run();
                c.seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
            }
    }
}

int main(int argc, char **argv)
{
    const auto opt = rtl::bench::parseOptions(argc, argv);
    const size_t n = opt.smoke ? 1000 : 1000000;

    std::mt19937 rng(1);
    std::uniform_real_distribution<float> u(-10.f, 10.f);
    std::vector<Eigen::Vector3f> eig_in(n), eig_out(n), eig_out2(n);
    std::vector<rtl::Vector3f> rtl_in(n), rtl_out(n), rtl_out2(n), rtl_out3(n);
    for (size_t i = 0; i < n; ++i)
    {
        eig_in[i] = Eigen::Vector3f(u(rng), u(rng), u(rng));
        rtl_in[i] = rtl::Vector3f(eig_in[i]);
    }
    std::vector<rtl::Vector3f> inplace = rtl_in;

    const rtl::RigidTf3f tf(0.7f, rtl::Vector3f(1.f, 2.f, 3.f), rtl::Vector3f(0.5f, -1.f, 2.f));
    Eigen::Isometry3f iso = Eigen::Isometry3f::Identity();
    iso.linear() = tf.rotMat().data();
    iso.translation() = tf.trVec().data();
    const Eigen::Matrix3f rot_m = tf.rotMat().data();
    const Eigen::Vector3f tr_v = tf.trVec().data();

    using GTf = rtl::GeneralTf<rtl::Translation3f, rtl::Rotation3f, rtl::RigidTf3f>;
    const GTf gtf(tf);
    const rtl::TfChain<rtl::RigidTf3f> chain(std::list<rtl::RigidTf3f>{tf, tf.inverted(), tf});
    const rtl::RigidTf3f squashed = chain.squash();

    std::vector<Case> cases;
    cases.push_back({"Eigen Isometry3f * v (baseline)", [&] {
        for (size_t i = 0; i < n; ++i)
            eig_out[i] = iso * eig_in[i];
        rtl::bench::doNotOptimize(eig_out.data());
    }, {}});
    cases.push_back({"Eigen R * v + t (second baseline)", [&] {
        for (size_t i = 0; i < n; ++i)
            eig_out2[i] = rot_m * eig_in[i] + tr_v;
        rtl::bench::doNotOptimize(eig_out2.data());
    }, {}});
    cases.push_back({"rtl RigidTf3f tf(v)", [&] {
        for (size_t i = 0; i < n; ++i)
            rtl_out[i] = tf(rtl_in[i]);
        rtl::bench::doNotOptimize(rtl_out.data());
    }, {}});
    cases.push_back({"rtl v.transform(tf) in place", [&] {
        for (size_t i = 0; i < n; ++i)
            inplace[i].transform(tf);
        rtl::bench::doNotOptimize(inplace.data());
    }, {}});
    cases.push_back({"rtl GeneralTf<Tr,Rot,Rigid>(v)", [&] {
        for (size_t i = 0; i < n; ++i)
            rtl_out2[i] = gtf(rtl_in[i]);
        rtl::bench::doNotOptimize(rtl_out2.data());
    }, {}});
    cases.push_back({"rtl TfChain(3 steps).squash() then tf(v)", [&] {
        for (size_t i = 0; i < n; ++i)
            rtl_out3[i] = squashed(rtl_in[i]);
        rtl::bench::doNotOptimize(rtl_out3.data());
    }, {}});

    runInterleaved(cases, opt.repetitions);

    // Results must agree (checked in every mode, including --smoke).
    double worst = 0;
    for (size_t i = 0; i < n; ++i)
    {
        worst = std::max(worst, static_cast<double>((rtl_out[i].data() - eig_out[i]).norm()));
        worst = std::max(worst, static_cast<double>((rtl_out2[i].data() - eig_out[i]).norm()));
        worst = std::max(worst, static_cast<double>((rtl_out3[i].data() - eig_out[i]).norm()));
        worst = std::max(worst, static_cast<double>((eig_out2[i] - eig_out[i]).norm()));
    }

    const double t_iso = median(cases[0].seconds), t_plain = median(cases[1].seconds);
    rtl::bench::printHeader("RigidTfND<3,float> applied to 1M points (ratio: time / Eigen Isometry3f loop)");
    char note[128];
    for (const Case &c : cases)
    {
        const double t = median(c.seconds);
        std::snprintf(note, sizeof note, "%.2fx the plain Eigen R*v+t loop", t / t_plain);
        rtl::bench::printRow(c.name, n, t, t_iso, note);
    }
    std::printf("goal: rtl tf(v) <= 1.10x the Isometry3f loop; max |rtl - Eigen| = %.2e; %d interleaved rounds\n", worst,
                opt.repetitions);

    if (worst > 1e-4)
    {
        std::fprintf(stderr, "rtl and Eigen results differ by %g\n", worst);
        return 1;
    }
    return 0;
}
