// The management layer of the transformation module: GeneralTf dispatch and result-type collapse, VariantResultType
// and its type-level helpers, TfChain (application order, squash, result types), TfTreeNode linking and TfTree
// (insert/erase/queries against manual composition, deep copy, move).
#include <gtest/gtest.h>

#include <cstdint>
#include <initializer_list>
#include <list>
#include <map>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "rtl/Core.h"
#include "rtl/Transformation.h"
#include "tf_helpers.h"

// ====================================================================================================================
// GeneralTf dispatch and result-type collapse; VariantResultType and its type-level helpers.
using tf_test::Gen;
using tf_test::dist;
using tf_test::tfDistance;
using rtl::Vector2f;
using rtl::Vector3d;
using rtl::Translation2f;
using rtl::Rotation2f;
using rtl::RigidTf2f;
using rtl::VariantResultType;

namespace
{
    using GTf = rtl::GeneralTf<Translation2f, Rotation2f, RigidTf2f>;

    // Toy types for the closure helpers: A -> B -> C under Step, C is a dead end; X <-> Y under Flip.
    struct Step {};
    struct C {};
    struct B { C transformed(const Step &) const { return {}; } };
    struct A { B transformed(const Step &) const { return {}; } };
    struct Flip {};
    struct Y;
    struct X { Y transformed(const Flip &) const; };
    struct Y { X transformed(const Flip &) const { return {}; } };
    Y X::transformed(const Flip &) const { return {}; }

    // ---- type-level helpers ----------------------------------------------------------------------------------------
    static_assert(std::is_same_v<rtl::Unique<VariantResultType<>, int, void, float, int, void>::type, VariantResultType<int, float>>);
    static_assert(std::is_same_v<rtl::Unique<VariantResultType<float>, int, float>::type, VariantResultType<float, int>>);
    static_assert(std::is_same_v<rtl::StripIfUnique<VariantResultType<int>>::type, int>);
    static_assert(std::is_same_v<rtl::StripIfUnique<VariantResultType<int, float>>::type, VariantResultType<int, float>>);
    static_assert(std::is_same_v<rtl::StripIfUnique<double>::type, double>);

    static_assert(std::is_same_v<rtl::VariantResultOTs<Vector2f, Translation2f, Rotation2f, RigidTf2f>, VariantResultType<Vector2f>>);
    static_assert(std::is_same_v<rtl::VariantResultOTs<Translation2f, Translation2f, Rotation2f, RigidTf2f>,
                                 VariantResultType<Translation2f, RigidTf2f>>);
    static_assert(std::is_same_v<rtl::VariantResultOTs<Rotation2f, Translation2f, Rotation2f, RigidTf2f>,
                                 VariantResultType<RigidTf2f, Rotation2f>>);
    static_assert(std::is_same_v<rtl::VariantResultOTsStripped<Vector2f, Translation2f, rtl::Translation3f>, Vector2f>);
    static_assert(std::is_same_v<rtl::VariantResultOTs<Vector3d, Translation2f>, VariantResultType<>>);
    static_assert(std::is_same_v<rtl::VariantResultTOs<Translation2f, Vector2f, Translation2f, Vector3d>,
                                 VariantResultType<Vector2f, Translation2f>>);
    static_assert(std::is_same_v<rtl::VariantResultTOsStripped<Translation2f, Vector2f, Vector3d>, Vector2f>);

    // Real closure, not one step: A -> B -> C, and a cycle X -> Y -> X.
    static_assert(std::is_same_v<rtl::VariantResultOTs<A, Step>, VariantResultType<B>>);
    static_assert(std::is_same_v<rtl::VariantResultRecursive<A, Step>, VariantResultType<B, C>>);
    static_assert(std::is_same_v<rtl::VariantResultRecursiveStripped<A, Step>, VariantResultType<B, C>>);
    static_assert(std::is_same_v<rtl::VariantResultRecursive<A, rtl::GeneralTf<Step>>, VariantResultType<B, C>>);
    static_assert(std::is_same_v<rtl::VariantResultRecursive<X, Flip>, VariantResultType<Y, X>>);
    static_assert(std::is_same_v<rtl::VariantResultRecursiveStripped<B, Step>, C>);
    static_assert(std::is_same_v<rtl::Expansion<VariantResultType<A>, VariantResultType<A>, Step>::type, VariantResultType<A, B>>);
    static_assert(std::is_same_v<rtl::Recursion<VariantResultType<A>, Step>::type, VariantResultType<A, B, C>>);
    static_assert(std::is_same_v<rtl::VariantResultRecursiveStripped<Vector2f, GTf>, Vector2f>);
    static_assert(std::is_same_v<rtl::VariantResultRecursiveStripped<Translation2f, GTf>, VariantResultType<Translation2f, RigidTf2f>>);
    static_assert(std::is_same_v<rtl::VariantResultRecursiveStripped<Vector2f, RigidTf2f>, Vector2f>);

    // is_transformable with a GeneralTf: value and the actual result type.
    static_assert(rtl::is_transformable_v<Vector2f, GTf>);
    static_assert(std::is_same_v<rtl::is_transformable_t<Vector2f, GTf>, Vector2f>);
    static_assert(std::is_same_v<rtl::is_transformable<Translation2f, GTf>::type, VariantResultType<Translation2f, RigidTf2f>>);
    static_assert(!rtl::is_transformable_v<Vector3d, GTf>);
    static_assert(!rtl::is_transformable_v<rtl::Quaternionf, rtl::GeneralTf<rtl::Translation3f, rtl::Rotation3f>>);

    // VariantResultType conversions are constrained to its alternatives.
    static_assert(std::is_convertible_v<Translation2f, VariantResultType<Translation2f, RigidTf2f>>);
    static_assert(!std::is_convertible_v<Rotation2f, VariantResultType<Translation2f, RigidTf2f>>);
    static_assert(std::is_convertible_v<VariantResultType<Translation2f, RigidTf2f>, RigidTf2f>);
    static_assert(!std::is_convertible_v<VariantResultType<Translation2f, RigidTf2f>, Rotation2f>);
    static_assert(std::is_convertible_v<VariantResultType<RigidTf2f>, VariantResultType<Translation2f, RigidTf2f>>);
    static_assert(!std::is_convertible_v<VariantResultType<Translation2f, RigidTf2f>, VariantResultType<RigidTf2f>>);
    static_assert(VariantResultType<Translation2f, RigidTf2f>::alternatives_cnt == 2);
    static_assert(VariantResultType<>::alternatives_cnt == 0);
    static_assert(!std::is_default_constructible_v<VariantResultType<Translation2f, RigidTf2f>>);

    // random() is SFINAE-friendly: it accepts only nullary callables, so has_random reports the truth (true for
    // every transformation, false for a non-callable or void generator; docs/reference.md, "Type traits").
    static_assert(rtl::has_random_v<Translation2f> && rtl::has_random_v<Rotation2f> && rtl::has_random_v<RigidTf2f>);
    static_assert(rtl::has_random_v<rtl::RigidTfND<4, double>, tf_test::Gen>);
    static_assert(!rtl::has_random_v<RigidTf2f, int> && !rtl::has_random_v<rtl::Rotation3d, void>);
    static_assert(!rtl::has_random_v<rtl::Translation3f, tf_test::Gen, tf_test::Gen>);
    static_assert(rtl::has_random_v<GTf, tf_test::Gen> && rtl::has_random_v<GTf, tf_test::Gen, tf_test::Gen>);

    // GeneralTf construction and assignment are constrained to its alternatives.
    static_assert(std::is_convertible_v<Rotation2f, GTf>);
    static_assert(!std::is_convertible_v<rtl::Rotation3f, GTf>);
    static_assert(std::is_assignable_v<GTf &, GTf &>);
    static_assert(!std::is_assignable_v<GTf &, rtl::Rotation3f>);
}

TEST(VariantResult, ConversionsAndIndex)
{
    using VR = VariantResultType<Translation2f, RigidTf2f>;
    const VR t = Translation2f(1, 2);
    EXPECT_EQ(t.index(), 0u);
    const Translation2f back = t;
    EXPECT_EQ(back.trVec(), Vector2f(1, 2));
    EXPECT_THROW(static_cast<void>(static_cast<RigidTf2f>(t)), std::bad_variant_access);
    VR r = RigidTf2f(0.5f, 1.f, 1.f);
    EXPECT_EQ(r.index(), 1u);
    r = t;                                            // copy assignment switches the held type
    EXPECT_EQ(r.index(), 0u);
    VR m(std::move(r));
    EXPECT_EQ(static_cast<Translation2f>(m).trVec(), Vector2f(1, 2));
    // From a subset with a different order.
    const VariantResultType<RigidTf2f> sub = RigidTf2f(0.25f, 0.f, 0.f);
    const VR widened = sub;
    EXPECT_EQ(widened.index(), 1u);
    EXPECT_FLOAT_EQ(static_cast<RigidTf2f>(widened).rotAngle(), 0.25f);
    const VariantResultType<RigidTf2f, Translation2f> reordered = t;
    const VR back2 = reordered;
    EXPECT_EQ(back2.index(), 0u);
    EXPECT_EQ(back2.visit([](const auto &x) { return x.dimensionality(); }), 2);
}

TEST(GeneralTf, DispatchesOnEachHeldType)
{
    Gen g(1200);
    for (int rep = 0; rep < 10; ++rep)
    {
        const auto t = Translation2f::random(g);
        const auto r = Rotation2f::random(g);
        const auto k = RigidTf2f::random(g);
        const auto v = tf_test::randomVector<2, float>(g);
        const GTf gt(t), gr(r), gk(k);
        EXPECT_EQ(gt.index(), 0u);
        EXPECT_EQ(gr.index(), 1u);
        EXPECT_EQ(gk.index(), 2u);
        static_assert(std::is_same_v<decltype(gt(v)), Vector2f>);    // every alternative maps a vector to a vector
        EXPECT_EQ(gt(v), t(v));
        EXPECT_EQ(gr(v), r(v));
        EXPECT_EQ(gk(v), k(v));
        // Transformations as objects: the result type is the set of possible results.
        static_assert(std::is_same_v<decltype(gr(t)), VariantResultType<Translation2f, RigidTf2f>>);
        static_assert(std::is_same_v<decltype(gt(r)), VariantResultType<RigidTf2f, Rotation2f>>);
        static_assert(std::is_same_v<decltype(gt(k)), RigidTf2f>);
        const Translation2f tt = gt(t);
        EXPECT_EQ(tt.trVec(), t(t).trVec());
        const RigidTf2f rt = gr(t);
        EXPECT_LE((tfDistance<2, float>(rt, r(t))), 0.0f);
        EXPECT_THROW(static_cast<void>(static_cast<Translation2f>(gr(t))), std::bad_variant_access);
        // tf<T>() and conversions.
        EXPECT_EQ(gt.tf<Translation2f>().trVec(), t.trVec());
        EXPECT_THROW(static_cast<void>(gt.tf<Rotation2f>()), std::bad_variant_access);
        GTf copy = gk;
        const RigidTf2f kk = copy;
        EXPECT_LE((tfDistance<2, float>(kk, k)), 0.0f);
    }
}

TEST(GeneralTf, AlternativeThatCannotTransformThrows)
{
    using Mixed = rtl::GeneralTf<Translation2f, Rotation2f, rtl::Translation3f>;
    static_assert(std::is_same_v<decltype(std::declval<const Mixed &>()(Vector2f())), Vector2f>);
    const Mixed m2(Translation2f(1, 1));
    EXPECT_EQ(m2(Vector2f(1, 1)), Vector2f(2, 2));
    const Mixed m3(rtl::Translation3f(1, 1, 1));
    EXPECT_THROW(static_cast<void>(m3(Vector2f(1, 1))), std::bad_variant_access);
    EXPECT_EQ(m3(rtl::Vector3f(0, 0, 0)), rtl::Vector3f(1, 1, 1));
}

TEST(GeneralTf, CompositionTransformAndInverse)
{
    Gen g(1300);
    const auto t = Translation2f::random(g);
    const auto r = Rotation2f::random(g);
    const auto k = RigidTf2f::random(g);
    GTf gk(k), gr(r), gt(t);
    // gtf(gtf): the argument first, then this.
    const GTf c = gr(gk);
    EXPECT_LE((tfDistance<2, float>(c, r(k))), 1e-6f);
    const GTf nested = gk(gk(gk));
    EXPECT_LE((tfDistance<2, float>(nested, k(k(k)))), 1e-5f);
    // transformed / transform with plain and general arguments.
    EXPECT_LE((tfDistance<2, float>(gt.transformed(Translation2f(1, 10)), Translation2f(1, 10)(t))), 1e-6f);
    EXPECT_LE((tfDistance<2, float>(gt.transformed(gr), r(t))), 1e-6f);
    GTf m = gt;
    m.transform(Translation2f(10, 10));
    EXPECT_EQ(m.index(), 0u);
    EXPECT_LE((tfDistance<2, float>(m, Translation2f(10, 10)(t))), 1e-6f);
    m.transform(m);
    EXPECT_LE((tfDistance<2, float>(m, Translation2f(10, 10)(t)(Translation2f(10, 10)(t)))), 1e-5f);
    m.transform(gr);
    EXPECT_EQ(m.index(), 2u);                          // translation then rotation is a RigidTf
    // Inverse of the held alternative.
    EXPECT_LE((tfDistance<2, float>(gk.inverted()(gk), RigidTf2f::identity())), 1e-5f);
    GTf inv = gr;
    inv.invert();
    EXPECT_EQ(inv.index(), 1u);
    EXPECT_LE((tfDistance<2, float>(inv, r.inverted())), 0.0f);
    // A composition whose result type is not an alternative throws.
    using TrRot = rtl::GeneralTf<Translation2f, Rotation2f>;
    TrRot tr(Translation2f(1, 1));
    EXPECT_THROW(tr.transform(Rotation2f(0.5f)), std::bad_variant_access);
    EXPECT_EQ(tr.index(), 0u);                        // unchanged after the failed transform
    EXPECT_NO_THROW(tr.transform(Translation2f(1, 1)));
}

TEST(GeneralTf, AssignmentAndCopy)
{
    GTf a(Translation2f(1, 2)), b(Rotation2f(0.5f));
    a = b;                                            // non-const lvalue: plain copy assignment (fixed defect)
    EXPECT_EQ(a.index(), 1u);
    EXPECT_EQ(a.tf<Rotation2f>().rotMat(), b.tf<Rotation2f>().rotMat());
    a = RigidTf2f(0.1f, 2.f, 3.f);                    // assigning an alternative switches the held type
    EXPECT_EQ(a.index(), 2u);
    GTf c(a);
    EXPECT_EQ(c.index(), 2u);
    GTf d(std::move(c));
    EXPECT_EQ(d.tf<RigidTf2f>().trVecY(), 3.0f);
    const GTf def;
    EXPECT_EQ(def.index(), 0u);                       // value-initialised first alternative
    EXPECT_EQ(def.tf<Translation2f>().trVec(), Vector2f(0, 0));
}

TEST(GeneralTf, ExplicitTemplateOperatorCallWithConversion)
{
    using G3 = rtl::GeneralTf<rtl::Translation3d, rtl::Rotation3d, rtl::RigidTf3d>;
    Gen g(1400);
    const auto k1 = rtl::RigidTf3d::random(g), k2 = rtl::RigidTf3d::random(g);
    G3 gtf(k1);
    G3 gtfAggregated(k2);
    // Selects operator()(const T &) with T = RigidTf3d; the argument converts through operator T().
    gtf = gtf.template operator()<rtl::RigidTfND<3, double>>(gtfAggregated);
    EXPECT_EQ(gtf.index(), 2u);
    EXPECT_LE((tfDistance<3, double>(gtf, k1(k2))), 1e-12);
    // Conversion of a prvalue.
    const auto prv = (rtl::RigidTfND<3, double>) G3(k1);
    EXPECT_LE((tfDistance<3, double>(prv, k1)), 0.0);
}

TEST(GeneralTf, IdentityAndRandom)
{
    const auto id = rtl::GeneralTf<Vector2f, Translation2f>::identity();   // Vector2f has no identity()
    EXPECT_EQ(id.index(), 1u);
    EXPECT_EQ(id.tf<Translation2f>().trVec(), Vector2f(0, 0));
    EXPECT_EQ(GTf::identity().index(), 0u);

    using All = rtl::GeneralTf<rtl::Translation3d, rtl::Rotation3d, rtl::RigidTf3d, rtl::Translation2d, rtl::Rotation2d,
                               rtl::RigidTf2d, rtl::Translation3f, rtl::Rotation3f, rtl::RigidTf3f, rtl::Translation2f,
                               rtl::Rotation2f, rtl::RigidTf2f>;
    const int dims[] = {3, 3, 3, 2, 2, 2, 3, 3, 3, 2, 2, 2};
    Gen g(1500);
    for (size_t i = 0; i < 12; ++i)
    {
        const All a = All::random(g, [i]() { return i; });
        EXPECT_EQ(a.index(), i);
        EXPECT_EQ(a.visit([](auto &&t) { return t.dimensionality(); }), dims[i]);
    }
    // Elements are static_cast to the drawn alternative's element type: same draws as the plain random().
    Gen g1(77), g2(77);
    const All f = All::random(g1, []() { return 9; });
    const auto plain = Translation2f::random(g2);
    EXPECT_EQ(f.tf<Translation2f>().trVec(), plain.trVec());
    EXPECT_THROW(All::random(g, []() { return 12; }), std::out_of_range);
    EXPECT_THROW(All::random(g, []() { return -1; }), std::out_of_range);
    const GTf first = GTf::random(g);                   // the first alternative with random()
    EXPECT_EQ(first.index(), 0u);
    // An alternative without random() throws when drawn.
    struct NoRandom {};
    using WithBox = rtl::GeneralTf<Translation2f, NoRandom>;
    EXPECT_THROW(WithBox::random(g, []() { return 1; }), std::invalid_argument);
    EXPECT_EQ(WithBox::random(g, []() { return 0; }).index(), 0u);
}

// ====================================================================================================================
// TfChain: application in list order, squash, result types, empty chains.
using tf_test::Gen;
using tf_test::dist;
using tf_test::tfDistance;
using rtl::RigidTf2f;
using rtl::Rotation2f;
using rtl::Translation2f;
using rtl::Vector2f;

namespace
{
    using GTf = rtl::GeneralTf<Translation2f, Rotation2f, RigidTf2f>;
}

TEST(TfChain, AppliesFrontFirstAndSquashes)
{
    Gen g(1600);
    for (int rep = 0; rep < 10; ++rep)
    {
        const auto a = rtl::RigidTf3d::random(g), b = rtl::RigidTf3d::random(g), c = rtl::RigidTf3d::random(g);
        const rtl::TfChain<rtl::RigidTf3d> chain(std::list<rtl::RigidTf3d>{a, b, c});
        const auto v = tf_test::randomVector<3, double>(g);
        static_assert(std::is_same_v<decltype(chain(v)), rtl::Vector3d>);
        EXPECT_LE(dist(chain(v), c(b(a(v)))), 1e-12);
        EXPECT_LE((tfDistance<3, double>(chain.squash(), c(b(a)))), 1e-12);
        // Applying the chain equals applying its squash, and its steps are kept in order.
        EXPECT_LE(dist(chain(v), chain.squash()(v)), 1e-12);
        ASSERT_EQ(chain.list().size(), 3u);
        EXPECT_LE((tfDistance<3, double>(chain.list().front(), a)), 0.0);
        EXPECT_LE((tfDistance<3, double>(chain.list().back(), c)), 0.0);
        // The order matters: the reversed chain is a different transformation.
        const rtl::TfChain<rtl::RigidTf3d> reversed(std::list<rtl::RigidTf3d>{c, b, a});
        EXPECT_GT((tfDistance<3, double>(reversed.squash(), chain.squash())), 1e-3);
    }
}

TEST(TfChain, GeneralTfChainOnVectorsAndTransformations)
{
    const rtl::TfChain<GTf> chain({GTf(Translation2f(1, 2)), GTf(Rotation2f(rtl::C_PIf)), GTf(Translation2f(3, 1))});
    static_assert(std::is_same_v<decltype(chain(Vector2f(1, 1))), Vector2f>);
    EXPECT_LE(dist(chain(Vector2f(1, 1)), Vector2f(1, -2)), 1e-5f);
    // Transformations through the chain: the result type is the closure {Translation, RigidTf}.
    static_assert(std::is_same_v<decltype(chain(Translation2f(1, 1))), rtl::VariantResultType<Translation2f, RigidTf2f>>);
    const auto k = (rtl::RigidTf2f) chain(Translation2f(1, 1));
    EXPECT_LE(dist(k(Vector2f(0, 0)), Vector2f(1, -2)), 1e-5f);
    EXPECT_NEAR(std::abs(k.rotAngle()), rtl::C_PIf, 1e-5f);
    // Only translations: the held result stays a translation.
    const rtl::TfChain<GTf> shifts({GTf(Translation2f(1, 2)), GTf(Translation2f(3, 1))});
    const Translation2f t = shifts(Translation2f(1, 1));
    EXPECT_EQ(t.trVec(), Vector2f(5, 4));
    EXPECT_THROW(static_cast<void>(static_cast<RigidTf2f>(shifts(Translation2f(1, 1)))), std::bad_variant_access);
    // squash keeps the GeneralTf type.
    const GTf s = chain.squash();
    EXPECT_EQ(s.index(), 2u);
    EXPECT_LE(dist(s(Vector2f(1, 1)), Vector2f(1, -2)), 1e-5f);
    // Braced list of a named list.
    std::list<GTf> tfList{GTf(Rotation2f(0.5f))};
    const rtl::TfChain<GTf> one{tfList};
    EXPECT_EQ(one.list().size(), 1u);
}

TEST(TfChain, StepThatCannotTransformThrows)
{
    using Mixed = rtl::GeneralTf<Translation2f, rtl::Translation3f>;
    const rtl::TfChain<Mixed> chain({Mixed(Translation2f(1, 1)), Mixed(rtl::Translation3f(1, 1, 1))});
    EXPECT_THROW(static_cast<void>(chain(Vector2f(0, 0))), std::bad_variant_access);
    const rtl::TfChain<Mixed> ok({Mixed(Translation2f(1, 1)), Mixed(Translation2f(1, 1))});
    EXPECT_EQ(ok(Vector2f(0, 0)), Vector2f(2, 2));
}

TEST(TfChain, EmptyCopyMove)
{
    const rtl::TfChain<rtl::RigidTfND<3, double>> empty;
    EXPECT_TRUE(empty.list().empty());
    EXPECT_LE((tfDistance<3, double>(empty.squash(), rtl::RigidTf3d::identity())), 0.0);
    EXPECT_THROW(static_cast<void>(empty(rtl::Vector3d(1, 2, 3))), std::out_of_range);

    Gen g(1700);
    rtl::TfChain<rtl::RigidTfND<3, double>> a(std::list<rtl::RigidTf3d>{rtl::RigidTf3d::random(g), rtl::RigidTf3d::random(g)});
    const rtl::TfChain<rtl::RigidTfND<3, double>> copy(a);
    const rtl::TfChain<rtl::RigidTfND<3, double>> moved(std::move(a));
    EXPECT_EQ(moved.list().size(), 2u);
    EXPECT_LE((tfDistance<3, double>(copy.squash(), moved.squash())), 0.0);
    rtl::TfChain<rtl::RigidTfND<3, double>> assigned;
    assigned = copy;
    EXPECT_EQ(assigned.list().size(), 2u);
    assigned = rtl::TfChain<rtl::RigidTfND<3, double>>();
    EXPECT_TRUE(assigned.list().empty());
    // Chains built from different random lists squash to different transformations.
    const rtl::TfChain<rtl::RigidTfND<3, double>> other(std::list<rtl::RigidTf3d>{rtl::RigidTf3d::random(g), rtl::RigidTf3d::random(g)});
    EXPECT_GT((tfDistance<3, double>(other.squash(), copy.squash())), 1e-3);
}

// ====================================================================================================================
// TfTreeNode linking and TfTree: insert/erase/queries, tf(from, to) against manual composition, copy and move.
using tf_test::Gen;
using tf_test::dist;
using tf_test::tfDistance;
using rtl::RigidTf3d;
using rtl::Vector3d;

namespace
{
    using Tree = rtl::TfTree<int, RigidTf3d>;

    //! Transformation from the root frame to `key`: the node transformations from the root down, composed manually.
    RigidTf3d fromRoot(const Tree &tree, int key)
    {
        std::vector<const Tree::NodeType *> path;
        for (const Tree::NodeType *n = &tree.at(key); n != &tree.root(); n = n->parent())
            path.push_back(n);
        RigidTf3d r = RigidTf3d::identity();
        for (auto it = path.rbegin(); it != path.rend(); ++it)
            r = (*it)->tf()(r);
        return r;
    }

    //! tf(from, to) must equal fromRoot(to) o fromRoot(from)^-1.
    void expectQueryMatches(const Tree &tree, int from, int to, double tolerance = 1e-9)
    {
        const auto chain = tree.tf(from, to);
        const RigidTf3d expected = fromRoot(tree, to)(fromRoot(tree, from).inverted());
        EXPECT_LE((tfDistance<3, double>(chain.squash(), expected)), tolerance) << from << " -> " << to;
        const Vector3d v(0.3, -0.2, 0.5);
        if (from == to)     // empty chain: squash() is the identity, applying it throws (docs/reference.md)
            EXPECT_THROW(static_cast<void>(chain(v)), std::out_of_range);
        else
            EXPECT_LE(dist(chain(v), expected(v)), tolerance) << from << " -> " << to;
    }

    template<typename K>
    void checkNodeLinking(const K &k0, const K &k1, const K &k2)
    {
        using Node = rtl::TfTreeNode<K, RigidTf3d>;
        const Node def;
        EXPECT_EQ(def.depth(), 0u);
        EXPECT_TRUE(def.children().empty());
        EXPECT_EQ(def.parent(), nullptr);

        Node root{k0};
        EXPECT_EQ(root.parent(), &root);
        EXPECT_EQ(root.parent()->key(), root.key());
        EXPECT_EQ(root.depth(), 0u);

        const RigidTf3d tf(0.5, Vector3d(0, 0, 1), Vector3d(1, 2, 3));
        {
            Node child{k1, tf, root};
            EXPECT_EQ(root.children().size(), 1u);
            EXPECT_EQ(child.depth(), 1u);
            EXPECT_EQ(child.parent(), &root);
            EXPECT_EQ((*root.children().begin())->key(), k1);
            EXPECT_LE((tfDistance<3, double>(child.tf(), tf)), 0.0);
            {
                Node grandchild{k2, RigidTf3d::identity(), child};
                EXPECT_EQ(grandchild.depth(), 2u);
                EXPECT_EQ(child.children().size(), 1u);
                // A copy is a snapshot; destroying it leaves the links alone.
                {
                    const Node snapshot(child);
                    EXPECT_EQ(snapshot.parent(), &root);
                    EXPECT_EQ(snapshot.children().size(), 1u);
                    EXPECT_EQ(snapshot.key(), k1);
                }
                EXPECT_EQ(root.children().size(), 1u);
                EXPECT_EQ(child.children().size(), 1u);
                // Moving relinks the parent's child set and the children's parent pointers.
                Node moved(std::move(child));
                EXPECT_EQ(root.children().count(&moved), 1u);
                EXPECT_EQ(root.children().count(&child), 0u);
                EXPECT_EQ(grandchild.parent(), &moved);
                EXPECT_EQ(moved.depth(), 1u);
                EXPECT_EQ(moved.key(), k1);
            }   // grandchild unregisters from `moved`, then `moved` from root
            EXPECT_EQ(root.children().size(), 0u);
        }
        EXPECT_TRUE(root.children().empty());
        // A moved root becomes its own parent (guaranteed elision for the prvalue, then a real move).
        Node node_mv{Node{k0}};
        EXPECT_EQ(node_mv.parent(), &node_mv);
        Node node_mv2(std::move(node_mv));
        EXPECT_EQ(node_mv2.parent(), &node_mv2);
        EXPECT_EQ(node_mv2.key(), k0);
    }

    //! origin -> 1 -> 3 -> 8 and origin -> 2 -> 5 -> 9 (plus a few extra leaves).
    Tree exampleTree(const Gen &g, std::map<int, RigidTf3d> &tfs)
    {
        Tree tree(0);
        const int parents[][2] = {{1, 0}, {2, 0}, {3, 1}, {4, 1}, {5, 2}, {6, 2}, {7, 3}, {8, 3}, {9, 5}};
        for (const auto &kp : parents)
        {
            tfs[kp[0]] = RigidTf3d::random(g);
            EXPECT_TRUE(tree.insert(kp[0], tfs[kp[0]], kp[1]));
        }
        return tree;
    }
}

TEST(TfTreeNode, LinkingWithDifferentKeyTypes)
{
    checkNodeLinking<uint32_t>(0u, 1u, 2u);
    checkNodeLinking<int32_t>(-1, 5, 7);
    checkNodeLinking<std::string>("origin", "a", "b");
}

TEST(TfTree, BasicQueries)
{
    Gen g(1800);
    std::map<int, RigidTf3d> tfs;
    Tree tree = exampleTree(g, tfs);
    EXPECT_FALSE(tree.empty());
    EXPECT_EQ(tree.size(), 10u);
    EXPECT_TRUE(tree.contains(9));
    EXPECT_FALSE(tree.contains(42));
    EXPECT_FALSE(tree.insert(10, RigidTf3d::identity(), 42));      // missing parent
    EXPECT_FALSE(tree.insert(9, RigidTf3d::identity(), 0));        // existing key
    EXPECT_EQ(tree.size(), 10u);
    EXPECT_EQ(&tree[8], &tree.at(8));
    EXPECT_THROW(tree.at(42), std::out_of_range);
    EXPECT_THROW(tree[42], std::out_of_range);
    EXPECT_THROW(static_cast<void>(tree.tf(0, 42)), std::out_of_range);
    EXPECT_EQ(tree.contains(42), false);                            // operator[] did not insert
    EXPECT_EQ(tree.root().key(), 0);
    EXPECT_EQ(tree.at(8).depth(), 3u);
    EXPECT_EQ(tree.at(8).parent()->key(), 3);
    EXPECT_EQ(tree.root().children().size(), 2u);
    // Nodes hold the inserted transformations, and tree[k].tf() modifies them in place.
    EXPECT_LE((tfDistance<3, double>(tree[5].tf(), tfs[5])), 0.0);
    const RigidTf3d replacement = RigidTf3d::random(g);
    tree[5].tf() = replacement;
    EXPECT_LE((tfDistance<3, double>(tree.at(5).tf(), replacement)), 0.0);
    // A node copy is a snapshot that does not damage the tree when destroyed.
    {
        auto node = tree[3];
        EXPECT_EQ(node.children().size(), 2u);
    }
    EXPECT_EQ(tree.at(3).children().size(), 2u);
    EXPECT_EQ(tree.at(8).parent(), &tree.at(3));
}

TEST(TfTree, QueriesMatchManualComposition)
{
    Gen g(1900);
    std::map<int, RigidTf3d> tfs;
    const Tree tree = exampleTree(g, tfs);
    // Up-then-down through the root: tf(8, 9) == tf9(tf5(tf2(tf1^-1(tf3^-1(tf8^-1))))).
    const auto chain = tree.tf(8, 9);
    ASSERT_EQ(chain.list().size(), 6u);
    const RigidTf3d manual = tfs[9](tfs[5](tfs[2](tfs[1].inverted()(tfs[3].inverted()(tfs[8].inverted())))));
    EXPECT_LE((tfDistance<3, double>(chain.squash(), manual)), 1e-9);
    const Vector3d v(1, 2, 3);
    EXPECT_LE(dist(chain(v), manual(v)), 1e-9);
    // Through a common ancestor below the root: 7 -> 3 -> 8 is {tf7^-1, tf8}.
    const auto sibling = tree.tf(7, 8);
    ASSERT_EQ(sibling.list().size(), 2u);
    EXPECT_LE((tfDistance<3, double>(sibling.squash(), tfs[8](tfs[7].inverted()))), 1e-9);
    // Up only, down only, and the empty path.
    EXPECT_LE((tfDistance<3, double>(tree.tf(8, 1).squash(), tfs[3].inverted()(tfs[8].inverted()))), 1e-9);
    EXPECT_LE((tfDistance<3, double>(tree.tf(0, 9).squash(), tfs[9](tfs[5](tfs[2])))), 1e-9);
    EXPECT_TRUE(tree.tf(5, 5).list().empty());
    EXPECT_LE((tfDistance<3, double>(tree.tf(5, 5).squash(), RigidTf3d::identity())), 0.0);
    // Every pair.
    for (int from = 0; from <= 9; ++from)
        for (int to = 0; to <= 9; ++to)
            expectQueryMatches(tree, from, to);
    // Round trip.
    EXPECT_LE((tfDistance<3, double>(tree.tf(9, 8).squash()(tree.tf(8, 9).squash()), RigidTf3d::identity())), 1e-9);
}

TEST(TfTree, RandomTreeQueries)
{
    Gen g(2000);
    Tree tree(0);
    std::mt19937 pick(5);
    for (int k = 1; k < 200; ++k)
        ASSERT_TRUE(tree.insert(k, RigidTf3d::random(g), std::uniform_int_distribution<int>(0, k - 1)(pick)));
    for (int rep = 0; rep < 100; ++rep)
    {
        const int a = std::uniform_int_distribution<int>(0, 199)(pick), b = std::uniform_int_distribution<int>(0, 199)(pick);
        const auto chain = tree.tf(a, b);
        // Path length = depth(a) + depth(b) - 2 depth(lowest common ancestor) <= depth(a) + depth(b).
        EXPECT_LE(chain.list().size(), tree.at(a).depth() + tree.at(b).depth());
        expectQueryMatches(tree, a, b, 1e-8);
    }
}

TEST(TfTree, GeneralTfTree)
{
    using G3 = rtl::GeneralTf<rtl::Translation3d, rtl::Rotation3d, RigidTf3d>;
    Gen g(2100);
    const auto rigid = RigidTf3d::random(g);
    const auto trans = rtl::Translation3d::random(g);
    const auto rot = rtl::Rotation3d::random(g);
    rtl::TfTree<std::string, G3> tree("origin");
    ASSERT_TRUE(tree.insert("k1", trans, "origin"));
    ASSERT_TRUE(tree.insert("k3", rigid, "k1"));
    ASSERT_TRUE(tree.insert("k2", rot, "origin"));
    const auto squashed = (RigidTf3d) tree.tf("k3", "k2").squash();
    EXPECT_LE((tfDistance<3, double>(squashed, rot(trans.inverted()(rigid.inverted())))), 1e-12);
    // Applying the chain directly to a vector.
    const Vector3d v(1, 0, 0);
    EXPECT_LE(dist(tree.tf("k3", "k2")(v), rot(trans.inverted()(rigid.inverted()(v)))), 1e-12);
    // Only translations on the path: the squash stays a translation.
    EXPECT_EQ(tree.tf("k1", "origin").squash().index(), 0u);
}

TEST(TfTree, EraseAndReinsert)
{
    Tree tree(0);
    for (int k = 1; k <= 5; ++k)
        ASSERT_TRUE(tree.insert(k, RigidTf3d(0.1 * k, Vector3d(0, 0, 1), Vector3d(k, 0, 0)), k - 1));   // a chain 0-1-2-3-4-5
    EXPECT_FALSE(tree.erase(0));                                    // never the root
    EXPECT_FALSE(tree.erase(42));
    for (int k = 5; k >= 3; --k)                                    // deepest first, one at a time
    {
        EXPECT_TRUE(tree.erase(k));
        EXPECT_EQ(tree.size(), static_cast<size_t>(k));
        EXPECT_FALSE(tree.contains(k));
        EXPECT_TRUE(tree.contains(k - 1));
        EXPECT_TRUE(tree.at(k - 1).children().empty());
    }
    ASSERT_TRUE(tree.insert(3, RigidTf3d::identity(), 2));
    ASSERT_TRUE(tree.insert(4, RigidTf3d::identity(), 3));
    ASSERT_TRUE(tree.insert(10, RigidTf3d::identity(), 1));
    EXPECT_EQ(tree.size(), 6u);
    EXPECT_TRUE(tree.erase(1));                                     // removes 1 and every descendant
    EXPECT_EQ(tree.size(), 1u);
    for (int k : {1, 2, 3, 4, 10})
        EXPECT_FALSE(tree.contains(k));
    EXPECT_TRUE(tree.root().children().empty());
    // Re-insert under the same keys and query again.
    const RigidTf3d a(0.3, Vector3d(1, 0, 0), Vector3d(1, 2, 3)), b(-0.4, Vector3d(0, 1, 0), Vector3d(0, 0, 1));
    ASSERT_TRUE(tree.insert(1, a, 0));
    ASSERT_TRUE(tree.insert(2, b, 1));
    EXPECT_LE((tfDistance<3, double>(tree.tf(0, 2).squash(), b(a))), 1e-12);
    EXPECT_LE((tfDistance<3, double>(tree.tf(2, 0).squash(), b(a).inverted())), 1e-12);
    tree.clear();
    EXPECT_EQ(tree.size(), 1u);
    EXPECT_TRUE(tree.contains(0));
    EXPECT_TRUE(tree.root().children().empty());
    EXPECT_TRUE(tree.insert(1, a, 0));
}

TEST(TfTree, DeepCopyIsIndependent)
{
    Gen g(2200);
    std::map<int, RigidTf3d> tfs;
    Tree original = exampleTree(g, tfs);
    const Tree copy(original);
    Tree assigned(100);
    assigned = original;
    for (const Tree *t : std::initializer_list<const Tree *>{&copy, &assigned})
    {
        EXPECT_EQ(t->size(), 10u);
        // Parent pointers point into the copy, not into the original.
        for (int k = 1; k <= 9; ++k)
        {
            EXPECT_NE(&t->at(k), &original.at(k));
            EXPECT_EQ(t->at(k).parent(), &t->at(original.at(k).parent()->key()));
            EXPECT_EQ(t->at(k).depth(), original.at(k).depth());
            EXPECT_EQ(t->at(k).children().size(), original.at(k).children().size());
        }
        EXPECT_EQ(t->root().key(), 0);
    }
    const auto before = copy.tf(8, 9).squash();
    // Changing the original leaves the copies alone.
    original[5].tf() = RigidTf3d::random(g);
    EXPECT_TRUE(original.erase(3));
    EXPECT_TRUE(original.insert(11, RigidTf3d::identity(), 9));
    EXPECT_EQ(original.size(), 8u);
    EXPECT_EQ(copy.size(), 10u);
    EXPECT_TRUE(copy.contains(8));
    EXPECT_FALSE(copy.contains(11));
    EXPECT_LE((tfDistance<3, double>(copy.tf(8, 9).squash(), before)), 0.0);
    EXPECT_LE((tfDistance<3, double>(assigned.tf(8, 9).squash(), before)), 0.0);
    expectQueryMatches(copy, 7, 9);
    expectQueryMatches(original, 11, 4);
    // Clearing a copy leaves the original alone.
    Tree copy2(original);
    copy2.clear();
    EXPECT_EQ(copy2.size(), 1u);
    EXPECT_EQ(original.size(), 8u);
    expectQueryMatches(original, 11, 6);
}

TEST(TfTree, MoveLeavesAValidRoot)
{
    Gen g(2300);
    std::map<int, RigidTf3d> tfs;
    Tree source = exampleTree(g, tfs);
    const auto before = source.tf(8, 9).squash();
    Tree moved(std::move(source));
    EXPECT_EQ(moved.size(), 10u);
    EXPECT_LE((tfDistance<3, double>(moved.tf(8, 9).squash(), before)), 0.0);
    EXPECT_EQ(moved.at(8).parent(), &moved.at(3));
    // The moved-from tree still has its root and stays usable.
    EXPECT_EQ(source.size(), 1u);
    EXPECT_TRUE(source.contains(0));
    EXPECT_TRUE(source.insert(1, RigidTf3d::identity(), 0));
    EXPECT_TRUE(source.erase(1));
    // Move assignment from a temporary, and from a named tree.
    Tree target(0);
    target = Tree(exampleTree(g, tfs));
    EXPECT_EQ(target.size(), 10u);
    expectQueryMatches(target, 4, 6);
    target = std::move(moved);
    EXPECT_EQ(target.size(), 10u);
    EXPECT_LE((tfDistance<3, double>(target.tf(8, 9).squash(), before)), 0.0);
    EXPECT_FALSE(moved.empty());
    moved.clear();
    EXPECT_EQ(moved.size(), 1u);
}
