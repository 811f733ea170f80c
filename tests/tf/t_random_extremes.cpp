// random() and the vector/axis/quaternion constructors with elements near the limits of the element type
// (RigidTf2D<float>::random() with elements near +-1e30 gave a NaN rotation matrix, because the cross and dot
// products of the raw elements overflow; 3D and N-D silently gave the identity because the squared norm overflows).
// A rotation depends only on the directions of its vectors, so scaling every drawn element by any factor must give
// the same rotation as the unscaled draws.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "rtl/Core.h"
#include "rtl/Transformation.h"
#include "rtl/tf/Transformation2D.h"
#include "rtl/tf/Transformation3D.h"

namespace
{
    //! Uniform draws in [-1, 1) times `scale`, from a fixed seed: the same sequence at every scale.
    struct ScaledGen
    {
        mutable std::mt19937 rng;
        double scale;
        ScaledGen(unsigned seed, double s) : rng(seed), scale(s) {}
        double operator()() const { return scale * std::uniform_real_distribution<double>(-1, 1)(rng); }
    };

    template<class M>
    void expectRotation(const M &m, double tol)
    {
        ASSERT_TRUE(m.allFinite()) << m;
        const auto d = m.template cast<double>();
        EXPECT_LE((d.transpose() * d - decltype(d * d)::Identity()).cwiseAbs().maxCoeff(), tol) << d;
        EXPECT_NEAR(d.determinant(), 1.0, tol);
    }

    template<class T>
    void checkScaleInvariance(double scale, double tol)
    {
        for (unsigned seed = 1; seed <= 200; ++seed)
        {
            const auto r = T::random(ScaledGen(seed, scale)).rotMat().data();
            const auto ref = T::random(ScaledGen(seed, 1.0)).rotMat().data();
            expectRotation(r, tol);
            ASSERT_LE((r - ref).cwiseAbs().maxCoeff(), tol) << "seed " << seed << ", scale " << scale << "\n" << r;
        }
    }
}

TEST(RandomExtremes, FloatRotationsFromHugeAndTinyElements)
{
    for (double scale : {1e30, -1e30, 3e37, 1e20, 1e-30, 1e-38})
    {
        SCOPED_TRACE(scale);
        checkScaleInvariance<rtl::RigidTf2f>(scale, 2e-5);
        checkScaleInvariance<rtl::Rotation2f>(scale, 2e-5);
        checkScaleInvariance<rtl::RigidTf3f>(scale, 2e-5);
        checkScaleInvariance<rtl::RotationND<4, float>>(scale, 2e-5);
        checkScaleInvariance<rtl::RigidTfND<5, float>>(scale, 2e-5);
    }
}

TEST(RandomExtremes, DoubleRotationsFromHugeAndTinyElements)
{
    for (double scale : {1e200, 1e300, 1e-200, 1e-300})
    {
        SCOPED_TRACE(scale);
        checkScaleInvariance<rtl::RigidTf2d>(scale, 1e-12);
        checkScaleInvariance<rtl::RigidTf3d>(scale, 1e-12);
        checkScaleInvariance<rtl::RigidTfND<4, double>>(scale, 1e-12);
    }
}

TEST(RandomExtremes, TranslationsKeepTheDrawnElements)
{
    const auto t = rtl::RigidTf2f::random(ScaledGen(7, 1e30));
    ScaledGen g(7, 1e30);
    for (int i = 0; i < 4; ++i)
        g();   // the rotation's two vectors come first
    EXPECT_EQ(t.trVec().x(), static_cast<float>(g()));
    EXPECT_EQ(t.trVec().y(), static_cast<float>(g()));
}

TEST(RandomExtremes, AxesAndQuaternionsNearTheLimits)
{
    for (float s : {1e30f, 1e-30f, 3e38f})
    {
        SCOPED_TRACE(s);
        const rtl::Rotation3f aa(0.5f, rtl::Vector3f(s, 0, 0));   // about x by 0.5 rad
        expectRotation(aa.rotMat().data(), 1e-6);
        EXPECT_NEAR(aa.rotMat().data()(1, 1), std::cos(0.5f), 1e-6f);
        EXPECT_NEAR(aa.rotAxis().x(), 1.0f, 1e-6f);
        const rtl::Rotation3f two(rtl::Vector3f(s, 0, 0), rtl::Vector3f(0, s, 0));   // x -> y: 90 degrees about z
        EXPECT_NEAR(two.rotMat().data()(1, 0), 1.0f, 1e-6f);
        EXPECT_NEAR(two.rotAngle(), static_cast<float>(M_PI / 2), 1e-6f);
        const rtl::Rotation3f q(rtl::Quaternion<float>(s, 0, 0, s));   // 90 degrees about z
        EXPECT_NEAR(q.rotMat().data()(1, 0), 1.0f, 1e-6f);
        const rtl::Rotation2f r2(rtl::Vector2f(s, 0), rtl::Vector2f(-s, s));   // 135 degrees
        EXPECT_NEAR(r2.rotAngle(), static_cast<float>(3 * M_PI / 4), 1e-6f);
        const rtl::Transformation3D<float> t3(0.5f, rtl::Vector3f(0, 0, s), rtl::Vector3f(1, 2, 3));
        EXPECT_NEAR(t3.rotAngle(), 0.5f, 1e-6f);
        EXPECT_NEAR(t3.rotAxis().z(), 1.0f, 1e-6f);
        const rtl::Transformation3D<float> tq(rtl::Quaternion<float>(s, 0, s, 0), rtl::Vector3f(0, 0, 0));
        EXPECT_NEAR(tq.rotAngle(), static_cast<float>(M_PI / 2), 1e-6f);
    }
    // Transformation3D::random draws its axis from the element generator: huge elements, same rotation.
    ScaledGen ang1(3, 1.0), ang2(3, 1.0);
    const auto a = rtl::Transformation3D<float>::random(ang1, ScaledGen(5, 1e30));
    const auto b = rtl::Transformation3D<float>::random(ang2, ScaledGen(5, 1.0));
    EXPECT_LE((a.rotMat().data() - b.rotMat().data()).cwiseAbs().maxCoeff(), 1e-6f);
    // Degenerate input keeps its documented result: zero or non-finite vectors give the identity.
    EXPECT_EQ(rtl::Rotation2f(rtl::Vector2f(0, 0), rtl::Vector2f(1, 0)).rotMat().data(), Eigen::Matrix2f::Identity());
    EXPECT_EQ(rtl::Rotation2f(rtl::Vector2f(INFINITY, 0), rtl::Vector2f(1, 1)).rotMat().data(), Eigen::Matrix2f::Identity());
    EXPECT_EQ(rtl::Rotation3f(rtl::Vector3f(0, 0, 0), rtl::Vector3f(1, 0, 0)).rotMat().data(), Eigen::Matrix3f::Identity());
    EXPECT_EQ((rtl::RotationND<4, float>(rtl::VectorND<4, float>(NAN, 0, 0, 0), rtl::VectorND<4, float>(1, 0, 0, 0))
                       .rotMat().data()),
              (Eigen::Matrix4f::Identity()));
}
