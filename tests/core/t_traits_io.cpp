// The type-trait table, stream output formats (io/StdLib.h) and the Test module (Random, TypeDetails, TemplateTester).
#include <complex>
#include <cstdint>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "rtl/io/StdLib.h"          // deliberately before Core.h: StdLib.h must be self-sufficient
#include "rtl/Core.h"
#include "rtl/Transformation.h"
#include "rtl/Test.h"

namespace
{
    //! One row of the trait table: dimensional, element type, metric, invertible, identity, nan, random,
    //! transformable by translation / rotation / rigid transformation.
    using Row = std::vector<bool>;

    //! The trait row of an N-D template in dimension d (transformations of the same dimension and element type).
    template<template<int, typename> class Tmpl, int d, typename E>
    Row ndRow()
    {
        using T = Tmpl<d, E>;
        return {rtl::is_dimensional_v<T>, rtl::has_element_type_v<T>, rtl::has_metric_v<T>, rtl::is_invertible_v<T>,
                rtl::has_identity_v<T>, rtl::has_nan_v<T>, rtl::has_random_v<T>,
                rtl::is_transformable_v<T, rtl::TranslationND<d, E>>, rtl::is_transformable_v<T, rtl::RotationND<d, E>>,
                rtl::is_transformable_v<T, rtl::RigidTfND<d, E>>};
    }
    template<template<typename> class Tmpl, int d, typename E>
    Row fixedRow()
    {
        using T = Tmpl<E>;
        return {rtl::is_dimensional_v<T>, rtl::has_element_type_v<T>, rtl::has_metric_v<T>, rtl::is_invertible_v<T>,
                rtl::has_identity_v<T>, rtl::has_nan_v<T>, rtl::has_random_v<T>,
                rtl::is_transformable_v<T, rtl::TranslationND<d, E>>, rtl::is_transformable_v<T, rtl::RotationND<d, E>>,
                rtl::is_transformable_v<T, rtl::RigidTfND<d, E>>};
    }
    template<int, typename E> using Square3 = rtl::Matrix<3, 3, E>;

    template<typename E>
    class TraitTable : public ::testing::Test {};
    using Elements = ::testing::Types<float, double>;
    TYPED_TEST_SUITE(TraitTable, Elements);

    template<typename T>
    std::string str(const T &t)
    {
        std::ostringstream os;
        os << t;
        return os.str();
    }
}

TYPED_TEST(TraitTable, MatchesTheReferenceTable)
{
    using E = TypeParam;
    //                        dim elem metric inv  id   nan  rnd  Tr   Rot  Rig
    const Row vector       = {1,  1,   1,     0,   0,   1,   1,   1,   1,   1};
    const Row segment      = {1,  1,   1,     0,   0,   0,   1,   1,   1,   1};
    const Row box          = {1,  1,   0,     0,   0,   0,   0,   1,   1,   1};
    const Row polygon      = box, frustum = box;
    const Row translation  = {1,  1,   1,     1,   1,   0,   1,   1,   1,   1};
    const Row rotation     = {1,  1,   0,     1,   1,   0,   1,   1,   1,   1};
    const Row rigid        = rotation;
    const Row matrix       = {0,  1,   1,     1,   1,   1,   1,   0,   0,   0};
    const Row quaternion   = {0,  1,   1,     1,   1,   0,   1,   0,   0,   0};

    EXPECT_EQ((ndRow<rtl::VectorND, 2, E>()), vector);
    EXPECT_EQ((ndRow<rtl::VectorND, 3, E>()), vector);
    EXPECT_EQ((ndRow<rtl::VectorND, 4, E>()), vector);
    EXPECT_EQ((ndRow<rtl::VectorND, 5, E>()), vector);
    EXPECT_EQ((ndRow<rtl::LineSegmentND, 2, E>()), segment);
    EXPECT_EQ((ndRow<rtl::LineSegmentND, 3, E>()), segment);
    EXPECT_EQ((ndRow<rtl::LineSegmentND, 4, E>()), segment);
    EXPECT_EQ((ndRow<rtl::BoundingBoxND, 2, E>()), box);
    EXPECT_EQ((ndRow<rtl::BoundingBoxND, 3, E>()), box);
    EXPECT_EQ((ndRow<rtl::BoundingBoxND, 4, E>()), box);
    EXPECT_EQ((fixedRow<rtl::Polygon2D, 2, E>()), polygon);
    EXPECT_EQ((fixedRow<rtl::Polygon3D, 3, E>()), polygon);
    EXPECT_EQ((fixedRow<rtl::Frustum3D, 3, E>()), frustum);
    EXPECT_EQ((ndRow<rtl::TranslationND, 2, E>()), translation);
    EXPECT_EQ((ndRow<rtl::TranslationND, 4, E>()), translation);
    EXPECT_EQ((ndRow<rtl::RotationND, 2, E>()), rotation);
    EXPECT_EQ((ndRow<rtl::RotationND, 3, E>()), rotation);
    EXPECT_EQ((ndRow<rtl::RotationND, 4, E>()), rotation);
    EXPECT_EQ((ndRow<rtl::RigidTfND, 2, E>()), rigid);
    EXPECT_EQ((ndRow<rtl::RigidTfND, 3, E>()), rigid);
    EXPECT_EQ((ndRow<rtl::RigidTfND, 4, E>()), rigid);
    EXPECT_EQ((ndRow<Square3, 3, E>()), matrix);
    EXPECT_EQ((fixedRow<rtl::Quaternion, 3, E>()), quaternion);

    // Mismatched dimension or element type is not transformable; 1-D objects take translations only.
    EXPECT_FALSE((rtl::is_transformable_v<rtl::VectorND<3, E>, rtl::TranslationND<2, E>>));
    EXPECT_TRUE((rtl::is_transformable_v<rtl::VectorND<1, E>, rtl::TranslationND<1, E>>));
    EXPECT_TRUE((rtl::is_transformable_v<rtl::BoundingBoxND<1, E>, rtl::TranslationND<1, E>>));
    EXPECT_TRUE((rtl::has_random_v<rtl::LineSegmentND<1, E>>));
}

TEST(TypeTraits, RandomGeneratorsTypesAndVariants)
{
    using Q = rtl::Quaternionf;
    auto gen = []() { return 1.0; };
    using G = decltype(gen);
    EXPECT_TRUE(rtl::has_random_v<Q>);
    EXPECT_TRUE((rtl::has_random_v<Q, G>));
    EXPECT_TRUE((rtl::has_random_v<Q, G, G>));
    EXPECT_FALSE((rtl::has_random_v<Q, void>));
    EXPECT_FALSE((rtl::has_random_v<Q, G, G, G>));
    EXPECT_FALSE((rtl::has_random_v<rtl::Vector3f, int>));               // an int is not callable

    // ::type agrees with ::value.
    static_assert(std::is_same_v<rtl::has_nan_t<rtl::Vector2f>, std::true_type>);
    static_assert(std::is_same_v<rtl::has_nan_t<Q>, std::false_type>);
    static_assert(std::is_same_v<rtl::has_random_t<Q, void>, std::false_type>);
    static_assert(std::is_same_v<rtl::is_dimensional_t<rtl::Matrix33f>, std::false_type>);
    static_assert(std::is_same_v<rtl::is_transformable_t<rtl::Vector2f, rtl::Rotation2f>, std::true_type>);
    static_assert(rtl::has_element_type_v<rtl::Polygon2Df> && !rtl::has_element_type_v<int>);
    static_assert(rtl::is_variant_result_v<rtl::VariantResultType<rtl::Vector2f, rtl::Vector3f>>);
    static_assert(!rtl::is_variant_result_v<rtl::Vector2f>);
    SUCCEED();
}

TEST(StdLib, CoreFormats)
{
    EXPECT_EQ(str(rtl::Vector3d(1, 2.5, -3)), "[1, 2.5, -3]");
    EXPECT_EQ(str(rtl::VectorND<1, int>(7)), "[7]");
    EXPECT_EQ(str(rtl::VectorND<2, std::complex<double>>(std::complex<double>(1, 2), std::complex<double>(0, -1))), "[(1,2), (0,-1)]");
    rtl::Matrix22d m;
    m.setRow(0, {1, 2});
    m.setRow(1, {3, 4});
    EXPECT_EQ(str(m), "[1, 2; 3, 4]");
    EXPECT_EQ(str(rtl::Matrix<4, 1, int>(Eigen::Matrix<int, 4, 1>(1, 2, 3, 4))), "[1; 2; 3; 4]");
    EXPECT_EQ(str(rtl::Matrix<1, 3, int>::ones()), "[1, 1, 1]");
    EXPECT_EQ(str(rtl::Quaterniond(0.1, 0.35, -1.2, 0.35)), "0.1 + 0.35i - 1.2j + 0.35k");
    EXPECT_EQ(str(rtl::Quaterniond::identity()), "1 + 0i + 0j + 0k");
    EXPECT_EQ(str(rtl::LineSegment2d(0, 0, 1, 1)), "[0, 0]-->[1, 1]");
    EXPECT_EQ(str(rtl::BoundingBox2d({0, 1}, {2, -1})), "min: [0, -1]   max: [2, 1]");
    rtl::Polygon2Df poly;
    poly.addPoint({0, 0});
    poly.addPoint({1, 0.5});
    EXPECT_EQ(str(poly), "{[0, 0], [1, 0.5]}");
    rtl::Polygon3Df p3(rtl::Vector3f::baseZ(), 2);
    p3.addPoint({1, 1, 0});
    EXPECT_EQ(str(p3), "n: [0, 0, 1]   d: 2   {[1, 1, 2]}");
    const rtl::Frustum3d f{{0, 0, 0}, {1, 1, 1}, {1, -1, 1}, {1, 1, -1}, {1, -1, -1}, 3};
    EXPECT_EQ(str(f), "origin: [0, 0, 0]   near: [1, 1, 1], [1, -1, 1], [1, 1, -1], [1, -1, -1]   depth: 3");

    // The stream's own formatting applies to the elements.
    std::ostringstream os;
    os.precision(3);
    os << rtl::Vector2d(rtl::C_PId, 1.0 / 3.0);
    EXPECT_EQ(os.str(), "[3.14, 0.333]");
}

TEST(StdLib, RvalueStreamIdiomFindsOperatorsByAdl)
{
    // Regression (published defect; docs/reference.md, "Stream operators and argument-dependent lookup"): with the
    // operators at global scope this did not compile.
    const rtl::Vector2f v1(1, 2);
    const rtl::Matrix22f m = rtl::Matrix22f::identity();
    const std::string s = static_cast<std::ostringstream &&>((std::ostringstream() << "v = " << v1 << ", m = " << m)).str();
    EXPECT_EQ(s, "v = [1, 2], m = [1, 0; 0, 1]");
}

TEST(StdLib, TransformationFormats)
{
    EXPECT_EQ(str(rtl::Translation2d(1, 1)), "t: [1, 1]");
    EXPECT_EQ(str(rtl::RotationND<4, double>()), "R: [1, 0, 0, 0; 0, 1, 0, 0; 0, 0, 1, 0; 0, 0, 0, 1]");
    const rtl::Rotation3d r3;
    EXPECT_EQ(str(r3), "R: " + str(r3.rotMat()) + "   axix: " + str(r3.rotAxis()) + "   angle: " + str(r3.rotAngle()));
    EXPECT_EQ(str(r3).substr(0, 34), "R: [1, 0, 0; 0, 1, 0; 0, 0, 1]   a");
    const rtl::Rotation2d r2(0.5);
    const rtl::RigidTf2d tf(r2, rtl::Translation2d(3, -4));
    EXPECT_EQ(str(tf), str(r2) + "   t: [3, -4]");
    EXPECT_EQ(str(r2), "R: [" + str(std::cos(0.5)) + ", " + str(-std::sin(0.5)) + "; " + str(std::sin(0.5)) + ", " + str(std::cos(0.5)) + "]");

    rtl::GeneralTf<rtl::Translation2d, rtl::Rotation2d> g(rtl::Translation2d(5, 6));
    EXPECT_EQ(str(g), "t: [5, 6]");
    g = rtl::GeneralTf<rtl::Translation2d, rtl::Rotation2d>(r2);
    EXPECT_EQ(str(g), str(r2));

    rtl::TfTree<std::string, rtl::Translation2d> tree("root");
    tree.insert("pos1", rtl::Translation2d(1, 1), "root");
    tree.insert("pos11", rtl::Translation2d(1, 2), "pos1");
    EXPECT_EQ(str(tree), "root\n\tpos1   t: [1, 1]\n\t\tpos11   t: [1, 2]\n");
    EXPECT_EQ(str(tree["pos11"]), "pos11   t: [1, 2]");
    tree.insert("pos2", rtl::Translation2d(2, 1), "root");
    const std::string both = str(tree);
    // Siblings come in pointer order: either way round, with pos11 right below pos1.
    EXPECT_TRUE(both == "root\n\tpos1   t: [1, 1]\n\t\tpos11   t: [1, 2]\n\tpos2   t: [2, 1]\n" ||
                both == "root\n\tpos2   t: [2, 1]\n\tpos1   t: [1, 1]\n\t\tpos11   t: [1, 2]\n") << both;
}

namespace
{
    std::vector<std::string> calls;

    template<typename T> struct RecordType
    {
        static void testFunction(int tag) { calls.push_back(rtl::test::type<T>::description() + "/" + std::to_string(tag)); }
    };
    template<int r, typename T> struct RecordRange
    {
        static void testFunction() { calls.push_back(std::to_string(r) + rtl::test::type<T>::description()); }
    };
    template<int r, typename E, typename T2> struct RecordRangeTypes
    {
        static void testFunction() { calls.push_back(std::to_string(r) + rtl::test::type<E>::description() + rtl::test::type<T2>::description()); }
    };
    template<int r1, int r2, typename T> struct RecordRangeRange
    {
        static void testFunction(double x) { calls.push_back(std::to_string(r1) + std::to_string(r2) + rtl::test::type<T>::description() + std::to_string(int(x))); }
    };
}

TEST(TestModule, TemplateTesterOrder)
{
    calls.clear();
    rtl::test::Types<RecordType, float, double, int> t(7);
    EXPECT_EQ(calls, (std::vector<std::string>{"int/7", "double/7", "float/7"}));

    calls.clear();
    rtl::test::RangeTypes<RecordRange, 1, 3, float, double> rt;
    EXPECT_EQ(calls, (std::vector<std::string>{"1double", "2double", "3double", "1float", "2float", "3float"}));
    calls.clear();
    rtl::test::RangeTypes<RecordRange, 2, 2, float>{};
    EXPECT_EQ(calls, (std::vector<std::string>{"2float"}));

    calls.clear();
    [[maybe_unused]] auto x = rtl::test::RangeTypesTypes<RecordRangeTypes, 2, 3, float, double>::with<uint32_t, std::string>{};
    EXPECT_EQ(calls, (std::vector<std::string>{"2doublestd::string", "3doublestd::string", "2floatstd::string", "3floatstd::string",
                                               "2doubleunsigned int", "3doubleunsigned int", "2floatunsigned int", "3floatunsigned int"}));

    calls.clear();
    rtl::test::RangeRangeTypes<RecordRangeRange, 1, 2, 3, 4, int32_t> rr(5.0);
    EXPECT_EQ(calls, (std::vector<std::string>{"13int5", "14int5", "23int5", "24int5"}));
}

TEST(TestModule, TypeDetails)
{
    using rtl::test::type;
    EXPECT_EQ(type<float>::allowedError(), 0.001f);
    EXPECT_EQ(type<double>::allowedError(), 1e-6);
    EXPECT_EQ(type<int>::allowedError(), 0.0);
    EXPECT_EQ(type<unsigned int>::allowedError(), 0.0);
    EXPECT_EQ((type<rtl::VectorND<3, float>>::allowedError()), 0.003f);
    EXPECT_EQ((type<rtl::Matrix<2, 3, double>>::allowedError()), 6e-6);
    EXPECT_EQ(type<std::string>::description(), "std::string");
    EXPECT_EQ(type<int32_t>::description(), "int");
    EXPECT_EQ(type<uint32_t>::description(), "unsigned int");
    EXPECT_EQ((type<rtl::VectorND<2, float>>::description()), "rtl::VectorND<2, float>");
    EXPECT_EQ((type<rtl::Matrix<2, 3, double>>::description()), "rtl::MatrixND<2, 3, double>");
    EXPECT_EQ(type<rtl::Quaternionf>::description(), "rtl::Quaternion<float>");
    EXPECT_EQ(type<rtl::LineSegment3d>::description(), "rtl::LineSegmentND<3, double>");
    EXPECT_EQ(type<rtl::BoundingBox2f>::description(), "rtl::BoundingBoxND<2, float>");
    EXPECT_EQ(type<rtl::Translation3f>::description(), "rtl::TranslationND<3, float>");
    EXPECT_EQ(type<rtl::Rotation2d>::description(), "rtl::RotationND<2, double>");
    EXPECT_EQ(type<rtl::RigidTf3f>::description(), "rtl::RigidTfND<3, float>");
    EXPECT_EQ((type<rtl::GeneralTf<rtl::Translation2f, rtl::Rotation2f, rtl::RigidTf2f>>::description()),
              "rtl::GeneralTf<rtl::TranslationND<2, float>, rtl::RotationND<2, float>, rtl::RigidTfND<2, float>>");
    EXPECT_EQ((type<rtl::VariantResultType<rtl::Vector2f, rtl::Vector3d>>::description()),
              "rtl::VariantResultType<rtl::VectorND<2, float>, rtl::VectorND<3, double>>");
    EXPECT_EQ(type<rtl::Polygon2Df>::description(), "rtl::Polygon2D<float>");
    EXPECT_EQ(type<rtl::Polygon3Dd>::description(), "rtl::Polygon3D<double>");
    EXPECT_EQ(type<rtl::Frustum3f>::description(), "rtl::Frustum3D<float>");

    // The post-processing t_type_traits applies: the name between "rtl::" and "ND<".
    const std::string d = type<rtl::Translation3f>::description();
    const auto colon = d.rfind(':');
    EXPECT_EQ(d.substr(colon + 1, d.find("ND<") - colon - 1), "Translation");
}

TEST(TestModule, Random)
{
    rtl::test::Random::seed(42);
    for (int i = 0; i < 200; ++i)
    {
        const int v = rtl::test::Random::uniformValue<int>(3, 5);
        EXPECT_GE(v, 3);
        EXPECT_LE(v, 5);
        const double d = rtl::test::Random::uniformValue(-1.0, 1.0);
        EXPECT_GE(d, -1.0);
        EXPECT_LT(d, 1.0);
        EXPECT_LE(rtl::test::Random::uniformValue<unsigned char>(0, 9), 9);
    }
    // Callables work through const references, as random() functions take them.
    const auto el = rtl::test::Random::uniformCallable<double>(-1.0, 1.0);
    const auto idx = rtl::test::Random::uniformCallable(0ul, 3ul);
    const auto ang = rtl::test::Random::uniformCallable(-rtl::C_PI<float>, rtl::C_PI<float>);
    const auto v = rtl::Vector3f::random(el);
    EXPECT_LE(v.data().cwiseAbs().maxCoeff(), 1.0f);
    EXPECT_LE(idx(), 3ul);
    const auto q = rtl::Quaternionf::random(ang, el);
    EXPECT_NEAR(q.norm(), 1.f, 1e-5f);
    // Every value of a small integral range shows up.
    std::vector<int> seen(3, 0);
    const auto small = rtl::test::Random::uniformCallable(0, 2);
    for (int i = 0; i < 300; ++i)
        ++seen[size_t(small())];
    for (int s : seen)
        EXPECT_GT(s, 0);
    // Reseeding replays the sequence.
    rtl::test::Random::seed(7);
    const double a = el();
    rtl::test::Random::seed(7);
    EXPECT_EQ(el(), a);
}
