// Polygon2D / Polygon3D construction and transformations; Frustum3D corners and transformations (float and double).
#include <cmath>
#include <list>
#include <vector>

#include <gtest/gtest.h>

#include "rtl/Core.h"
#include "rtl/Transformation.h"

namespace
{
    template<typename E> constexpr E tol() { return std::is_same_v<E, float> ? E(1e-5) : E(1e-12); }

    template<typename E>
    class PolygonTest : public ::testing::Test {};
    template<typename E>
    class FrustumTest : public ::testing::Test {};
    using Elements = ::testing::Types<float, double>;
    TYPED_TEST_SUITE(PolygonTest, Elements);
    TYPED_TEST_SUITE(FrustumTest, Elements);
}

TYPED_TEST(PolygonTest, Polygon2DConstructionAndTransforms)
{
    using E = TypeParam;
    using V = rtl::VectorND<2, E>;
    rtl::Polygon2D<E> p;
    EXPECT_TRUE(p.points().empty());
    EXPECT_EQ(rtl::Polygon2D<E>::dimensionality(), 2);
    p.reservePoints(4);
    p.addPoint({0, 0});
    const std::list<V> rest{V(2, 0), V(2, 1), V(0, 1)};
    p.addPoints(rest.begin(), rest.end());
    ASSERT_EQ(p.points().size(), 4u);
    EXPECT_EQ(p.points()[2], V(2, 1));

    // Regression (published defect: transformed() did not compile): every vertex moves, in order.
    const rtl::TranslationND<2, E> tr(E(1), E(-1));
    const auto moved = p.transformed(tr);
    ASSERT_EQ(moved.points().size(), 4u);
    for (size_t i = 0; i < 4; ++i)
        EXPECT_EQ(moved.points()[i], p.points()[i] + V(1, -1));
    const rtl::RotationND<2, E> rot(rtl::C_PI_2<E>);
    const auto turned = p.transformed(rot);
    EXPECT_LE(V::distance(turned.points()[1], V(0, 2)), tol<E>());
    const rtl::RigidTfND<2, E> tf(rot, tr);
    const auto both = tf(p);
    EXPECT_LE(V::distance(both.points()[2], V(0, 1)), tol<E>());     // R (2, 1) + (1, -1) = (-1, 2) + (1, -1)
    auto inPlace = p;
    inPlace.transform(tf);
    EXPECT_EQ(inPlace.points(), both.points());
    inPlace.transform(tr);
    inPlace.transform(rot);
    EXPECT_EQ(inPlace.points().size(), 4u);
}

TYPED_TEST(PolygonTest, Polygon3DPlaneProjectionAndTransforms)
{
    using E = TypeParam;
    using V = rtl::VectorND<3, E>;
    using P = rtl::Polygon3D<E>;
    const P plane(V(0, 0, 2), E(1.5));                   // z = 1.5; the normal is normalised
    EXPECT_EQ(plane.normal(), V::baseZ());
    EXPECT_EQ(plane.distance(), E(1.5));
    EXPECT_EQ(plane.a(), E(0));
    EXPECT_EQ(plane.b(), E(0));
    EXPECT_EQ(plane.c(), E(1));
    EXPECT_EQ(plane.d(), E(-1.5));
    EXPECT_EQ(P::dimensionality(), 3);

    P sq = plane;
    sq.reservePoints(5);
    sq.addPoint({1, 1, 7});                              // projected to z = 1.5
    const std::vector<V> more{V(-1, 1, -3), V(-1, -1, 1.5)};
    sq.addPoints(more.begin(), more.end());
    sq.addPointDirect(V(1, -1, 4));                      // stored as given
    const std::vector<V> direct{V(0, 0, 9)};
    sq.addPointsDirect(direct.begin(), direct.end());
    ASSERT_EQ(sq.points().size(), 5u);
    EXPECT_EQ(sq.points()[0], V(1, 1, 1.5));
    EXPECT_EQ(sq.points()[1], V(-1, 1, 1.5));
    EXPECT_EQ(sq.points()[3], V(1, -1, 4));
    EXPECT_EQ(sq.points()[4], V(0, 0, 9));

    // Oblique plane: projections satisfy n.p = distance.
    P oblique(V(1, 1, 1), E(2));
    oblique.addPoint(V(5, -2, 0.5));
    EXPECT_NEAR(oblique.normal().length(), E(1), tol<E>());
    EXPECT_NEAR(oblique.normal().dot(oblique.points()[0]), E(2), tol<E>() * 10);

    // Transformations move the plane with the vertices (regression: the published in-place rigid transform did not compile).
    P square(V::baseX(), E(0));
    for (const V &v : {V(0, 1, 1), V(0, -1, 1), V(0, -1, -1), V(0, 1, -1)})
        square.addPoint(v);
    auto onPlane = [](const P &poly) {
        for (const auto &pt : poly.points())
            EXPECT_NEAR(poly.normal().dot(pt), poly.distance(), tol<E>() * 10);
    };
    const rtl::TranslationND<3, E> tr(E(2), E(3), E(-1));
    const P moved = square.transformed(tr);
    EXPECT_EQ(moved.distance(), E(2));
    onPlane(moved);
    const rtl::RotationND<3, E> rot(rtl::C_PI_2<E>, V::baseZ());
    P turned = square;
    turned.transform(rot);                               // x-normal turns into y-normal
    EXPECT_LE(V::distance(turned.normal(), V::baseY()), tol<E>());
    EXPECT_NEAR(turned.distance(), E(0), tol<E>());
    onPlane(turned);
    const rtl::RigidTfND<3, E> tf(rot, tr);
    const P both = tf(square);
    EXPECT_LE(V::distance(both.normal(), V::baseY()), tol<E>());
    EXPECT_NEAR(both.distance(), E(3), tol<E>() * 10);
    onPlane(both);
    P inPlace = square;
    inPlace.transform(tf);
    EXPECT_EQ(inPlace.points(), both.points());
    EXPECT_EQ(inPlace.normal(), both.normal());
    EXPECT_EQ(inPlace.distance(), both.distance());
}

TYPED_TEST(FrustumTest, CornersAndTransforms)
{
    using E = TypeParam;
    using F = rtl::Frustum3D<E>;
    using V = typename F::VectorType;
    const F f{{0, 0, 0}, {10, 1, 1}, {10, -1, 1}, {10, 1, -1}, {10, -1, -1}, 1};
    EXPECT_EQ(F::dimensionality(), 3);
    EXPECT_EQ(f.getOrigin(), V(0, 0, 0));
    EXPECT_EQ(f.getNearTopLeft(), V(10, 1, 1));
    EXPECT_EQ(f.getNearTopRight(), V(10, -1, 1));
    EXPECT_EQ(f.getNearBottomLeft(), V(10, 1, -1));
    EXPECT_EQ(f.getNearBottomRight(), V(10, -1, -1));
    EXPECT_EQ(f.getNearMidPoint(), V(10, 0, 0));
    EXPECT_EQ(f.getDepth(), E(1));

    // L = |nearMid - origin| = 10, scale = (L + depth) / L: far corners are exactly near * scale here.
    const E scale = (E(10) + E(1)) / E(10);
    EXPECT_EQ(f.getFarTopLeft(), V(10 * scale, 1 * scale, 1 * scale));
    EXPECT_EQ(f.getFarTopRight(), V(10 * scale, -1 * scale, 1 * scale));
    EXPECT_EQ(f.getFarBottomLeft(), V(10 * scale, 1 * scale, -1 * scale));
    EXPECT_EQ(f.getFarBottomRight(), V(10 * scale, -1 * scale, -1 * scale));
    // The far plane lies `depth` beyond the near plane along the axis.
    EXPECT_NEAR(((f.getFarTopLeft() + f.getFarBottomRight()) / E(2) - f.getNearMidPoint()).length(), E(1), tol<E>());

    // A pure shift by identity-quaternion rigid transform moves every corner exactly.
    const E tx = 2;
    const rtl::RigidTfND<3, E> shift{rtl::Quaternion<E>::identity(), V{tx, 0, 0}};
    const F s = f.transformed(shift);
    EXPECT_EQ(s.getOrigin(), V(tx, 0, 0));
    EXPECT_EQ(s.getNearTopLeft(), V(10 + tx, 1, 1));
    EXPECT_EQ(s.getFarTopLeft(), V(10 * scale + tx, 1 * scale, 1 * scale));
    EXPECT_EQ(s.getFarBottomRight(), V(10 * scale + tx, -1 * scale, -1 * scale));
    EXPECT_EQ(s.getDepth(), E(1));
    F si = f;
    si.transform(rtl::TranslationND<3, E>(tx, 0, 0));
    EXPECT_EQ(si.getFarTopRight(), s.getFarTopRight());

    // Yaw by 90 degrees maps (10, 1, 1) to (-1, 10, 1).
    const E t = std::is_same_v<E, float> ? E(1e-5) : E(1e-10);
    const rtl::RigidTfND<3, E> yaw{0, 0, rtl::C_PI_2<E>, V{0, 0, 0}};
    const F y = f.transformed(yaw);
    EXPECT_LE(V::distance(y.getNearTopLeft(), V(-1, 10, 1)), t);
    EXPECT_LE(V::distance(y.getFarTopLeft(), V(-1, 10, 1) * scale), 10 * t);
    F yr = f;
    yr.transform(yaw.rot());
    EXPECT_LE(V::distance(yr.getNearBottomRight(), V(1, 10, -1)), t);
    EXPECT_EQ(yaw.rot()(f).getNearTopLeft(), yr.getNearTopLeft());
}
