// rtl::test::type<T>: per-type test details, the tolerance allowedError() and a readable description().
// Tolerances: float 1e-3, double 1e-6, integers 0; a d-vector allows d times its element's error, an r x c matrix
// r*c times (errors are measured with VectorND::distance / Matrix::distance).
#pragma once

#include <chrono>
#include <random>
#include <string>
#include <type_traits>

#include "rtl/Core.h"
#include "rtl/Transformation.h"

namespace rtl::test
{
    template<typename T> struct type_no_details : std::false_type {};

    template<typename T>
    struct type
    {
        static_assert(type_no_details<T>::value, "rtl::test::type: no details specified for this type.");
    };

    template<> struct type<float>
    {
        static constexpr float allowedError() { return 0.001f; }
        static std::string description() { return "float"; }
    };
    template<> struct type<double>
    {
        static constexpr double allowedError() { return 0.000001; }
        static std::string description() { return "double"; }
    };
    template<> struct type<int>
    {
        static constexpr double allowedError() { return 0; }
        static std::string description() { return "int"; }
    };
    template<> struct type<unsigned int>
    {
        static constexpr double allowedError() { return 0; }
        static std::string description() { return "unsigned int"; }
    };
    template<> struct type<std::string>
    {
        static std::string description() { return "std::string"; }
    };

}  // namespace rtl::test

namespace rtl::detail
{
    inline std::string nd(const char *name, int d, const std::string &element)
    {
        return std::string("rtl::") + name + "<" + std::to_string(d) + ", " + element + ">";
    }
    template<typename T, typename... Ts>
    std::string joined()
    {
        return (test::type<T>::description() + ... + (", " + test::type<Ts>::description()));
    }
}  // namespace rtl::detail

namespace rtl::test
{
    template<int r, int c, typename E> struct type<rtl::Matrix<r, c, E>>
    {
        static constexpr E allowedError() { return static_cast<E>(r * c * type<E>::allowedError()); }
        static std::string description()
        {
            return "rtl::MatrixND<" + std::to_string(r) + ", " + std::to_string(c) + ", " + type<E>::description() + ">";
        }
    };
    template<int d, typename E> struct type<rtl::VectorND<d, E>>
    {
        static constexpr E allowedError() { return static_cast<E>(d * type<E>::allowedError()); }
        static std::string description() { return detail::nd("VectorND", d, type<E>::description()); }
    };
    template<typename T> struct type<rtl::Quaternion<T>>
    {
        static std::string description() { return "rtl::Quaternion<" + type<T>::description() + ">"; }
    };
    template<int d, typename E> struct type<rtl::LineSegmentND<d, E>>
    {
        static std::string description() { return detail::nd("LineSegmentND", d, type<E>::description()); }
    };
    template<int d, typename E> struct type<rtl::BoundingBoxND<d, E>>
    {
        static std::string description() { return detail::nd("BoundingBoxND", d, type<E>::description()); }
    };
    template<int d, typename E> struct type<rtl::RotationND<d, E>>
    {
        static std::string description() { return detail::nd("RotationND", d, type<E>::description()); }
    };
    template<int d, typename E> struct type<rtl::TranslationND<d, E>>
    {
        static std::string description() { return detail::nd("TranslationND", d, type<E>::description()); }
    };
    template<int d, typename E> struct type<rtl::RigidTfND<d, E>>
    {
        static std::string description() { return detail::nd("RigidTfND", d, type<E>::description()); }
    };
    template<typename T, typename... Tfs> struct type<rtl::GeneralTf<T, Tfs...>>
    {
        static std::string description() { return "rtl::GeneralTf<" + detail::joined<T, Tfs...>() + ">"; }
    };
    template<typename T, typename... Ts> struct type<rtl::VariantResultType<T, Ts...>>
    {
        static std::string description() { return "rtl::VariantResultType<" + detail::joined<T, Ts...>() + ">"; }
    };
    template<typename T> struct type<rtl::Polygon2D<T>>
    {
        static std::string description() { return "rtl::Polygon2D<" + type<T>::description() + ">"; }
    };
    template<typename T> struct type<rtl::Polygon3D<T>>
    {
        static std::string description() { return "rtl::Polygon3D<" + type<T>::description() + ">"; }
    };
    template<typename T> struct type<rtl::Frustum3D<T>>
    {
        static std::string description() { return "rtl::Frustum3D<" + type<T>::description() + ">"; }
    };
}
