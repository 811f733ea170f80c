// Matrix (algebra, inverse, determinant, eigen-decomposition) and Quaternion (products, rotation matrix, RPY and
// angle-axis round trips, slerp).
#include <cmath>
#include <complex>
#include <stdexcept>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "rtl/core/Constants.h"
#include "rtl/core/Matrix.h"
#include "rtl/core/Quaternion.h"

namespace
{
    template<typename E> constexpr E tol() { return std::is_same_v<E, float> ? E(1e-5) : E(1e-9); }

    template<typename E>
    class MatrixTest : public ::testing::Test {};
    template<typename E>
    class QuaternionTest : public ::testing::Test {};
    using Elements = ::testing::Types<float, double>;
    TYPED_TEST_SUITE(MatrixTest, Elements);
    TYPED_TEST_SUITE(QuaternionTest, Elements);

    //! Deterministic pseudo-random values in [-1, 1] (a small LCG, so the tests are reproducible).
    struct Lcg
    {
        mutable unsigned state = 12345u;
        double operator()() const
        {
            state = state * 1664525u + 1013904223u;
            return double(state >> 8) / double(1u << 23) - 1.0;
        }
    };
}

TYPED_TEST(MatrixTest, ConstantsAndExactIdentityProduct)
{
    using E = TypeParam;
    using M = rtl::Matrix<3, 3, E>;
    EXPECT_EQ(M(), M::zeros());                                  // default construction zero-initialises
    EXPECT_EQ(M::identity() * M::ones() + M::zeros(), M::ones());
    EXPECT_TRUE(M::nan().hasNaN());
    EXPECT_FALSE(M::identity().hasNaN());
    EXPECT_EQ(M::rowNr(), 3);
    EXPECT_EQ(M::colNr(), 3);
    EXPECT_EQ(M::identity().trace(), E(3));
    EXPECT_EQ(M::identity().determinant(), E(1));
}

TYPED_TEST(MatrixTest, KnownDeterminantsTraceAndInverse)
{
    using E = TypeParam;
    using M2 = rtl::Matrix<2, 2, E>;
    M2 a;
    a.setRow(0, {1, 2});
    a.setRow(1, {3, 4});
    EXPECT_NEAR(a.determinant(), E(-2), tol<E>());
    EXPECT_EQ(a.trace(), E(5));
    // [[1,2],[3,4]]^-1 = [[-2, 1], [1.5, -0.5]]
    const M2 inv = a.inverted();
    EXPECT_NEAR(inv(0, 0), E(-2), tol<E>());
    EXPECT_NEAR(inv(0, 1), E(1), tol<E>());
    EXPECT_NEAR(inv(1, 0), E(1.5), tol<E>());
    EXPECT_NEAR(inv(1, 1), E(-0.5), tol<E>());
    M2 b = a;
    b.invert();
    EXPECT_EQ(b, inv);

    using M3 = rtl::Matrix<3, 3, E>;
    M3 d;
    d.setElement(0, 0, E(2));
    d.setElement(1, 1, E(3));
    d.setElement(2, 2, E(4));
    d.setElement(0, 2, E(7));                                    // upper triangular: det = product of the diagonal
    EXPECT_NEAR(d.determinant(), E(24), tol<E>() * 24);
    EXPECT_NEAR(M3::distance(d * d.inverted(), M3::identity()), E(0), tol<E>() * 10);

    // Random well-conditioned matrices: inverse and transpose are involutions.
    const Lcg gen;
    for (int k = 0; k < 20; ++k)
    {
        const M3 m = M3::random(gen) + M3::identity() * E(3);
        EXPECT_LE(M3::distance(m, m.inverted().inverted()), (std::is_same_v<E, float> ? E(1e-4) : E(1e-6)));
        EXPECT_EQ(m, m.transposed().transposed());
        EXPECT_NEAR(m.determinant() * m.inverted().determinant(), E(1), tol<E>() * 10);
        M3 t = m;
        t.transpose();
        EXPECT_EQ(t, m.transposed());
    }
}

TYPED_TEST(MatrixTest, EigenDecomposition)
{
    using E = TypeParam;
    using M2 = rtl::Matrix<2, 2, E>;
    M2 s;
    s.setRow(0, {2, 1});
    s.setRow(1, {1, 2});
    auto ev = s.eigenvalues();                                   // symmetric [[2,1],[1,2]]: eigenvalues 1 and 3
    E lo = std::min(ev[0].real(), ev[1].real()), hi = std::max(ev[0].real(), ev[1].real());
    EXPECT_NEAR(lo, E(1), tol<E>());
    EXPECT_NEAR(hi, E(3), tol<E>());
    EXPECT_NEAR(ev[0].imag(), E(0), tol<E>());

    // A rotation by 90 degrees has eigenvalues +-i.
    M2 r;
    r.setRow(0, {0, -1});
    r.setRow(1, {1, 0});
    ev = r.eigenvalues();
    EXPECT_NEAR(std::abs(ev[0].imag()), E(1), tol<E>());
    EXPECT_NEAR(ev[0].real(), E(0), tol<E>());
    EXPECT_NEAR((ev[0] + ev[1]).imag(), E(0), tol<E>());

    // General matrix: A v = lambda v for every eigenpair.
    using M3 = rtl::Matrix<3, 3, E>;
    const Lcg gen;
    for (int k = 0; k < 10; ++k)
    {
        const M3 a = M3::random(gen);
        const auto vals = a.eigenvalues();
        const auto vecs = a.eigenvectors();
        const Eigen::Matrix<std::complex<E>, 3, 3> ac = a.data().template cast<std::complex<E>>();
        for (int i = 0; i < 3; ++i)
        {
            const Eigen::Matrix<std::complex<E>, 3, 1> v = vecs.data().col(i);
            EXPECT_NEAR(v.norm(), E(1), tol<E>() * 10);
            EXPECT_LE((ac * v - vals[size_t(i)] * v).norm(), tol<E>() * 100);
        }
    }
}

TYPED_TEST(MatrixTest, RowsColumnsAndProducts)
{
    using E = TypeParam;
    rtl::Matrix<2, 3, E> m;
    m.setRow(0, rtl::VectorND<3, E>(1, 2, 3));
    m.setColumn(2, {7, 8});
    EXPECT_EQ(m.getRow(0), (rtl::VectorND<3, E>(1, 2, 7)));
    EXPECT_EQ(m.getColumn(2), (rtl::VectorND<2, E>(7, 8)));
    EXPECT_EQ(m.getElement(1, 2), E(8));
    EXPECT_THROW(m.getElement(2, 0), std::out_of_range);
    EXPECT_THROW(m.setElement(0, 3, E(1)), std::out_of_range);
    EXPECT_THROW(m.getRow(2), std::out_of_range);

    // Regression (published defect): a 2x3 matrix times a 3-vector is a 2-vector.
    const rtl::VectorND<2, E> mv = m * rtl::VectorND<3, E>(1, 1, 1);
    EXPECT_EQ(mv, (rtl::VectorND<2, E>(10, 8)));
    // Row vector times matrix: (1, 2) M = (1, 2, 7 + 16).
    const rtl::VectorND<3, E> vm = rtl::VectorND<2, E>(1, 2) * m;
    EXPECT_EQ(vm, (rtl::VectorND<3, E>(1, 2, 23)));

    const rtl::Matrix<3, 2, E> mt = m.transposed();
    const rtl::Matrix<2, 2, E> mmt = m * mt;
    EXPECT_EQ(mmt(0, 0), E(1 + 4 + 49));
    EXPECT_EQ(mmt(0, 1), E(56));
    EXPECT_EQ(mmt(1, 1), E(64));
    EXPECT_EQ(mmt, mmt.transposed());

    // Element-wise algebra and scalars.
    EXPECT_EQ((m * E(2)).getElement(0, 1), E(4));
    EXPECT_EQ((E(2) * m).getElement(0, 1), E(4));
    EXPECT_EQ((m / E(2)).getElement(0, 1), E(1));
    EXPECT_EQ(m + m - m, m);
    EXPECT_EQ(-m + m, (rtl::Matrix<2, 3, E>::zeros()));
    auto c = m;
    c += m;
    c -= m;
    c *= E(3);
    c /= E(3);
    EXPECT_EQ(c, m);
    rtl::Matrix<2, 2, E> sq = mmt;
    sq *= rtl::Matrix<2, 2, E>::identity();
    EXPECT_EQ(sq, mmt);
    using M23 = rtl::Matrix<2, 3, E>;
    EXPECT_EQ(M23::distanceSquared(m, m * E(2)), m.data().squaredNorm());
}

TEST(Matrix, OtherElementTypesCtadAndDynamic)
{
    using Mi = rtl::Matrix<3, 3, int>;
    const Mi five = 5 * Mi::ones();
    EXPECT_EQ(five.trace(), 15);
    rtl::Matrix<2, 2, double> d;
    d(0, 0) = 2.7;
    d(1, 1) = -1.2;
    const auto di = d.cast<int>();
    EXPECT_EQ(di(0, 0), 2);
    EXPECT_EQ(di(1, 1), -1);
    rtl::Matrix<4, 4, unsigned char> mask{};
    EXPECT_EQ(mask, (rtl::Matrix<4, 4, unsigned char>::zeros()));

    auto ctad = rtl::Matrix{Eigen::Matrix<double, 2, 2>{Eigen::Matrix<double, 2, 2>::Identity()}};
    static_assert(std::is_same_v<decltype(ctad), rtl::Matrix<2, 2, double>>);
    EXPECT_EQ(ctad, (rtl::Matrix<2, 2, double>::identity()));

    rtl::Matrix<Eigen::Dynamic, Eigen::Dynamic, double> dyn(2, 3);
    EXPECT_EQ(dyn.data().rows(), 2);
    EXPECT_EQ(dyn.data().cols(), 3);
    EXPECT_TRUE(dyn.data().isZero(0));
    EXPECT_THROW(dyn.getElement(2, 0), std::out_of_range);
    rtl::Matrix<Eigen::Dynamic, Eigen::Dynamic, double> empty;
    EXPECT_EQ(empty.data().size(), 0);
    EXPECT_NE(empty, dyn);

    const auto o = rtl::VectorND<2, double>(1, 2).outer(rtl::VectorND<3, double>(3, 4, 5));
    EXPECT_EQ(o.getRow(1), (rtl::VectorND<3, double>(6, 8, 10)));
}

TYPED_TEST(QuaternionTest, ConstructionAndAccessors)
{
    using E = TypeParam;
    using Q = rtl::Quaternion<E>;
    const Q zero;
    EXPECT_EQ(zero.norm(), E(0));                                // zero-initialised, like every core default
    Q q(E(1), E(2), E(3), E(4));
    EXPECT_EQ(q.w(), E(1));
    EXPECT_EQ(q.scalar(), E(1));
    EXPECT_EQ(q.vector(), (rtl::VectorND<3, E>(2, 3, 4)));
    EXPECT_EQ(q.normSquared(), E(30));
    q.setW(E(5));
    q.setX(E(6));
    q.setY(E(7));
    q.setZ(E(8));
    EXPECT_EQ(q.data().coeffs(), (Eigen::Matrix<E, 4, 1>(6, 7, 8, 5)));   // Eigen order x, y, z, w
    q.setScalar(E(-1));
    q.setVector({0, 1, 0});
    EXPECT_EQ(q.w(), E(-1));
    EXPECT_EQ(q.y(), E(1));

    EXPECT_EQ(Q::identity().rotMat(), (rtl::Matrix<3, 3, E>::identity()));   // exact
    const Q about_x(rtl::C_PI_4<E>, rtl::VectorND<3, E>(5, 0, 0));
    const auto rx = about_x.rotMat();
    EXPECT_EQ(rx(0, 0), E(1));
    EXPECT_EQ(rx(0, 1), E(0));
    EXPECT_EQ(rx(1, 0), E(0));
    EXPECT_NEAR(rx(1, 1), rtl::C_SQRT1_2<E>, tol<E>());
    EXPECT_NEAR(rx(2, 1), rtl::C_SQRT1_2<E>, tol<E>());
}

TYPED_TEST(QuaternionTest, AlgebraAndHamiltonProduct)
{
    using E = TypeParam;
    using Q = rtl::Quaternion<E>;
    const Q i(0, 1, 0, 0), j(0, 0, 1, 0), k(0, 0, 0, 1), one = Q::identity();
    auto expectEq = [](const Q &a, const Q &b) { EXPECT_LE(Q::distance(a, b), tol<E>()) << a.data().coeffs().transpose() << " vs " << b.data().coeffs().transpose(); };
    expectEq(i * j, k);
    expectEq(j * k, i);
    expectEq(k * i, j);
    expectEq(j * i, -k);
    expectEq(i * i, -one);
    expectEq(i * j * k, -one);

    const Q q(E(0.1), E(0.35), E(-1.2), E(0.35));
    expectEq(q + q, q * E(2));
    expectEq(E(2) * q, q * E(2));
    expectEq((q + q) / E(2), q);
    expectEq(q - q, Q(0, 0, 0, 0));
    Q c = q;
    c += q;
    c -= q;
    c *= E(4);
    c /= E(4);
    expectEq(c, q);
    c *= i;
    expectEq(c, q * i);

    const Q pi = q * q.inverted();
    EXPECT_NEAR(pi.scalar(), E(1), tol<E>());
    EXPECT_LE(pi.vector().length(), tol<E>());
    Q inv = q;
    inv.invert();
    expectEq(inv, q.inverted());
    const Q half = (q + q.conjugated()) / E(2);
    EXPECT_EQ(half.scalar(), q.scalar());
    EXPECT_LE(half.vector().length(), tol<E>());
    Q conj = q;
    conj.conjugate();
    expectEq(conj, Q(q.w(), -q.x(), -q.y(), -q.z()));

    EXPECT_NEAR(q.norm(), std::sqrt(E(0.01 + 0.1225 * 2 + 1.44)), tol<E>());
    EXPECT_NEAR(q.normalized().norm(), E(1), tol<E>());
    Q n = q;
    n.normalize();
    expectEq(n, q.normalized());
    EXPECT_NEAR(Q::dotProduct(q, one), E(0.1), tol<E>());
    EXPECT_NEAR(Q::distanceSquared(one, i), E(2), tol<E>());
}

TYPED_TEST(QuaternionTest, RotationMatrixAndRpyRoundTrips)
{
    using E = TypeParam;
    using Q = rtl::Quaternion<E>;
    using V = rtl::VectorND<3, E>;
    using EM = Eigen::Matrix<E, 3, 3>;
    const E t = tol<E>();
    int cases = 0;
    for (E roll = E(-3.0); roll < E(3.1); roll += E(0.7))
        for (E pitch = E(-1.5); pitch < E(1.55); pitch += E(0.5))
            for (E yaw = E(-3.0); yaw < E(3.1); yaw += E(0.9))
            {
                const Q q(roll, pitch, yaw);
                EXPECT_NEAR(q.norm(), E(1), t);
                // Rx(roll) Ry(pitch) Rz(yaw), built independently.
                const EM rx = Eigen::AngleAxis<E>(roll, Eigen::Matrix<E, 3, 1>::UnitX()).toRotationMatrix();
                const EM ry = Eigen::AngleAxis<E>(pitch, Eigen::Matrix<E, 3, 1>::UnitY()).toRotationMatrix();
                const EM rz = Eigen::AngleAxis<E>(yaw, Eigen::Matrix<E, 3, 1>::UnitZ()).toRotationMatrix();
                const EM expected = rx * ry * rz;
                EXPECT_LE((q.rotMat().data() - expected).norm(), 10 * t);

                // rpy() returns these very angles (pitch inside (-pi/2, pi/2), roll/yaw inside (-pi, pi]).
                E r, p, y;
                q.rpy(r, p, y);
                EXPECT_NEAR(r, roll, 100 * t);
                EXPECT_NEAR(p, pitch, 100 * t);
                EXPECT_NEAR(y, yaw, 100 * t);
                // quaternion -> matrix -> quaternion
                const Q back(typename Q::EigenType(q.rotMat().data()));
                EXPECT_LE(back.data().angularDistance(q.data()), 10 * std::sqrt(t));
                // rotMat rotates like q v q^-1
                const V v(E(0.3), E(-1.2), E(2));
                const Q qv = q * Q(0, v.x(), v.y(), v.z()) * q.inverted();
                EXPECT_LE(V::distance(qv.vector(), q.rotMat() * v), 10 * t);
                ++cases;
            }
    EXPECT_EQ(cases, 9 * 7 * 7);

    // Gimbal lock: only roll + yaw is defined; the returned triple still rebuilds the same rotation.
    const Q lock(E(0.4), rtl::C_PI_2<E>, E(-0.3));
    E r, p, y;
    lock.rpy(r, p, y);
    EXPECT_NEAR(p, rtl::C_PI_2<E>, std::sqrt(t));
    EXPECT_LE(Q(r, p, y).data().angularDistance(lock.data()), std::sqrt(t));
}

TYPED_TEST(QuaternionTest, AngleAxisTwoVectorsAndSlerp)
{
    using E = TypeParam;
    using Q = rtl::Quaternion<E>;
    using V = rtl::VectorND<3, E>;
    const E t = tol<E>();

    const Q z90(rtl::C_PI_2<E>, V::baseZ());
    EXPECT_LE(V::distance(z90.rotMat() * V::baseX(), V::baseY()), t);

    const V from(1, 2, 3), to(-2, 0.5, 1);
    const Q ft(from, to);
    EXPECT_LE(V::distance(ft.rotMat() * from.normalized(), to.normalized()), 10 * t);
    EXPECT_NEAR(ft.norm(), E(1), t);

    // slerp between the identity and a rotation by theta about an axis is the rotation by s*theta.
    const V axis = V(1, -1, 2).normalized();
    const E theta = E(2.2);
    const Q end(theta, axis);
    for (E s = 0; s <= E(1.0001); s += E(0.125))
    {
        const Q mid = Q::identity().slerp(end, s);
        const Q expected(s * theta, axis);
        EXPECT_LE(mid.data().angularDistance(expected.data()), 10 * std::sqrt(t)) << "s = " << s;
    }
    EXPECT_LE(Q::distance(Q::identity().slerp(end, 0), Q::identity()), t);
    EXPECT_LE(Q::distance(Q::identity().slerp(end, 1), end), t);
}

TYPED_TEST(QuaternionTest, RandomGeneration)
{
    using E = TypeParam;
    using Q = rtl::Quaternion<E>;
    int calls = 0;
    const auto gen = [&calls]() { return double(++calls); };
    const Q q = Q::random(gen);
    EXPECT_EQ(calls, 4);
    EXPECT_EQ(q.data().coeffs(), (Eigen::Matrix<E, 4, 1>(2, 3, 4, 1)));     // drawn as w, x, y, z

    const Lcg el;
    const auto ang = []() { return 0.75; };
    for (int k = 0; k < 10; ++k)
    {
        const Q r = Q::random(ang, el);
        EXPECT_NEAR(r.norm(), E(1), tol<E>());
        EXPECT_NEAR(r.data().angularDistance(Q::identity().data()), E(0.75), 10 * tol<E>());
    }
    const auto zero = []() { return 0.0; };
    EXPECT_NEAR(Q::random(ang, zero).x(), std::sin(E(0.375)), tol<E>());    // zero axis falls back to X
}
