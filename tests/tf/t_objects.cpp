// Applying transformations to Core objects equals applying them to the objects' points, the transformation columns of
// the Core trait table (docs/reference.md, "Type traits"), and the legacy Transformation2D/3D (not in the umbrella
// header).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

#include "rtl/Core.h"
#include "rtl/Transformation.h"
#include "rtl/tf/Transformation2D.h"
#include "rtl/tf/Transformation3D.h"
#include "tf_helpers.h"

using tf_test::Gen;
using tf_test::dist;
using tf_test::tol;

namespace
{
    template<int d, typename E> using Tr = rtl::TranslationND<d, E>;
    template<int d, typename E> using Rot = rtl::RotationND<d, E>;
    template<int d, typename E> using Rig = rtl::RigidTfND<d, E>;

    // ---- trait table: transformation columns -----------------------------------------------------------------------
    template<template<int, typename> class Obj, int d, typename E>
    constexpr bool transformableByAll()
    {
        return rtl::is_transformable_v<Obj<d, E>, Tr<d, E>> && rtl::is_transformable_v<Obj<d, E>, Rot<d, E>>
               && rtl::is_transformable_v<Obj<d, E>, Rig<d, E>>;
    }
    template<template<int, typename> class Obj, typename E>
    constexpr bool transformableDims2to5()
    {
        return transformableByAll<Obj, 2, E>() && transformableByAll<Obj, 3, E>() && transformableByAll<Obj, 4, E>()
               && transformableByAll<Obj, 5, E>();
    }
    template<typename T, int d, typename E>
    constexpr bool fixedTransformableByAll()
    {
        return rtl::is_transformable_v<T, Tr<d, E>> && rtl::is_transformable_v<T, Rot<d, E>> && rtl::is_transformable_v<T, Rig<d, E>>;
    }
    template<typename T, int d, typename E>
    constexpr bool fixedTransformableByNone()
    {
        return !rtl::is_transformable_v<T, Tr<d, E>> && !rtl::is_transformable_v<T, Rot<d, E>> && !rtl::is_transformable_v<T, Rig<d, E>>;
    }

    template<typename E>
    void checkTraitTable()
    {
        static_assert(transformableDims2to5<rtl::VectorND, E>());
        static_assert(transformableDims2to5<rtl::LineSegmentND, E>());
        static_assert(transformableDims2to5<rtl::BoundingBoxND, E>());
        static_assert(transformableDims2to5<rtl::TranslationND, E>());
        static_assert(transformableDims2to5<rtl::RotationND, E>());
        static_assert(transformableDims2to5<rtl::RigidTfND, E>());
        static_assert(fixedTransformableByAll<rtl::Polygon2D<E>, 2, E>());
        static_assert(fixedTransformableByAll<rtl::Polygon3D<E>, 3, E>());
        static_assert(fixedTransformableByAll<rtl::Frustum3D<E>, 3, E>());
        static_assert(fixedTransformableByNone<rtl::Matrix<2, 2, E>, 2, E>());
        static_assert(fixedTransformableByNone<rtl::Matrix<3, 3, E>, 3, E>());
        static_assert(fixedTransformableByNone<rtl::Quaternion<E>, 3, E>());
        // A 2D object is not transformable by a 3D transformation and vice versa.
        static_assert(fixedTransformableByNone<rtl::Polygon2D<E>, 3, E>());
        static_assert(fixedTransformableByNone<rtl::VectorND<3, E>, 2, E>());
        // The runtime values agree with the compile-time ones.
        EXPECT_TRUE((rtl::is_transformable<rtl::VectorND<3, E>, Rig<3, E>>::value));
        EXPECT_FALSE((rtl::is_transformable<rtl::Quaternion<E>, Rig<3, E>>::value));
        EXPECT_FALSE((rtl::is_transformable<rtl::Matrix<3, 3, E>, Tr<3, E>>::value));
    }

    // ---- line segments ---------------------------------------------------------------------------------------------
    template<int d, typename E, typename Tf>
    void checkSegment(const Tf &tf, const Gen &g)
    {
        const auto a = tf_test::randomVector<d, E>(g), b = tf_test::randomVector<d, E>(g);
        const rtl::LineSegmentND<d, E> s(a, b);
        const rtl::LineSegmentND<d, E> t = s.transformed(tf);
        EXPECT_LE(dist(t.beg(), tf(a)), tol<E>());
        EXPECT_LE(dist(t.end(), tf(b)), tol<E>());
        const rtl::VectorND<d, E> dir(typename rtl::VectorND<d, E>::EigenType((tf(b).data() - tf(a).data()).normalized()));
        EXPECT_LE(dist(t.direction(), dir), tol<E>());
        EXPECT_NEAR(t.length(), s.length(), tol<E>());
        // operator() and the in-place form agree with transformed().
        const rtl::LineSegmentND<d, E> t2 = tf(s);
        EXPECT_EQ(t2.beg(), t.beg());
        EXPECT_EQ(t2.end(), t.end());
        rtl::LineSegmentND<d, E> t3 = s;
        t3.transform(tf);
        EXPECT_LE(dist(t3.beg(), t.beg()), tol<E>());
        EXPECT_LE(dist(t3.direction(), t.direction()), tol<E>());
    }

    // ---- bounding boxes --------------------------------------------------------------------------------------------
    template<int d, typename E, typename Tf>
    void checkBox(const Tf &tf, const Gen &g)
    {
        using V = rtl::VectorND<d, E>;
        const V a = tf_test::randomVector<d, E>(g), b = tf_test::randomVector<d, E>(g);
        const rtl::BoundingBoxND<d, E> box(a, b);
        // Expected: the axis-aligned box of the 2^d transformed corners.
        typename V::EigenType lo = V::EigenType::Constant(std::numeric_limits<E>::max());
        typename V::EigenType hi = V::EigenType::Constant(std::numeric_limits<E>::lowest());
        for (int mask = 0; mask < (1 << d); ++mask)
        {
            typename V::EigenType c;
            for (int i = 0; i < d; ++i)
                c[i] = (mask >> i) & 1 ? std::max(a[i], b[i]) : std::min(a[i], b[i]);
            const V tc = tf(V(c));
            lo = lo.cwiseMin(tc.data());
            hi = hi.cwiseMax(tc.data());
        }
        const auto t = box.transformed(tf);
        EXPECT_LE((t.min().data() - lo).norm(), tol<E>());
        EXPECT_LE((t.max().data() - hi).norm(), tol<E>());
        auto t2 = box;
        t2.transform(tf);
        EXPECT_EQ(t2.min(), t.min());      // in place is bit-identical to transformed
        EXPECT_EQ(t2.max(), t.max());
    }

    template<int d, typename E>
    void checkSegmentsAndBoxes()
    {
        Gen g(1000 + d);
        for (int rep = 0; rep < 10; ++rep)
        {
            checkSegment<d, E>(Tr<d, E>::random(g), g);
            checkSegment<d, E>(Rot<d, E>::random(g), g);
            checkSegment<d, E>(Rig<d, E>::random(g), g);
            checkBox<d, E>(Tr<d, E>::random(g), g);
            checkBox<d, E>(Rot<d, E>::random(g), g);
            checkBox<d, E>(Rig<d, E>::random(g), g);
        }
    }

    // ---- polygons --------------------------------------------------------------------------------------------------
    template<typename E, typename Tf>
    void checkPolygon2D(const Tf &tf, const Gen &g)
    {
        rtl::Polygon2D<E> p;
        std::vector<rtl::VectorND<2, E>> pts;
        for (int i = 0; i < 6; ++i)
        {
            pts.push_back(tf_test::randomVector<2, E>(g));
            p.addPoint(pts.back());
        }
        const rtl::Polygon2D<E> t = tf(p);
        ASSERT_EQ(t.points().size(), pts.size());
        for (size_t i = 0; i < pts.size(); ++i)
            EXPECT_LE(dist(t.points()[i], tf(pts[i])), tol<E>());
        rtl::Polygon2D<E> t2 = p;
        t2.transform(tf);
        ASSERT_EQ(t2.points().size(), pts.size());
        for (size_t i = 0; i < pts.size(); ++i)
            EXPECT_LE(dist(t2.points()[i], t.points()[i]), tol<E>());
    }

    template<typename E, typename Tf>
    void checkPolygon3D(const Tf &tf, const Gen &g)
    {
        using V = rtl::VectorND<3, E>;
        const V n = tf_test::randomVector<3, E>(g);
        const E distance = static_cast<E>(g());
        rtl::Polygon3D<E> p(n, distance);
        for (int i = 0; i < 5; ++i)
            p.addPoint(tf_test::randomVector<3, E>(g));
        const rtl::Polygon3D<E> t = tf(p);
        ASSERT_EQ(t.points().size(), p.points().size());
        for (size_t i = 0; i < p.points().size(); ++i)
        {
            EXPECT_LE(dist(t.points()[i], tf(p.points()[i])), tol<E>());
            // The plane moved with the points: n' . p' = distance'.
            EXPECT_NEAR(t.normal().data().dot(t.points()[i].data()), t.distance(), tol<E>());
        }
        EXPECT_NEAR(t.normal().data().norm(), E(1), tol<E>());
        rtl::Polygon3D<E> t2 = p;
        t2.transform(tf);
        EXPECT_LE(dist(t2.normal(), t.normal()), tol<E>());
        EXPECT_NEAR(t2.distance(), t.distance(), tol<E>());
        for (size_t i = 0; i < p.points().size(); ++i)
            EXPECT_LE(dist(t2.points()[i], t.points()[i]), tol<E>());
    }

    // ---- frustums --------------------------------------------------------------------------------------------------
    template<typename E, typename Tf>
    void checkFrustum(const Tf &tf)
    {
        using V = rtl::VectorND<3, E>;
        const rtl::Frustum3D<E> f(V(0, 0, 0), V(10, 1, 1), V(10, -1, 1), V(10, 1, -1), V(10, -1, -1), E(1));
        const rtl::Frustum3D<E> t = tf(f);
        EXPECT_LE(dist(t.getOrigin(), tf(f.getOrigin())), tol<E>());
        EXPECT_LE(dist(t.getNearTopLeft(), tf(f.getNearTopLeft())), tol<E>());
        EXPECT_LE(dist(t.getNearTopRight(), tf(f.getNearTopRight())), tol<E>());
        EXPECT_LE(dist(t.getNearBottomLeft(), tf(f.getNearBottomLeft())), tol<E>());
        EXPECT_LE(dist(t.getNearBottomRight(), tf(f.getNearBottomRight())), tol<E>());
        // Rigid motions preserve distances, so the far corners move like points too.
        EXPECT_LE(dist(t.getFarTopLeft(), tf(f.getFarTopLeft())), E(10) * tol<E>());
        EXPECT_LE(dist(t.getFarBottomRight(), tf(f.getFarBottomRight())), E(10) * tol<E>());
        EXPECT_EQ(t.getDepth(), f.getDepth());
        rtl::Frustum3D<E> t2 = f;
        t2.transform(tf);
        EXPECT_LE(dist(t2.getNearTopLeft(), t.getNearTopLeft()), tol<E>());
    }

    template<typename E>
    void checkPolygonsAndFrustums()
    {
        Gen g(1100);
        for (int rep = 0; rep < 10; ++rep)
        {
            checkPolygon2D<E>(Tr<2, E>::random(g), g);
            checkPolygon2D<E>(Rot<2, E>::random(g), g);
            checkPolygon2D<E>(Rig<2, E>::random(g), g);
            checkPolygon3D<E>(Tr<3, E>::random(g), g);
            checkPolygon3D<E>(Rot<3, E>::random(g), g);
            checkPolygon3D<E>(Rig<3, E>::random(g), g);
            checkFrustum<E>(Tr<3, E>::random(g));
            checkFrustum<E>(Rot<3, E>::random(g));
            checkFrustum<E>(Rig<3, E>::random(g));
        }
    }
}

TEST(TransformObjects, TraitTableTransformationColumns)
{
    checkTraitTable<float>();
    checkTraitTable<double>();
}

TEST(TransformObjects, SegmentsAndBoxesEqualTheirPoints)
{
    checkSegmentsAndBoxes<2, float>();
    checkSegmentsAndBoxes<3, float>();
    checkSegmentsAndBoxes<4, float>();
    checkSegmentsAndBoxes<2, double>();
    checkSegmentsAndBoxes<3, double>();
    checkSegmentsAndBoxes<4, double>();
}

TEST(TransformObjects, PolygonsAndFrustumsEqualTheirPoints)
{
    checkPolygonsAndFrustums<float>();
    checkPolygonsAndFrustums<double>();
}

TEST(TransformObjects, GeneralTfOnObjects)
{
    using GTf = rtl::GeneralTf<rtl::Translation2f, rtl::Rotation2f, rtl::RigidTf2f>;
    static_assert(rtl::is_transformable_v<rtl::LineSegment2f, GTf>);
    static_assert(std::is_same_v<rtl::is_transformable_t<rtl::Polygon2Df, GTf>, rtl::Polygon2Df>);
    static_assert(!rtl::is_transformable_v<rtl::Frustum3f, GTf>);
    Gen g(1250);
    for (int rep = 0; rep < 5; ++rep)
    {
        const auto t = rtl::Translation2f::random(g);
        const auto r = rtl::Rotation2f::random(g);
        const auto k = rtl::RigidTf2f::random(g);
        const rtl::LineSegment2f s(tf_test::randomVector<2, float>(g), tf_test::randomVector<2, float>(g));
        for (const GTf &gtf : {GTf(t), GTf(r), GTf(k)})
        {
            const rtl::LineSegment2f expected = gtf.visit([&s](const auto &tf) { return s.transformed(tf); });
            const rtl::LineSegment2f got = gtf(s);
            EXPECT_EQ(got.beg(), expected.beg());
            EXPECT_EQ(got.end(), expected.end());
        }
        EXPECT_EQ(GTf(k)(s).beg(), k(s).beg());
        EXPECT_LE(dist(GTf(t)(s).end(), t(s.end())), tol<float>());
    }
}

TEST(TransformObjects, AxisAlignedBoxRotationIsExact)
{
    // 45 degrees about x leaves the x bounds exactly and gives +-sqrt(2) in y and z.
    const rtl::BoundingBox3d box(rtl::Vector3d(-1, -1, -1), rtl::Vector3d(1, 1, 1));
    const auto t = box.transformed(rtl::RigidTf3d(rtl::C_PI_4d, rtl::Vector3d::baseX(), rtl::Vector3d()));
    EXPECT_EQ(t.min().x(), -1.0);
    EXPECT_EQ(t.max().x(), 1.0);
    EXPECT_NEAR(t.max().y(), rtl::C_SQRT2d, 1e-12);
    EXPECT_NEAR(t.min().z(), -rtl::C_SQRT2d, 1e-12);
}

// ---- legacy Transformation2D / Transformation3D agree with RigidTfND -------------------------------------------------
TEST(LegacyTransformation2D, AgreesWithRigidTf2D)
{
    Gen g(2400);
    for (int rep = 0; rep < 20; ++rep)
    {
        const double a = 3 * g(), b = 3 * g();
        const rtl::Transformation2D<double> t1(a, g(), g()), t2(b, rtl::Vector2d(g(), g()));
        const rtl::RigidTf2d r1(a, t1.trX(), t1.trY()), r2(b, t2.tr());
        const rtl::Vector2d v(g(), g());
        EXPECT_LE(dist(t1(v), r1(v)), 1e-12);
        EXPECT_LE(dist((t2 * t1)(v), r2(r1)(v)), 1e-12);          // t2 after t1
        EXPECT_LE(dist(t2(t1)(v), r2(r1)(v)), 1e-12);
        EXPECT_LE(dist(t1.inverted()(t1(v)), v), 1e-12);
        EXPECT_NEAR(t1.rotA(), r1.rotAngle(), 1e-12);
        EXPECT_LE(dist(t1.rotMat(), r1.rotMat()), 1e-12);
        EXPECT_NEAR(rtl::Transformation2D<double>::distance(t1, t1, 1, 1), 0.0, 1e-24);
        EXPECT_GT(rtl::Transformation2D<double>::distance(t1, t2, 1, 1), 0.0);
        const rtl::LineSegment2d s(v, rtl::Vector2d(1, 1));
        EXPECT_LE(dist(t1(s).end(), r1(rtl::Vector2d(1, 1))), 1e-12);
    }
    const rtl::Transformation2D<float> id;
    EXPECT_EQ(id(rtl::Vector2f(1, 2)), rtl::Vector2f(1, 2));
    EXPECT_LE(dist(rtl::Transformation2D<double>::rotated(rtl::Vector2d(1, 0), rtl::C_PI_2d), rtl::Vector2d(0, 1)), 1e-15);
    Gen g1(3), g2(3);
    const auto ra = rtl::Transformation2D<double>::random(g1, g1), rb = rtl::Transformation2D<double>::random(g2, g2);
    EXPECT_EQ(rtl::Transformation2D<double>::distance(ra, rb, 1, 1), 0.0);
}

TEST(LegacyTransformation3D, AgreesWithRigidTf3D)
{
    Gen g(2500);
    for (int rep = 0; rep < 20; ++rep)
    {
        const rtl::RigidTf3d r1 = rtl::RigidTf3d::random(g), r2 = rtl::RigidTf3d::random(g);
        const rtl::Transformation3D<double> t1(r1.rotAngle(), r1.rotAxis(), r1.trVec()), t2(r2.rotQuaternion(), r2.trVec());
        const rtl::Vector3d v(g(), g(), g());
        EXPECT_LE(dist(t1(v), r1(v)), 1e-12);
        EXPECT_LE(dist(t2(v), r2(v)), 1e-12);
        EXPECT_LE(dist(t2(t1)(v), r2(r1)(v)), 1e-12);
        EXPECT_LE(dist(t1.inverted()(t1(v)), v), 1e-12);
        EXPECT_LE(dist(t1.rotMat(), r1.rotMat()), 1e-12);
        double roll, pitch, yaw;
        t1.rpy(roll, pitch, yaw);
        EXPECT_LE(dist(rtl::Transformation3D<double>(roll, pitch, yaw, t1.tr())(v), r1(v)), 1e-12);
        EXPECT_NEAR(rtl::Transformation3D<double>::distance(t1, t1, 1, 1), 0.0, 1e-20);
        EXPECT_GT(rtl::Transformation3D<double>::distance(t1, t2, 1, 1), 0.0);
    }
    rtl::Transformation3D<double> t(0.5, rtl::Vector3d(0, 0, 2), rtl::Vector3d(1, 2, 3));
    EXPECT_NEAR(t.rotAngle(), 0.5, 1e-12);
    EXPECT_LE(dist(t.rotAxis(), rtl::Vector3d(0, 0, 1)), 1e-12);
    t.setAngle(1.0);
    t.setTranslationZ(0);
    EXPECT_LE(dist(t(rtl::Vector3d(1, 0, 0)), rtl::Vector3d(1 + std::cos(1.0), 2 + std::sin(1.0), 0)), 1e-12);
}
