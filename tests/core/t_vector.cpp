// VectorND: construction, algebra, products, projections, angles, 2D/3D specialisations, element types.
#include <complex>
#include <cstddef>
#include <stdexcept>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "rtl/core/Constants.h"
#include "rtl/core/VectorND.h"

namespace
{
    template<int D, typename E>
    struct DimType
    {
        static constexpr int dim = D;
        using Element = E;
    };

    template<typename E> constexpr E tol() { return std::is_same_v<E, float> ? E(1e-5) : E(1e-12); }

    //! (1, 2, ..., D).
    template<int D, typename E>
    rtl::VectorND<D, E> iota()
    {
        typename rtl::VectorND<D, E>::EigenType e;
        for (int i = 0; i < D; ++i)
            e[i] = E(i + 1);
        return rtl::VectorND<D, E>(e);
    }

    template<typename P>
    class VectorNDTest : public ::testing::Test
    {
    protected:
        static constexpr int D = P::dim;
        using E = typename P::Element;
        using V = rtl::VectorND<D, E>;
    };

    using DimsAndTypes = ::testing::Types<DimType<1, float>, DimType<2, float>, DimType<3, float>, DimType<4, float>,
                                          DimType<1, double>, DimType<2, double>, DimType<3, double>, DimType<4, double>>;
    TYPED_TEST_SUITE(VectorNDTest, DimsAndTypes);
}

TYPED_TEST(VectorNDTest, DefaultConstructionIsZero)
{
    using V = typename TestFixture::V;
    using E = typename TestFixture::E;
    V v;
    for (int i = 0; i < TestFixture::D; ++i)
        EXPECT_EQ(v[static_cast<size_t>(i)], E(0));
    EXPECT_EQ(v, V::zeros());
    V vi{};
    EXPECT_EQ(vi, V::zeros());
    EXPECT_EQ(V::dimensionality(), TestFixture::D);
}

TYPED_TEST(VectorNDTest, ConstantsAndNaN)
{
    using V = typename TestFixture::V;
    using E = typename TestFixture::E;
    EXPECT_TRUE(V::zeros().data().isZero(0));
    EXPECT_TRUE((V::ones().data().array() == E(1)).all());
    EXPECT_TRUE(V::nan().hasNaN());
    EXPECT_FALSE(V::ones().hasNaN());
    V v = V::ones();
    v[static_cast<size_t>(TestFixture::D - 1)] = std::numeric_limits<E>::quiet_NaN();
    EXPECT_TRUE(v.hasNaN());
}

TYPED_TEST(VectorNDTest, ElementAccess)
{
    using V = typename TestFixture::V;
    using E = typename TestFixture::E;
    V v = iota<TestFixture::D, E>();
    for (size_t i = 0; i < size_t(TestFixture::D); ++i)
    {
        EXPECT_EQ(v.getElement(i), E(i + 1));
        EXPECT_EQ(v[i], E(i + 1));
        v.setElement(i, E(10 * i));
        EXPECT_EQ(v.data()[Eigen::Index(i)], E(10 * i));
    }
    EXPECT_THROW(v.getElement(size_t(TestFixture::D)), std::out_of_range);
    EXPECT_THROW(v.setElement(size_t(TestFixture::D) + 5, E(1)), std::out_of_range);

    // From Eigen data (must not be ambiguous with the element constructor when D == 1), copy and assignment.
    V w(v.data());
    EXPECT_EQ(w, v);
    V a;
    a = v.data();
    EXPECT_EQ(a, v);
    V c(v);
    EXPECT_EQ(c, v);
    c[0] += E(1);
    EXPECT_NE(c, v);
}

TYPED_TEST(VectorNDTest, Algebra)
{
    using V = typename TestFixture::V;
    using E = typename TestFixture::E;
    const V a = iota<TestFixture::D, E>();
    const V b = V::ones() * E(3);
    const auto ea = a.data(), eb = b.data();

    EXPECT_EQ((a + b).data(), (ea + eb).eval());
    EXPECT_EQ((a - b).data(), (ea - eb).eval());
    EXPECT_EQ((a * E(2.5)).data(), (ea * E(2.5)).eval());
    EXPECT_EQ((E(2.5) * a).data(), (ea * E(2.5)).eval());
    EXPECT_EQ((a / E(4)).data(), (ea / E(4)).eval());
    EXPECT_EQ((-a).data(), (-ea).eval());
    EXPECT_EQ(a + (-a), V::zeros());

    V c = a;
    c += b;
    EXPECT_EQ(c, a + b);
    c -= b;
    EXPECT_EQ(c, a);
    c *= E(2);
    EXPECT_EQ(c, a + a);
    c /= E(2);
    EXPECT_EQ(c, a);

    // (1..D).(3..3) = 3 D (D + 1) / 2; |1..D|^2 = D (D + 1)(2 D + 1) / 6.
    const int D = TestFixture::D;
    EXPECT_EQ(a.dot(b), E(3 * D * (D + 1) / 2));
    EXPECT_EQ(a.lengthSquared(), E(D * (D + 1) * (2 * D + 1) / 6));
    EXPECT_NEAR(a.length(), std::sqrt(E(D * (D + 1) * (2 * D + 1) / 6)), tol<E>() * 10);
    EXPECT_NEAR(V::distance(a, b), (ea - eb).norm(), tol<E>() * 10);
    EXPECT_EQ(V::distanceSquared(a, b), (ea - eb).squaredNorm());
    EXPECT_EQ(V::distance(a, a), E(0));
}

TYPED_TEST(VectorNDTest, Normalisation)
{
    using V = typename TestFixture::V;
    using E = typename TestFixture::E;
    V a = iota<TestFixture::D, E>() * E(-3);
    V n = a.normalized();
    EXPECT_NEAR(n.length(), E(1), tol<E>());
    EXPECT_NEAR(V::angleShortest(n, a), E(0), std::sqrt(tol<E>()));
    a.normalize();
    EXPECT_EQ(a, n);
}

TYPED_TEST(VectorNDTest, ProjectionsAndAngles)
{
    using V = typename TestFixture::V;
    using E = typename TestFixture::E;
    const int D = TestFixture::D;
    const V p = iota<D, E>();
    const V on = V::ones() * E(2);
    const E sumIdx = E(D * (D + 1) / 2);

    // p.on / |on| = 2 sum / (2 sqrt(D)); vector projection = on * (2 sum) / (4 D).
    EXPECT_NEAR(V::scalarProjection(p, on), sumIdx / std::sqrt(E(D)), tol<E>() * 10);
    const V unit = on.normalized();
    EXPECT_NEAR(V::scalarProjectionOnUnit(p, unit), sumIdx / std::sqrt(E(D)), tol<E>() * 10);
    const V vp = V::vectorProjection(p, on);
    for (int i = 0; i < D; ++i)
        EXPECT_NEAR(vp[size_t(i)], sumIdx / E(D), tol<E>() * 10);
    EXPECT_LE(V::distance(V::vectorProjectionOnUnit(p, unit), vp), tol<E>() * 10);
    // The residual is orthogonal to `on`.
    EXPECT_NEAR((p - vp).dot(on), E(0), tol<E>() * 10 * E(D));

    // Angles: parallel 0, antiparallel pi; the clamped cosine never gives NaN for (anti)parallel vectors.
    const V scaled = p * E(1.1);
    EXPECT_FALSE(std::isnan(V::angleShortest(p, scaled)));
    EXPECT_NEAR(V::angleShortest(p, scaled), E(0), std::sqrt(tol<E>()) * 10);
    EXPECT_NEAR(V::angleShortest(p, -scaled), rtl::C_PI<E>, std::sqrt(tol<E>()) * 10);
    if constexpr (D >= 2)
    {
        V e0, e1;
        e0[0] = E(2);
        e1[1] = E(-0.5);
        EXPECT_NEAR(V::angleShortest(e0, e1), rtl::C_PI_2<E>, tol<E>());
        EXPECT_NEAR(V::angleShortest(e0, e0 + e1 * E(4)), rtl::C_PI_4<E>, tol<E>() * 10);
    }
}

TYPED_TEST(VectorNDTest, OuterProductCastAndRandom)
{
    using V = typename TestFixture::V;
    using E = typename TestFixture::E;
    const int D = TestFixture::D;
    const V a = iota<D, E>();
    const rtl::VectorND<3, E> b(E(1), E(-2), E(0.5));
    const auto m = a.outer(b);
    EXPECT_EQ(decltype(m)::rowNr(), D);
    EXPECT_EQ(decltype(m)::colNr(), 3);
    for (size_t i = 0; i < size_t(D); ++i)
        for (size_t j = 0; j < 3; ++j)
            EXPECT_EQ(m(i, j), a[i] * b[j]);

    const auto ci = (a * E(1.75)).template cast<int>();
    for (size_t i = 0; i < size_t(D); ++i)
        EXPECT_EQ(ci[i], int(E(i + 1) * E(1.75)));

    // Generators are called through a const reference, in index order; double generators feed float vectors.
    int calls = 0;
    auto gen = [&calls]() { return 0.5 + calls++; };
    const auto &cgen = gen;
    const V r = V::random(cgen);
    EXPECT_EQ(calls, D);
    for (size_t i = 0; i < size_t(D); ++i)
        EXPECT_EQ(r[i], E(0.5 + double(i)));
}

TEST(Vector2D, AccessorsAnglesAndCross)
{
    using V = rtl::VectorND<2, double>;
    V v{3.0, -4.0};                                    // copy-list-init through the implicit (x, y) constructor
    EXPECT_EQ(v.x(), 3.0);
    EXPECT_EQ(v.y(), -4.0);
    v.setX(1.0);
    v.setY(2.0);
    EXPECT_EQ(v, V(1.0, 2.0));
    EXPECT_NEAR(v.angleFromZero(), std::atan2(2.0, 1.0), 1e-15);
    EXPECT_EQ(V::baseX(), V(1, 0));
    EXPECT_EQ(V::baseY(), V(0, 1));
    EXPECT_EQ(V::baseX().cross(V::baseY()), 1.0);
    EXPECT_EQ(V(2, 3).cross(V(5, 7)), 2.0 * 7 - 3.0 * 5);
    for (double a = -3.1; a < 3.14; a += 0.1)
    {
        EXPECT_NEAR(V::angleCcw(V::baseX(), V(std::cos(a), std::sin(a))), a, 1e-12);
        EXPECT_NEAR(V::angleCcw(V(0, 2), V(-2 * std::sin(a), 2 * std::cos(a))), a, 1e-12);
    }
    EXPECT_NEAR(V::angleCcw(V(1, 0), V(-1, 0)), rtl::C_PId, 1e-15);
    const rtl::VectorND<2, float> f{1, 2};
    EXPECT_EQ((f * 2.0).x(), 2.0f);                    // double factor converts to the element type
}

TEST(Vector3D, CrossAndBase)
{
    using V = rtl::VectorND<3, float>;
    EXPECT_EQ(V::baseX().cross(V::baseY()), V::baseZ());
    EXPECT_EQ(V::baseY().cross(V::baseZ()), V::baseX());
    EXPECT_EQ(V::baseZ().cross(V::baseX()), V::baseY());
    const V a(1.5f, -2.f, 0.25f), b(-3.f, 0.5f, 4.f);
    EXPECT_EQ(a.cross(b).data(), a.data().cross(b.data()));
    EXPECT_NEAR(a.cross(b).dot(a), 0.f, 1e-5f);
    V c{0.0f, 0.0f, 0.0f};
    c.setX(1);
    c.setY(2);
    c.setZ(3);
    EXPECT_EQ(c.x() + c.y() + c.z(), 6.f);
}

TEST(VectorND, HigherDimensionsAndOtherElementTypes)
{
    const rtl::VectorND<5, float> v5{1.f, 2.f, 3.f, 4.f, 5.f};
    EXPECT_EQ(v5.lengthSquared(), 55.f);
    const rtl::VectorND<5, float> v5d(1, 2.0, 3.f, 4u, 5l);   // mixed arithmetic arguments are cast
    EXPECT_EQ(v5d, v5);

    const rtl::VectorND<3, size_t> s{1, 2, 3};
    EXPECT_EQ(s.dot(s), 14u);
    const rtl::VectorND<2, int> i2(3, 4);
    EXPECT_EQ((i2 * 2 - i2).x(), 3);
    using I4 = rtl::VectorND<4, int>;
    EXPECT_EQ(I4(), I4::zeros());

    using C = std::complex<double>;
    const rtl::VectorND<2, C> c(C(1, 1), C(0, -2));
    EXPECT_EQ((c + c)[1], C(0, -4));
    using C2 = rtl::VectorND<2, C>;
    EXPECT_EQ(C2()[0], C(0, 0));

    rtl::VectorND<3, bool> b;
    EXPECT_FALSE(b[0] || b[1] || b[2]);
    b[1] = true;
    EXPECT_TRUE(b[1]);
}
