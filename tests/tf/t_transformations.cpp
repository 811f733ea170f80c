// TranslationND, RotationND and RigidTfND: composition conventions, group laws, N-D construction, 2D/3D views.
#include <gtest/gtest.h>

#include <cmath>
#include <type_traits>

#include "rtl/Core.h"
#include "rtl/Transformation.h"
#include "tf_helpers.h"

using tf_test::Gen;
using tf_test::dist;
using tf_test::tfDistance;
using tf_test::tol;

// Every dimension 2..5 in both element types where it is cheap to compile. The heavier property checks run on the
// 2D specialisation (float), the 3D specialisation (double) and the general N-D code (4D, double); the 2D/3D
// specialisations in the other element type are covered by the dedicated tests further down. This keeps the
// translation unit's compile time (native and ASan) reasonable.
#define TF_FOR_ALL_DIMS_AND_TYPES(fn) \
    fn<2, float>(); fn<3, float>(); fn<4, float>(); fn<5, float>(); \
    fn<2, double>(); fn<3, double>(); fn<4, double>(); fn<5, double>()
#define TF_FOR_DIMS_AND_TYPES(fn) \
    fn<2, float>(); fn<3, double>(); fn<4, double>()

namespace
{
    template<int d, typename E> using Tr = rtl::TranslationND<d, E>;
    template<int d, typename E> using Rot = rtl::RotationND<d, E>;
    template<int d, typename E> using Rig = rtl::RigidTfND<d, E>;

    // ---- composition result types (docs/reference.md, "Composition rules") ------------------------------------------
    template<int d, typename E>
    void checkCompositionTypes()
    {
        const Tr<d, E> t;
        const Rot<d, E> r;
        const Rig<d, E> k;
        static_assert(std::is_same_v<decltype(t(t)), Tr<d, E>>);
        static_assert(std::is_same_v<decltype(t(r)), Rig<d, E>>);
        static_assert(std::is_same_v<decltype(t(k)), Rig<d, E>>);
        static_assert(std::is_same_v<decltype(r(t)), Rig<d, E>>);
        static_assert(std::is_same_v<decltype(r(r)), Rot<d, E>>);
        static_assert(std::is_same_v<decltype(r(k)), Rig<d, E>>);
        static_assert(std::is_same_v<decltype(k(t)), Rig<d, E>>);
        static_assert(std::is_same_v<decltype(k(r)), Rig<d, E>>);
        static_assert(std::is_same_v<decltype(k(k)), Rig<d, E>>);
        static_assert(std::is_same_v<decltype(t(rtl::VectorND<d, E>())), rtl::VectorND<d, E>>);
        static_assert(Tr<d, E>::dimensionality() == d && Rot<d, E>::dimensionality() == d && Rig<d, E>::dimensionality() == d);
        static_assert(std::is_same_v<typename Rig<d, E>::ElementType, E> && std::is_same_v<typename Rot<d, E>::VectorType, rtl::VectorND<d, E>>);
        // Mixed dimensions or element types do not compose.
        static_assert(!rtl::is_transformable_v<Tr<d, E>, Tr<d + 1, E>>);
        static_assert(!rtl::is_transformable_v<Rig<d, E>, Rot<d + 1, E>>);
        static_assert(!rtl::is_transformable_v<Rig<d, float>, Rig<d, double>>);
    }

    // ---- tf2(tf1)(v) == tf2(tf1(v)) == v.transformed(tf1).transformed(tf2), and the map itself ---------------------
    template<int d, typename E, typename A, typename B>
    void checkPair(const A &a, const B &b, const rtl::VectorND<d, E> &v)
    {
        const auto composed = b(a);
        const rtl::VectorND<d, E> r1 = composed(v), r2 = b(a(v)), r3 = v.transformed(a).transformed(b);
        EXPECT_LE(dist(r1, r2), tol<E>());
        EXPECT_LE(dist(r2, r3), tol<E>());
        // a.transformed(b) is the same composition as b(a).
        EXPECT_LE((tfDistance<d, E>(a.transformed(b), composed)), tol<E>());
    }

    template<int d, typename E>
    void checkAllPairs()
    {
        Gen g(100 + d);
        for (int rep = 0; rep < 20; ++rep)
        {
            const auto t1 = Tr<d, E>::random(g), t2 = Tr<d, E>::random(g);
            const auto r1 = Rot<d, E>::random(g), r2 = Rot<d, E>::random(g);
            const auto k1 = Rig<d, E>::random(g), k2 = Rig<d, E>::random(g);
            const auto v = tf_test::randomVector<d, E>(g);
            checkPair<d, E>(t1, t2, v); checkPair<d, E>(t1, r2, v); checkPair<d, E>(t1, k2, v);
            checkPair<d, E>(r1, t2, v); checkPair<d, E>(r1, r2, v); checkPair<d, E>(r1, k2, v);
            checkPair<d, E>(k1, t2, v); checkPair<d, E>(k1, r2, v); checkPair<d, E>(k1, k2, v);
        }
    }

    template<int d, typename E>
    void checkApplicationFormulas()
    {
        Gen g(7 * d);
        const auto k = Rig<d, E>::random(g);
        const auto v = tf_test::randomVector<d, E>(g);
        const typename rtl::VectorND<d, E>::EigenType expected = k.rotMat().data() * v.data() + k.trVec().data();
        EXPECT_LE((k(v).data() - expected).norm(), tol<E>());
        EXPECT_LE((k.rot()(v).data() - k.rotMat().data() * v.data()).norm(), tol<E>());
        EXPECT_LE((k.tr()(v).data() - (v.data() + k.trVec().data())).norm(), tol<E>());
        // The rigid transform is "rotation, then translation".
        EXPECT_LE((tfDistance<d, E>(k, k.tr()(k.rot()))), tol<E>());
        EXPECT_LE(tf_test::rotationError(k.rotMat()), tol<E>());
    }

    // ---- associativity ---------------------------------------------------------------------------------------------
    template<int d, typename E, typename A, typename B, typename C>
    void checkAssoc(const A &a, const B &b, const C &c)
    {
        // (a then b) then c  ==  a then (b then c)
        EXPECT_LE((tfDistance<d, E>(c(b(a)), c(b)(a))), tol<E>());
        EXPECT_LE((tfDistance<d, E>(a.transformed(b).transformed(c), a.transformed(b.transformed(c)))), tol<E>());
    }

    template<int d, typename E>
    void checkAssociativity()
    {
        Gen g(200 + d);
        for (int rep = 0; rep < 10; ++rep)
        {
            const auto t = Tr<d, E>::random(g), t2 = Tr<d, E>::random(g);
            const auto r = Rot<d, E>::random(g), r2 = Rot<d, E>::random(g);
            const auto k = Rig<d, E>::random(g), k2 = Rig<d, E>::random(g);
            checkAssoc<d, E>(t, r, k); checkAssoc<d, E>(r, k, t); checkAssoc<d, E>(k, t, r);
            checkAssoc<d, E>(t, t2, t); checkAssoc<d, E>(r, r2, r); checkAssoc<d, E>(k, k2, k);
            checkAssoc<d, E>(r, t, r2); checkAssoc<d, E>(t, k, t2);
        }
    }

    // ---- inverse and identity laws ---------------------------------------------------------------------------------
    template<int d, typename E, typename T>
    void checkGroupLaws(const T &a)
    {
        const T id = T::identity();
        EXPECT_LE((tfDistance<d, E>(a.inverted()(a), id)), tol<E>());
        EXPECT_LE((tfDistance<d, E>(a(a.inverted()), id)), tol<E>());
        EXPECT_LE((tfDistance<d, E>(a.inverted().inverted(), a)), tol<E>());
        T b = a;
        b.invert();
        EXPECT_LE((tfDistance<d, E>(b, a.inverted())), E(0));     // invert() and inverted() agree exactly
        EXPECT_LE((tfDistance<d, E>(id(a), a)), tol<E>());
        EXPECT_LE((tfDistance<d, E>(a(id), a)), tol<E>());
        const auto v = rtl::VectorND<d, E>::ones();
        EXPECT_EQ(id(v), v);                                      // the identity is exact
        // In-place transform equals transformed.
        T c = a;
        c.transform(a.inverted());
        EXPECT_LE((tfDistance<d, E>(c, a.transformed(a.inverted()))), E(0));
    }

    template<int d, typename E>
    void checkInverseIdentity()
    {
        Gen g(300 + d);
        for (int rep = 0; rep < 10; ++rep)
        {
            checkGroupLaws<d, E>(Tr<d, E>::random(g));
            checkGroupLaws<d, E>(Rot<d, E>::random(g));
            checkGroupLaws<d, E>(Rig<d, E>::random(g));
        }
        // A non-trivial transformation is not the identity (guards against a tfDistance that is always 0).
        EXPECT_GT((tfDistance<d, E>(Rig<d, E>::random(g), Rig<d, E>::identity())), E(0.01));
        // Rotation inverse is the transpose, exactly.
        const auto r = Rot<d, E>::random(g);
        EXPECT_EQ(r.inverted().rotMat().data(), r.rotMat().data().transpose());
        EXPECT_EQ(r.inverted().inverted().rotMat(), r.rotMat());
    }

    // ---- cast ------------------------------------------------------------------------------------------------------
    template<int d, typename E>
    void checkCast()
    {
        using Other = std::conditional_t<std::is_same_v<E, float>, double, float>;
        Gen g(400 + d);
        const auto t = Tr<d, E>::random(g);
        const auto r = Rot<d, E>::random(g);
        const auto k = Rig<d, E>::random(g);
        const Tr<d, Other> tc = t.template cast<Other>();
        const Rot<d, Other> rc = r.template cast<Other>();
        const Rig<d, Other> kc = k.template cast<Other>();
        EXPECT_LE((tc.trVec().data() - t.trVec().data().template cast<Other>()).norm(), Other(0));
        EXPECT_LE((rc.rotMat().data() - r.rotMat().data().template cast<Other>()).norm(), Other(0));
        EXPECT_LE((kc.rotMat().data() - k.rotMat().data().template cast<Other>()).norm(), Other(0));
        EXPECT_LE((kc.trVec().data() - k.trVec().data().template cast<Other>()).norm(), Other(0));
        // Round trip through the other type.
        EXPECT_LE((tfDistance<d, E>(kc.template cast<E>(), k)), tol<float>());
    }

    // ---- general N-D setRot ----------------------------------------------------------------------------------------
    template<int d, typename E>
    void checkGeneralSetRot()
    {
        using V = rtl::VectorND<d, E>;
        Gen g(500 + d);
        for (int rep = 0; rep < 20; ++rep)
        {
            const V v1 = tf_test::randomVector<d, E>(g), v2 = tf_test::randomVector<d, E>(g);
            Rot<d, E> r;
            r.rtl::template RotationND_common<d, E, rtl::RotationND>::setRot(v1, v2);
            EXPECT_LE(tf_test::rotationError(r.rotMat()), tol<E>());
            // v1's direction goes to v2's direction.
            EXPECT_LE((r(v1).data().normalized() - v2.data().normalized()).norm(), tol<E>());
            // Vectors orthogonal to the plane of v1 and v2 are fixed.
            typename V::EigenType w = tf_test::randomVector<d, E>(g).data();
            const typename V::EigenType u1 = v1.data().normalized();
            typename V::EigenType u2 = v2.data() - v2.data().dot(u1) * u1;
            u2.normalize();
            w -= w.dot(u1) * u1 + w.dot(u2) * u2;
            EXPECT_LE((r(V(w)).data() - w).norm(), tol<E>());
            // The constructor and the base method agree (general child: same algorithm).
            if constexpr (d > 3)
            {
                EXPECT_LE(dist(Rot<d, E>(v1, v2).rotMat(), r.rotMat()), E(0));
            }
        }
        // Degenerate inputs: parallel -> identity, zero -> identity, antiparallel -> a rotation by pi.
        const V v = tf_test::randomVector<d, E>(g);
        Rot<d, E> r;
        r.rtl::template RotationND_common<d, E, rtl::RotationND>::setRot(v, v * E(3));
        EXPECT_LE(dist(r.rotMat(), rtl::Matrix<d, d, E>::identity()), tol<E>());
        r.rtl::template RotationND_common<d, E, rtl::RotationND>::setRot(V::zeros(), v);
        EXPECT_EQ(r.rotMat(), (rtl::Matrix<d, d, E>::identity()));
        r.rtl::template RotationND_common<d, E, rtl::RotationND>::setRot(v, v * E(-2));
        EXPECT_LE(tf_test::rotationError(r.rotMat()), tol<E>());
        EXPECT_LE((r(v).data() + v.data()).norm(), tol<E>());
    }

    //! The general algorithm equals the 2D/3D specialised constructors (docs/reference.md, "RotationND").
    template<int d, typename E>
    void checkGeneralEqualsSpecialised()
    {
        Gen g(600 + d);
        for (int rep = 0; rep < 50; ++rep)
        {
            const auto v1 = tf_test::randomVector<d, E>(g), v2 = tf_test::randomVector<d, E>(g);
            Rot<d, E> gen;
            gen.rtl::template RotationND_common<d, E, rtl::RotationND>::setRot(v1, v2);
            const Rot<d, E> spec(v1, v2);
            EXPECT_LE(dist(gen.rotMat(), spec.rotMat()), E(d * d) * tol<E>());
            EXPECT_LE(std::abs(gen.rotAngle()), rtl::C_PI<E> + tol<E>());
            if constexpr (d == 3)
            {
                // Cache coherence: the base method refreshed the cached angle-axis of the 3D child.
                EXPECT_NEAR(gen.rotAngle(), spec.rotAngle(), tol<E>());
                const Eigen::Matrix<E, 3, 3> aa = Eigen::AngleAxis<E>(gen.rotAngle(), gen.rotAxis().data()).toRotationMatrix();
                EXPECT_LE((aa - gen.rotMat().data()).norm(), tol<E>());
            }
        }
    }

    // ---- rotation by 2 pi / d applied d times ----------------------------------------------------------------------
    template<int d, typename E>
    void checkFullTurn()
    {
        using V = rtl::VectorND<d, E>;
        Gen g(700 + d);
        for (int rep = 0; rep < 10; ++rep)
        {
            // A random plane (u1, u2) and v2 at angle 2 pi / d from v1 = u1 in it.
            const typename V::EigenType u1 = tf_test::randomVector<d, E>(g).data().normalized();
            typename V::EigenType u2 = tf_test::randomVector<d, E>(g).data();
            u2 = (u2 - u2.dot(u1) * u1).normalized();
            const E angle = E(2) * rtl::C_PI<E> / E(d);
            const V v1(u1), v2(typename V::EigenType(std::cos(angle) * u1 + std::sin(angle) * u2));
            const Rot<d, E> r(v1, v2);
            const V x = tf_test::randomVector<d, E>(g);
            V y = x;
            for (int i = 0; i < d; ++i)
            {
                y = r(y);
                if (i == 0)   // one step really moves the in-plane part (by 2 |sin(pi/d)| of its length)
                {
                    const E in_plane = std::hypot(x.data().dot(u1), x.data().dot(u2));
                    EXPECT_NEAR(dist(x, y), E(2) * std::sin(rtl::C_PI<E> / E(d)) * in_plane, E(4) * tol<E>());
                }
            }
            EXPECT_LE(dist(x, y), E(d) * tol<E>());
        }
    }

    // ---- random ----------------------------------------------------------------------------------------------------
    template<int d, typename E>
    void checkRandom()
    {
        Gen g1(42), g2(42);
        EXPECT_LE((tfDistance<d, E>(Rig<d, E>::random(g1), Rig<d, E>::random(g2))), E(0));     // reproducible
        EXPECT_GT((tfDistance<d, E>(Rig<d, E>::random(g1), Rig<d, E>::random(g1))), E(1e-3));  // and not constant
        // Translation elements are drawn in index order.
        Gen g3(9), g4(9);
        const auto t = Tr<d, E>::random(g3);
        for (int i = 0; i < d; ++i)
            EXPECT_EQ(t.trVec()[static_cast<size_t>(i)], static_cast<E>(g4()));
    }
}

TEST(Transformations, CompositionResultTypes)
{
    TF_FOR_ALL_DIMS_AND_TYPES(checkCompositionTypes);
}

TEST(Transformations, AllPairsFollowTheApplicationConvention)
{
    TF_FOR_DIMS_AND_TYPES(checkAllPairs);
}

TEST(Transformations, ApplicationFormulas)
{
    TF_FOR_DIMS_AND_TYPES(checkApplicationFormulas);
}

TEST(Transformations, Associativity)
{
    TF_FOR_DIMS_AND_TYPES(checkAssociativity);
}

TEST(Transformations, InverseAndIdentityLaws)
{
    TF_FOR_DIMS_AND_TYPES(checkInverseIdentity);
}

TEST(Transformations, CastAllThree)
{
    TF_FOR_DIMS_AND_TYPES(checkCast);
}

TEST(Transformations, GeneralSetRot)
{
    TF_FOR_DIMS_AND_TYPES(checkGeneralSetRot);
}

TEST(Transformations, GeneralSetRotEqualsSpecialisedConstructors)
{
    checkGeneralEqualsSpecialised<2, float>();
    checkGeneralEqualsSpecialised<2, double>();
    checkGeneralEqualsSpecialised<3, float>();
    checkGeneralEqualsSpecialised<3, double>();
}

TEST(Transformations, RotationByTwoPiOverDAppliedDTimes)
{
    TF_FOR_ALL_DIMS_AND_TYPES(checkFullTurn);
}

TEST(Transformations, RandomIsReproducible)
{
    TF_FOR_DIMS_AND_TYPES(checkRandom);
    Gen g(5);
    const auto t1 = rtl::TranslationND<1, double>::random(g);
    EXPECT_EQ(t1.dimensionality(), 1);
    EXPECT_EQ(t1.inverted().inverted().trVec(), t1.trVec());
}

TEST(Translation, ConstructionAndAccessors)
{
    const rtl::Translation2f t(1, 1);
    EXPECT_EQ(t.trVec(), rtl::Vector2f(1, 1));
    rtl::TranslationND<3, double> t3{0.0, 0.0, 0.0};
    EXPECT_EQ(t3.trVec(), rtl::Vector3d::zeros());
    t3.setTrVec({1.0, 2.0, 3.0});
    t3.setTrVecX(10);
    t3.setTrVecZ(-3);
    EXPECT_EQ(t3.trVecX(), 10.0);
    EXPECT_EQ(t3.trVecY(), 2.0);
    EXPECT_EQ(t3.trVecZ(), -3.0);
    const rtl::TranslationND<3, double> t3v{rtl::VectorND<3, double>{1.0, 2.0, 2.0}};
    EXPECT_DOUBLE_EQ(rtl::Translation3d::distance(t3v, rtl::Translation3d::identity()), 3.0);
    EXPECT_DOUBLE_EQ(rtl::Translation3d::distanceSquared(t3v, rtl::Translation3d::identity()), 9.0);
    const rtl::TranslationND<5, float> t5(1, 2, 3, 4, 5);
    EXPECT_EQ(t5.trVec()[4], 5.0f);
    EXPECT_EQ(t5.inverted().trVec()[2], -3.0f);
    EXPECT_EQ(rtl::Translation3f(0, 0, -2)(rtl::Vector3f(1, 1, 1)), rtl::Vector3f(1, 1, -1));
    rtl::Translation2d t2;                                           // default: zero
    EXPECT_EQ(t2.trVec(), rtl::Vector2d::zeros());
    t2.setTrVecY(4);
    EXPECT_EQ(t2.trVecY(), 4.0);
}

TEST(Rotation2D, AngleAccessors)
{
    for (int i = -17; i <= 18; ++i)
    {
        const double a = i * rtl::C_PId / 18;
        const rtl::Rotation2d r(a);
        EXPECT_NEAR(r.rotAngle(), a, 1e-12);
        EXPECT_DOUBLE_EQ(r.rotCos(), std::cos(a));
        EXPECT_DOUBLE_EQ(r.rotSin(), std::sin(a));
        // Counter-clockwise: the x axis goes to (cos a, sin a).
        const rtl::Vector2d x = r(rtl::Vector2d(1, 0));
        EXPECT_NEAR(x.x(), std::cos(a), 1e-12);
        EXPECT_NEAR(x.y(), std::sin(a), 1e-12);
        // The two-vector constructor recovers the angle.
        EXPECT_NEAR(rtl::Rotation2d(rtl::Vector2d(2, 0), x * 3.0).rotAngle(), a, 1e-12);
    }
    rtl::Rotation2f r;
    EXPECT_EQ(r.rotAngle(), 0.0f);
    r.setAngle(1.0f);
    EXPECT_FLOAT_EQ(r.rotAngle(), 1.0f);
    EXPECT_EQ(rtl::Rotation2f(0.0f).rotMat(), rtl::Matrix22f::identity());
}

TEST(RigidTf2D, ConstructorsAndAccessors)
{
    rtl::RigidTf2d k(0.5, 1.0, 2.0);
    EXPECT_NEAR(k.rotAngle(), 0.5, 1e-12);
    EXPECT_EQ(k.trVecX(), 1.0);
    EXPECT_EQ(k.trVecY(), 2.0);
    EXPECT_DOUBLE_EQ(k.rotCos(), std::cos(0.5));
    EXPECT_DOUBLE_EQ(k.rotSin(), std::sin(0.5));
    k.setAngle(-1.0);
    k.setTrVecX(3);
    k.setTrVecY(4);
    EXPECT_NEAR(k.rotAngle(), -1.0, 1e-12);
    EXPECT_LE((tfDistance<2, double>(k, rtl::RigidTf2d(-1.0, rtl::Vector2d(3, 4)))), 1e-15);
    // (rot_from, rot_to, tr) and (rot, tr) constructors.
    const rtl::RigidTf2d k2(rtl::Vector2d(1, 0), rtl::Vector2d(0, 5), rtl::Vector2d(1, 1));
    EXPECT_NEAR(k2.rotAngle(), rtl::C_PI_2d, 1e-12);
    const rtl::RigidTf2d k3(rtl::Rotation2d(rtl::C_PI_2d), rtl::Translation2d(1, 1));
    EXPECT_LE((tfDistance<2, double>(k2, k3)), 1e-12);
    EXPECT_LE((tfDistance<2, double>(rtl::RigidTf2d(rtl::Translation2d(1, 2)), rtl::Translation2d(1, 2))), 0.0);
    EXPECT_LE((tfDistance<2, double>(rtl::RigidTf2d(rtl::Rotation2d(0.3)), rtl::Rotation2d(0.3))), 0.0);
    rtl::RigidTf2d k4;
    k4.setTrVec({5.0, 6.0});
    k4.setRot(rtl::Vector2d(1, 0), rtl::Vector2d(-1, 0));
    EXPECT_NEAR(std::abs(k4.rotAngle()), rtl::C_PId, 1e-12);
    EXPECT_EQ(k4.trVec(), rtl::Vector2d(5, 6));
}

TEST(Rotation3D, AngleAxisQuaternionMatrixRpyConsistency)
{
    Gen g(800);
    for (int rep = 0; rep < 100; ++rep)
    {
        const auto r = rtl::Rotation3d::random(g);
        const Eigen::Matrix3d m = r.rotMat().data();
        // angle-axis <-> matrix
        EXPECT_LE((Eigen::AngleAxisd(r.rotAngle(), r.rotAxis().data()).toRotationMatrix() - m).norm(), 1e-12);
        EXPECT_NEAR(r.rotAxis().data().norm(), 1.0, 1e-12);
        EXPECT_GE(r.rotAngle(), 0.0);
        EXPECT_LE(r.rotAngle(), rtl::C_PId);
        EXPECT_DOUBLE_EQ(r.rotCos(), std::cos(r.rotAngle()));
        EXPECT_DOUBLE_EQ(r.rotSin(), std::sin(r.rotAngle()));
        EXPECT_LE(dist(rtl::Rotation3d(r.rotAngle(), r.rotAxis()).rotMat(), r.rotMat()), 1e-12);
        // quaternion <-> matrix
        const rtl::Quaterniond q = r.rotQuaternion();
        EXPECT_LE((q.data().toRotationMatrix() - m).norm(), 1e-12);
        EXPECT_LE(dist(rtl::Rotation3d(q).rotMat(), r.rotMat()), 1e-12);
        EXPECT_LE(dist(rtl::Rotation3d(q * 2.0).rotMat(), r.rotMat()), 1e-12);          // normalised on construction
        // RPY round trip, and agreement with Quaternion(roll, pitch, yaw)
        double roll, pitch, yaw;
        r.rotRpy(roll, pitch, yaw);
        EXPECT_LE(dist(rtl::Rotation3d(roll, pitch, yaw).rotMat(), r.rotMat()), 1e-12);
        EXPECT_LE((rtl::Quaterniond(roll, pitch, yaw).data().toRotationMatrix() - m).norm(), 1e-12);
        // Cache coherence after each matrix-changing operation.
        auto check = [](const rtl::Rotation3d &x) {
            EXPECT_LE((Eigen::AngleAxisd(x.rotAngle(), x.rotAxis().data()).toRotationMatrix() - x.rotMat().data()).norm(), 1e-12);
            EXPECT_LE((x.rotQuaternion().data().toRotationMatrix() - x.rotMat().data()).norm(), 1e-12);
        };
        const auto r2 = rtl::Rotation3d::random(g);
        check(r2(r));
        check(r.inverted());
        check(r.inverted().inverted());
        rtl::Rotation3d r3 = r;
        r3.invert();
        check(r3);
        r3.transform(r2);
        check(r3);
        check(rtl::RigidTf3d::random(g)(r).rot());
        const rtl::Rotation3f rf = r.cast<float>();
        EXPECT_LE((Eigen::AngleAxisf(rf.rotAngle(), rf.rotAxis().data()).toRotationMatrix() - rf.rotMat().data()).norm(), 1e-5f);
        EXPECT_NEAR(rf.rotAngle(), static_cast<float>(r.rotAngle()), 1e-5f);
    }
}

TEST(Rotation3D, KnownValuesAndExactAxisAligned)
{
    // RPY yaw 90 degrees maps (10, 1, 1) to (-1, 10, 1).
    const rtl::RigidTf3d yaw{0, 0, rtl::C_PI_2d, rtl::Vector3d(0, 0, 0)};
    EXPECT_LE(dist(yaw(rtl::Vector3d(10, 1, 1)), rtl::Vector3d(-1, 10, 1)), 1e-10);
    // Roll about x, pitch about y.
    EXPECT_LE(dist(rtl::Rotation3d(rtl::C_PI_2d, 0.0, 0.0)(rtl::Vector3d(0, 1, 0)), rtl::Vector3d(0, 0, 1)), 1e-12);
    EXPECT_LE(dist(rtl::Rotation3d(0.0, rtl::C_PI_2d, 0.0)(rtl::Vector3d(0, 0, 1)), rtl::Vector3d(1, 0, 0)), 1e-12);
    // An axis-aligned angle-axis gives exact 0/1 entries (bounding boxes compare with EXPECT_EQ).
    const rtl::RigidTf3d ax(rtl::C_PI_4d, rtl::Vector3d::baseX(), rtl::Vector3d());
    EXPECT_EQ(ax.rotMat().data().row(0), Eigen::RowVector3d(1, 0, 0));
    EXPECT_EQ(ax.rotMat().data().col(0), Eigen::Vector3d(1, 0, 0));
    EXPECT_EQ(ax.trVec(), rtl::Vector3d::zeros());
    // The identity quaternion translates exactly.
    const rtl::RigidTf3d q{rtl::Quaternion<double>::identity(), rtl::Vector3D<double>{2, 0, 0}};
    EXPECT_EQ(q(rtl::Vector3d(1, 2, 3)), rtl::Vector3d(3, 2, 3));
    // Identity: angle 0 about x.
    const auto id = rtl::Rotation3f::identity();
    EXPECT_EQ(id.rotAngle(), 0.0f);
    EXPECT_EQ(id.rotAxis(), rtl::Vector3f(1, 0, 0));
    EXPECT_EQ(id.rotMat(), rtl::Matrix33f::identity());
    // Shortest rotation between two vectors: axis is their cross product.
    const rtl::Rotation3d r(rtl::Vector3d(1, 0, 0), rtl::Vector3d(0, 2, 0));
    EXPECT_NEAR(r.rotAngle(), rtl::C_PI_2d, 1e-12);
    EXPECT_LE(dist(r.rotAxis(), rtl::Vector3d(0, 0, 1)), 1e-12);
    // Degenerate inputs give the identity instead of NaN.
    EXPECT_EQ(rtl::Rotation3d(1.0, rtl::Vector3d::zeros()).rotMat(), rtl::Matrix33d::identity());
    EXPECT_EQ(rtl::Rotation3d(rtl::Vector3d::zeros(), rtl::Vector3d(1, 0, 0)).rotMat(), rtl::Matrix33d::identity());
}

TEST(Rotation3D, SettersKeepViewsConsistent)
{
    rtl::Rotation3d r(0.3, rtl::Vector3d(0, 0, 2));
    EXPECT_DOUBLE_EQ(r.rotAngle(), 0.3);
    EXPECT_EQ(r.rotAxis(), rtl::Vector3d(0, 0, 1));
    r.setAngle(-0.7);
    EXPECT_DOUBLE_EQ(r.rotAngle(), -0.7);
    EXPECT_LE(dist(r(rtl::Vector3d(1, 0, 0)), rtl::Vector3d(std::cos(-0.7), std::sin(-0.7), 0)), 1e-12);
    r.setAxis(rtl::Vector3d(0, 3, 0));
    EXPECT_EQ(r.rotAxis(), rtl::Vector3d(0, 1, 0));
    EXPECT_LE(dist(r.rotMat(), rtl::Rotation3d(-0.7, rtl::Vector3d(0, 1, 0)).rotMat()), 0.0);
    r.setAngleAxis(1.1, rtl::Vector3d(1, 1, 0));
    EXPECT_LE(dist(r.rotAxis(), rtl::Vector3d(std::sqrt(0.5), std::sqrt(0.5), 0)), 1e-15);
    r.setRot(rtl::Vector3d(0, 0, 1), rtl::Vector3d(0, 0, -1));      // antiparallel: any rotation by pi
    EXPECT_NEAR(r.rotAngle(), rtl::C_PId, 1e-9);
    EXPECT_LE(dist(r(rtl::Vector3d(0, 0, 1)), rtl::Vector3d(0, 0, -1)), 1e-12);

    rtl::RigidTf3f k(0.5f, rtl::Vector3f(0, 0, 1), rtl::Vector3f(1, 2, 3));
    EXPECT_FLOAT_EQ(k.rotAngle(), 0.5f);
    EXPECT_EQ(k.rotAxis(), rtl::Vector3f(0, 0, 1));
    EXPECT_EQ(k.trVecX(), 1.0f);
    EXPECT_EQ(k.trVecY(), 2.0f);
    EXPECT_EQ(k.trVecZ(), 3.0f);
    EXPECT_FLOAT_EQ(k.rotCos(), std::cos(0.5f));
    EXPECT_FLOAT_EQ(k.rotSin(), std::sin(0.5f));
    k.setAngleAxis(0.25f, rtl::Vector3f(1, 0, 0));
    k.setTrVecZ(-1);
    EXPECT_FLOAT_EQ(k.rotAngle(), 0.25f);
    EXPECT_EQ(k.trVecZ(), -1.0f);
    k.setAngle(0.5f);
    k.setAxis(rtl::Vector3f(0, 1, 0));
    EXPECT_LE((tfDistance<3, float>(k, rtl::RigidTf3f(0.5f, rtl::Vector3f(0, 1, 0), rtl::Vector3f(1, 2, -1)))), 0.0f);
    float roll, pitch, yaw;
    k.rotRpy(roll, pitch, yaw);
    EXPECT_LE((tfDistance<3, float>(k, rtl::RigidTf3f(roll, pitch, yaw, k.trVec()))), 1e-5f);
    EXPECT_LE((tfDistance<3, float>(k, rtl::RigidTf3f(k.rotQuaternion(), k.trVec()))), 1e-5f);
    // Composition of two random rigid transforms keeps the angle-axis of the result consistent.
    Gen g(900);
    const auto a = rtl::RigidTf3d::random(g), b = rtl::RigidTf3d::random(g);
    const auto c = b(a);
    EXPECT_LE((Eigen::AngleAxisd(c.rotAngle(), c.rotAxis().data()).toRotationMatrix() - c.rotMat().data()).norm(), 1e-12);
    EXPECT_LE((tfDistance<3, double>(rtl::RigidTf3d(c.rotQuaternion(), c.trVec()), c)), 1e-12);
}
