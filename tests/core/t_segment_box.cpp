// LineSegmentND and BoundingBoxND in dimensions 1..4 (float and double): lengths, distances, projections, closest
// points, box cropping, 2D crossings; box union, intersection, IoU, volume, vertices and transformations.
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "rtl/Core.h"
#include "rtl/Transformation.h"

namespace
{
    template<int D, typename E>
    struct DimType
    {
        static constexpr int dim = D;
        using Element = E;
    };
    using DimsAndTypes = ::testing::Types<DimType<1, float>, DimType<2, float>, DimType<3, float>, DimType<4, float>,
                                          DimType<1, double>, DimType<2, double>, DimType<3, double>, DimType<4, double>>;

    template<typename E> constexpr E tol() { return std::is_same_v<E, float> ? E(2e-5) : E(1e-12); }

    template<int D, typename E>
    rtl::VectorND<D, E> unit(int i, E scale = E(1))
    {
        rtl::VectorND<D, E> v;
        v[size_t(i)] = scale;
        return v;
    }

    template<typename P>
    class SegmentTest : public ::testing::Test
    {
    protected:
        static constexpr int D = P::dim;
        using E = typename P::Element;
        using V = rtl::VectorND<D, E>;
        using L = rtl::LineSegmentND<D, E>;
    };
    template<typename P>
    class BoxTest : public SegmentTest<P>
    {
    protected:
        using B = rtl::BoundingBoxND<P::dim, typename P::Element>;
    };
    TYPED_TEST_SUITE(SegmentTest, DimsAndTypes);
    TYPED_TEST_SUITE(BoxTest, DimsAndTypes);
}

TYPED_TEST(SegmentTest, LengthDirectionAndProjections)
{
    using V = typename TestFixture::V;
    using L = typename TestFixture::L;
    using E = typename TestFixture::E;
    constexpr int D = TestFixture::D;
    const V beg = V::ones() * E(0.5);
    const V d = unit<D, E>(0, E(3)) + (D > 1 ? unit<D, E>(D - 1, E(-4)) : V());
    const V end = beg + d;
    const L ls(beg, end);
    EXPECT_EQ(ls.beg(), beg);
    EXPECT_EQ(ls.end(), end);
    EXPECT_NEAR(ls.direction().length(), E(1), tol<E>());
    EXPECT_NEAR(ls.length(), D > 1 ? E(5) : E(3), tol<E>() * 5);
    EXPECT_EQ(L::dimensionality(), D);

    // A point s along the line and k off it (perpendicular), D >= 2.
    const E s = E(1.75), k = E(-0.6);
    V perp;
    if constexpr (D > 1)
        perp = (unit<D, E>(0, E(4)) + unit<D, E>(D - 1, E(3))) / E(5);
    const V p = beg + ls.direction() * s + perp * k;
    EXPECT_NEAR(ls.scalarProjectionUnit(p), s, tol<E>() * 10);
    EXPECT_NEAR(ls.scalarProjection(p), s, tol<E>() * 10);
    EXPECT_LE(V::distance(ls.vectorProjection(p), beg + ls.direction() * s), tol<E>() * 10);
    EXPECT_NEAR(ls.distanceToPoint(p), D > 1 ? std::abs(k) : E(0), std::sqrt(tol<E>()));
    EXPECT_NEAR(ls.distanceToPointSquared(p), D > 1 ? k * k : E(0), tol<E>() * 10);
    // distanceToPoint is measured from the infinite line, not clamped to the segment.
    EXPECT_NEAR(ls.distanceToPoint(beg + ls.direction() * E(100) + perp * k), D > 1 ? std::abs(k) : E(0), std::sqrt(tol<E>()) * 10);
    // The origin: beg = 0.5 * ones, so its distance follows from the projection of -beg on the line.
    const E along = (-beg).dot(ls.direction());
    EXPECT_NEAR(ls.distanceToOrigin(), std::sqrt(std::max(E(0), beg.lengthSquared() - along * along)), std::sqrt(tol<E>()));
}

TYPED_TEST(SegmentTest, MovingEndpoints)
{
    using V = typename TestFixture::V;
    using L = typename TestFixture::L;
    using E = typename TestFixture::E;
    const V b = V::zeros(), e = V::ones() * E(2);
    L ls(b, e);
    const V dir = ls.direction();
    ls.moveEnd(E(0.5));
    EXPECT_LE(V::distance(ls.end(), V::ones()), tol<E>());
    EXPECT_EQ(ls.direction(), dir);
    ls.moveBegin(E(-1));                                 // beg -> beg - (end - beg) = -ones
    EXPECT_LE(V::distance(ls.beg(), -V::ones()), tol<E>());
    EXPECT_NEAR(ls.length(), E(2) * std::sqrt(E(TestFixture::D)), tol<E>() * 10);
    ls.moveEnd(E(-1));                                   // end passes beg: the direction flips
    EXPECT_LE(V::distance(ls.end(), V::ones() * E(-3)), tol<E>() * 10);
    EXPECT_LE(V::distance(ls.direction(), -dir), tol<E>());
    ls.swapEndpoints();
    EXPECT_LE(V::distance(ls.direction(), dir), tol<E>());
    EXPECT_GT(ls.length(), E(0));
    ls.setBegin(V::ones() * E(4));
    ls.setEnd(V::ones() * E(5));
    EXPECT_LE(V::distance(ls.direction(), dir), tol<E>());
    EXPECT_NEAR(ls.length(), std::sqrt(E(TestFixture::D)), tol<E>() * 10);
}

TYPED_TEST(SegmentTest, ClosestPoints)
{
    using V = typename TestFixture::V;
    using L = typename TestFixture::L;
    using E = typename TestFixture::E;
    constexpr int D = TestFixture::D;
    const E limit = std::is_same_v<E, float> ? E(0.01) : E(1e-4);
    E t1 = E(-7), t2 = E(-7), t = E(-7);

    // Parallel lines have no unique closest points (in 1D every pair is parallel).
    const L a(V::zeros(), V::ones());
    const L a2(V::ones() * E(3), V::ones() * E(5));
    EXPECT_FALSE(L::closestPoint(a, a2, t1, t2));
    EXPECT_FALSE(a.closestPoint(a2, t));
    EXPECT_EQ(t, E(-7));

    if constexpr (D >= 2)
    {
        // ls1 along e0 through the origin at t = 0.25; ls2 along e1 through h * e2 (h = 0 in 2D) at t = 0.6.
        const E h = D >= 3 ? E(2) : E(0);
        const V off = D >= 3 ? unit<D, E>(2, h) : V();
        const L ls1(unit<D, E>(0, E(-1)), unit<D, E>(0, E(3)));
        const L ls2(off + unit<D, E>(1, E(-3)), off + unit<D, E>(1, E(2)));
        ASSERT_TRUE(L::closestPoint(ls1, ls2, t1, t2));
        EXPECT_NEAR(t1, E(0.25), limit);
        EXPECT_NEAR(t2, E(0.6), limit);
        ASSERT_TRUE(ls1.closestPoint(ls2, t));
        EXPECT_NEAR(t, t1, limit);
        ASSERT_TRUE(ls2.closestPoint(ls1, t));
        EXPECT_NEAR(t, t2, limit);
        // In units of length along the unit directions.
        ASSERT_TRUE(L::closestPointUnit(ls1, ls2, t1, t2));
        EXPECT_NEAR(t1, E(1), limit);
        EXPECT_NEAR(t2, E(3), limit);
        ASSERT_TRUE(ls1.closestPointUnit(ls2, t));
        EXPECT_NEAR(t, E(1), limit);
        // Their distance: the common perpendicular has length h.
        const V p1 = ls1.beg() + (ls1.end() - ls1.beg()) * E(0.25), p2 = ls2.beg() + (ls2.end() - ls2.beg()) * E(0.6);
        EXPECT_NEAR(V::distance(p1, p2), h, limit);
    }
}

TYPED_TEST(SegmentTest, CroppingByHyperRectangle)
{
    using V = typename TestFixture::V;
    using L = typename TestFixture::L;
    using E = typename TestFixture::E;
    constexpr int D = TestFixture::D;
    const E sq = std::sqrt(E(D));
    const V c1 = V::ones(), c2 = -V::ones();             // corners in either order

    // The diagonal from -3 * ones enters the box at -ones (t = 2 sqrt(D)) and leaves at +ones (t = 4 sqrt(D)).
    L diag(V::ones() * E(-3), V::ones() * E(-2));
    E tb, te;
    ASSERT_TRUE(diag.cropByHyperRect(c1, c2, tb, te));
    EXPECT_NEAR(tb, E(2) * sq, tol<E>() * 10);
    EXPECT_NEAR(te, E(4) * sq, tol<E>() * 10);
    V pb, pe;
    ASSERT_TRUE(diag.cropByHyperRect(c1, c2, pb, pe));
    EXPECT_LE(V::distance(pb, -V::ones()), tol<E>() * 10);
    EXPECT_LE(V::distance(pe, V::ones()), tol<E>() * 10);
    const V dir = diag.direction();
    ASSERT_TRUE(diag.fitToHyperRect(c2, c1));
    EXPECT_LE(V::distance(diag.beg(), -V::ones()), tol<E>() * 10);
    EXPECT_LE(V::distance(diag.end(), V::ones()), tol<E>() * 10);
    EXPECT_LE(V::distance((diag.end() - diag.beg()).normalized(), diag.direction()), tol<E>() * 10);
    EXPECT_EQ(diag.direction(), dir);

    if constexpr (D >= 2)
    {
        // Regression (published defect): a line parallel to axis 0 but outside the box's slab in axis 1 misses it.
        const L outside(unit<D, E>(0, E(-5)) + unit<D, E>(1, E(2)), unit<D, E>(0, E(5)) + unit<D, E>(1, E(2)));
        EXPECT_FALSE(outside.cropByHyperRect(c1, c2, tb, te));
        L copy = outside;
        EXPECT_FALSE(copy.fitToHyperRect(c1, c2));
        EXPECT_EQ(copy.beg(), outside.beg());
        // Parallel and inside the slab: crosses from x = -1 to x = 1.
        const L inside(unit<D, E>(0, E(-5)) + unit<D, E>(1, E(0.5)), unit<D, E>(0, E(5)) + unit<D, E>(1, E(0.5)));
        ASSERT_TRUE(inside.cropByHyperRect(c1, c2, tb, te));
        EXPECT_NEAR(tb, E(4), tol<E>() * 10);
        EXPECT_NEAR(te, E(6), tol<E>() * 10);
        // Oblique line passing beside the box.
        const L beside(unit<D, E>(0, E(3)), unit<D, E>(1, E(3)));
        EXPECT_FALSE(beside.cropByHyperRect(c1, c2, tb, te));
    }
    else
    {
        const L line(V(E(7)), V(E(6)));                  // pointing down: enters at 1 (t = 6), leaves at -1 (t = 8)
        ASSERT_TRUE(line.cropByHyperRect(c1, c2, tb, te));
        EXPECT_NEAR(tb, E(6), tol<E>());
        EXPECT_NEAR(te, E(8), tol<E>());
    }
}

TYPED_TEST(SegmentTest, DistanceRandomAndTransforms)
{
    using V = typename TestFixture::V;
    using L = typename TestFixture::L;
    using E = typename TestFixture::E;
    constexpr int D = TestFixture::D;
    const L a(V::zeros(), V::ones());
    const L b(V::ones() * E(2), V::ones() * E(3));
    const auto dist = L::distance(a, b);
    EXPECT_NEAR(dist.dist_ang, E(0), std::sqrt(tol<E>()) * 10);
    auto d2 = L::distance(a, L(V::ones(), V::zeros()));
    EXPECT_NEAR(d2.dist_ang, rtl::C_PI<E>, std::sqrt(tol<E>()) * 10);
    EXPECT_NEAR(d2.combined(E(2), E(1)), E(2) * d2.dist_ang + d2.dist_lin, tol<E>());

    int calls = 0;
    const auto gen = [&calls]() { return double(calls++); };
    const L r = L::random(gen);
    EXPECT_EQ(calls, 2 * D);
    EXPECT_EQ(r.beg()[0], E(0));
    EXPECT_EQ(r.end()[0], E(D));

    // Transform there and back: endpoints and direction return within the vector tolerance.
    const L ls(unit<D, E>(0, E(1.5)) - V::ones() * E(0.25), V::ones() * E(2));
    const E allowed = E(D) * (std::is_same_v<E, float> ? E(1e-3) : E(1e-6));
    auto check = [&](const auto &tf) {
        const L there = ls.transformed(tf);
        L back = there;
        back.transform(tf.inverted());
        EXPECT_LE(V::distance(back.beg(), ls.beg()), allowed);
        EXPECT_LE(V::distance(back.end(), ls.end()), allowed);
        EXPECT_LE(V::distance(back.direction(), ls.direction()), allowed);
        EXPECT_LE(V::distance(there.beg(), ls.beg().transformed(tf)), allowed);
        EXPECT_NEAR(there.length(), ls.length(), allowed);
        EXPECT_EQ(tf(ls).beg(), there.beg());
    };
    rtl::TranslationND<D, E> tr;
    tr.setTrVec(V::ones() * E(-1.5));
    check(tr);
    if constexpr (D >= 2)
    {
        const auto rot = rtl::RotationND<D, E>(V::ones(), unit<D, E>(0, E(1)));
        check(rot);
        check(rtl::RigidTfND<D, E>(rot, tr));
    }
}

TEST(LineSegment2D, NormalCrossingsAndRect)
{
    using L = rtl::LineSegment2d;
    using V = rtl::Vector2d;
    const L ls(1, 1, 4, 5);                               // direction (0.6, 0.8)
    EXPECT_NEAR(ls.normal().x(), -0.8, 1e-15);
    EXPECT_NEAR(ls.normal().y(), 0.6, 1e-15);
    EXPECT_NEAR(ls.distanceToOrigin(), std::abs(1 * -0.8 + 1 * 0.6), 1e-15);
    EXPECT_NEAR(ls.distanceToOrigin(), ls.distanceToPoint(V(0, 0)), 1e-12);

    // The vector forms of setBegin/setEnd stay reachable next to the (x, y) forms (published defect).
    L m = ls;
    m.setBegin(V(0, 0));
    m.setEnd(3, 4);
    EXPECT_EQ(m.end(), V(3, 4));
    m.setEnd(V(0, 2));
    m.setBegin(0, 1);
    EXPECT_EQ(m.beg(), V(0, 1));
    EXPECT_NEAR(m.direction().y(), 1.0, 1e-15);

    // Crossing of x = y and the line through (0, 2), (2, 0): at (1, 1), t = 0.5 on both (double elements compile).
    const L d1(0, 0, 2, 2), d2(0, 2, 2, 0);
    double t1, t2;
    ASSERT_TRUE(L::getCrossing(d1, d2, t1, t2));
    EXPECT_NEAR(t1, 0.5, 1e-15);
    EXPECT_NEAR(t2, 0.5, 1e-15);
    V c;
    ASSERT_TRUE(L::getCrossing(d1, d2, c));
    EXPECT_LE(V::distance(c, V(1, 1)), 1e-15);
    ASSERT_TRUE(L::getCrossing(V(0, 0), V(4, 0), V(3, -1), V(3, 1), t1, t2));
    EXPECT_NEAR(t1, 0.75, 1e-15);
    EXPECT_NEAR(t2, 0.5, 1e-15);
    ASSERT_TRUE(L::getCrossing(V(0, 0), V(4, 0), V(3, -1), V(3, 1), c));
    EXPECT_EQ(c, V(3, 0));
    // Parallel: false, with saturated parameters.
    EXPECT_FALSE(L::getCrossing(L(0, 0, 1, 0), L(0, 1, 1, 1), t1, t2));
    EXPECT_TRUE(t1 == std::numeric_limits<double>::max() || t1 == std::numeric_limits<double>::lowest());
    EXPECT_TRUE(t2 == std::numeric_limits<double>::max() || t2 == std::numeric_limits<double>::lowest());

    // cropByRect (both overloads) is cropByHyperRect.
    double tb, te;
    ASSERT_TRUE(L(-2, 0, -1, 0).cropByRect(V(1, 1), V(-1, -1), tb, te));
    EXPECT_DOUBLE_EQ(tb, 1.0);
    EXPECT_DOUBLE_EQ(te, 3.0);
    V pb, pe;
    ASSERT_TRUE(L(-2, 0, -1, 0).cropByRect(V(1, 1), V(-1, -1), pb, pe));
    EXPECT_EQ(pb, V(-1, 0));
    EXPECT_EQ(pe, V(1, 0));

    const rtl::LineSegment2f f(0.f, 0.f, 2.f, 2.f), g(0.f, 2.f, 2.f, 0.f);
    float ft1, ft2;
    ASSERT_TRUE(rtl::LineSegment2f::getCrossing(f, g, ft1, ft2));
    EXPECT_FLOAT_EQ(ft1, 0.5f);
}

TEST(LineSegment3D, BraceConstructionAndVectorAssignment)
{
    auto make = [](const rtl::LineSegment3f &l) { return l; };
    const rtl::LineSegment3f l = make({rtl::Vector3f(0, 0, 0), rtl::Vector3f(0, 0, 2)});
    EXPECT_EQ(l.direction(), rtl::Vector3f::baseZ());
    std::vector<rtl::LineSegment2f> v1{{rtl::Vector2f(0, 0), rtl::Vector2f(1, 0)}}, v2;
    v2 = v1;
    EXPECT_EQ(v2.front().end(), rtl::Vector2f(1, 0));
}

TYPED_TEST(BoxTest, ConstructionVolumeAndGrowth)
{
    using V = typename TestFixture::V;
    using B = typename TestFixture::B;
    using E = typename TestFixture::E;
    constexpr int D = TestFixture::D;
    const B b(V::ones() * E(2), V::zeros());              // corners in any order
    EXPECT_EQ(b.min(), V::zeros());
    EXPECT_EQ(b.max(), V::ones() * E(2));
    EXPECT_EQ(b.volume(), E(1 << D));
    EXPECT_EQ(b.centroid(), V::ones());
    EXPECT_EQ(B::dimensionality(), D);

    const B point(V::ones());
    EXPECT_EQ(point.volume(), E(0));
    EXPECT_EQ(point.min(), point.max());

    std::vector<V> pts{V::ones(), -V::ones(), V::zeros()};
    B fromPts(pts);
    EXPECT_EQ(fromPts.min(), -V::ones());
    EXPECT_EQ(fromPts.max(), V::ones());
    EXPECT_THROW(B(std::vector<V>{}), std::invalid_argument);

    B grow(V::zeros());
    grow.addPoint(unit<D, E>(D - 1, E(3)));
    grow.addPoints({V::ones() * E(-1)});
    EXPECT_EQ(grow.min(), -V::ones());
    EXPECT_EQ(grow.max()[size_t(D - 1)], E(3));
    grow.addBoundingBox(B(V::ones() * E(5), V::ones() * E(6)));
    EXPECT_EQ(grow.max(), V::ones() * E(6));
    EXPECT_EQ(grow.min(), -V::ones());
}

TYPED_TEST(BoxTest, IntersectionUnionAndIoU)
{
    using V = typename TestFixture::V;
    using B = typename TestFixture::B;
    using E = typename TestFixture::E;
    constexpr int D = TestFixture::D;
    const B a(-V::ones(), V::ones()), b(V::zeros(), V::ones() * E(2));
    EXPECT_TRUE(a.intersects(b));
    EXPECT_TRUE(b.intersects(a));
    const auto i = B::intersection(a, b);
    ASSERT_NE(i, nullptr);
    EXPECT_EQ(i->min(), V::zeros());
    EXPECT_EQ(i->max(), V::ones());
    EXPECT_EQ(i->volume(), E(1));
    // IoU = 1 / (2^D + 2^D - 1); for D = 3 that is 1/15.
    EXPECT_NEAR(a.intersectionOverUnion(b), E(1) / E((1 << D) + (1 << D) - 1), tol<E>());
    EXPECT_NEAR(a.intersectionOverUnion(a), E(1), tol<E>());

    // Touching boxes intersect (closed intervals) but have no positive-volume intersection.
    const B touching(V::ones(), V::ones() * E(3));
    EXPECT_TRUE(a.intersects(touching));
    EXPECT_EQ(B::intersection(a, touching), nullptr);
    EXPECT_EQ(a.intersectionOverUnion(touching), E(0));
    const B far(V::ones() * E(4), V::ones() * E(5));
    EXPECT_FALSE(a.intersects(far));
    EXPECT_EQ(B::intersection(a, far), nullptr);
    EXPECT_EQ(far.intersectionOverUnion(a), E(0));
    // Separated in one dimension only.
    const B shifted(-V::ones() + unit<D, E>(D - 1, E(3)), V::ones() + unit<D, E>(D - 1, E(3)));
    EXPECT_FALSE(a.intersects(shifted));
}

TYPED_TEST(BoxTest, VerticesAndTransforms)
{
    using V = typename TestFixture::V;
    using B = typename TestFixture::B;
    using E = typename TestFixture::E;
    constexpr int D = TestFixture::D;
    const B b(V::zeros(), V::ones() * E(2));
    const std::vector<V> corners = b.allVertices();
    ASSERT_EQ(corners.size(), size_t(1) << D);
    std::set<std::vector<E>> distinct;
    for (const auto &c : corners)
    {
        for (int k = 0; k < D; ++k)
            EXPECT_TRUE(c[size_t(k)] == E(0) || c[size_t(k)] == E(2));
        distinct.insert(std::vector<E>(c.data().data(), c.data().data() + D));
    }
    EXPECT_EQ(distinct.size(), corners.size());
    const auto lengths = b.allVertices([](const V &v) { return v.lengthSquared(); });
    EXPECT_EQ(lengths.front(), E(0));
    EXPECT_EQ(lengths.back(), E(4 * D));

    rtl::TranslationND<D, E> tr;
    tr.setTrVec(V::ones() * E(-1));
    const B moved = b.transformed(tr);
    EXPECT_EQ(moved.min(), -V::ones());
    EXPECT_EQ(moved.max(), V::ones());
    B inPlace = b;
    inPlace.transform(tr);
    EXPECT_EQ(inPlace.min(), moved.min());
    EXPECT_EQ(inPlace.max(), moved.max());
    EXPECT_EQ(tr(b).max(), moved.max());

    if constexpr (D >= 2)
    {
        // A rotation by 90 degrees in the plane of axes 0 and 1 maps the box [-1, 1]^D onto itself.
        const auto rot = rtl::RotationND<D, E>(unit<D, E>(0, E(1)), unit<D, E>(1, E(1)));
        const B r = moved.transformed(rot);
        EXPECT_LE(V::distance(r.min(), -V::ones()), tol<E>() * 10);
        EXPECT_LE(V::distance(r.max(), V::ones()), tol<E>() * 10);
        B ri = moved;
        ri.transform(rot);
        EXPECT_EQ(ri.min(), r.min());                     // bit-identical to transformed()
        EXPECT_EQ(ri.max(), r.max());
        const rtl::RigidTfND<D, E> tf(rot, tr);
        const B t = b.transformed(tf);
        B ti = b;
        ti.transform(tf);
        EXPECT_EQ(ti.min(), t.min());
        EXPECT_EQ(ti.max(), t.max());
        EXPECT_NEAR(t.volume(), b.volume(), tol<E>() * 100);
    }
}

TEST(BoundingBox3D, RotationAboutXKeepsXBoundsExactly)
{
    const rtl::BoundingBox3d box(rtl::Vector3d(-1, -1, -1), rtl::Vector3d(1, 1, 1));
    const rtl::RigidTf3d tf(rtl::C_PI_4<double>, rtl::Vector3d::baseX(), rtl::Vector3d());
    const auto r = box.transformed(tf);
    EXPECT_EQ(r.min().x(), -1.0);
    EXPECT_EQ(r.max().x(), 1.0);
    EXPECT_NEAR(r.min().y(), -rtl::C_SQRT2d, 1e-12);
    EXPECT_NEAR(r.max().z(), rtl::C_SQRT2d, 1e-12);
    auto ri = box;
    ri.transform(tf);
    EXPECT_EQ(ri.min(), r.min());
    EXPECT_EQ(ri.max(), r.max());
}
