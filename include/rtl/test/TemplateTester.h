// Call a tester template's static testFunction(args...) for every combination of template arguments.
// Type packs are walked in reverse order, integer ranges in ascending order (as the published helpers do).
// Constructor arguments are passed on, as lvalues, to every call.
#pragma once

#include <chrono>
#include <random>
#include <type_traits>

#include "rtl/Core.h"
#include "rtl/Transformation.h"

namespace rtl::detail
{
    //! Calls f(std::integral_constant<int, i>) for i = from..to.
    template<int from, int to, typename F>
    void forRange(F &&f)
    {
        if constexpr (from <= to)
        {
            f(std::integral_constant<int, from>{});
            forRange<from + 1, to>(f);
        }
    }
    //! Calls f(type_identity<T>) for each T in reverse order.
    template<typename T> struct TypeTag { using type = T; };
    template<typename F>
    void forTypesReversed(F &&) {}
    template<typename T, typename... Ts, typename F>
    void forTypesReversed(F &&f)
    {
        forTypesReversed<Ts...>(f);
        f(TypeTag<T>{});
    }
}  // namespace rtl::detail

namespace rtl::test
{
    //! Tester<T>::testFunction(args...) for T in reverse(TestedTypes).
    template<template<typename> class Tester, typename... TestedTypes>
    class Types
    {
    public:
        template<typename... A>
        explicit Types(A... args)
        {
            detail::forTypesReversed<TestedTypes...>([&](auto t) { Tester<typename decltype(t)::type>::testFunction(args...); });
        }
    };

    //! For T in reverse(Types), r = r_min..r_max: Tester<r, T>::testFunction(args...).
    template<template<int, typename> class Tester, int r_min, int r_max, typename... Types>
    class RangeTypes
    {
    public:
        template<typename... A>
        explicit RangeTypes(A... args)
        {
            detail::forTypesReversed<Types...>([&](auto t) {
                detail::forRange<r_min, r_max>([&](auto r) { Tester<decltype(r)::value, typename decltype(t)::type>::testFunction(args...); });
            });
        }
    };

    //! For T2 in reverse(Types2), E in reverse(Types), r = r_min..r_max: Tester<r, E, T2>::testFunction(args...).
    template<template<int, typename, typename> class Tester, int r_min, int r_max, typename... Types>
    class RangeTypesTypes
    {
    public:
        template<typename... Types2>
        class with
        {
        public:
            template<typename... A>
            explicit with(A... args)
            {
                detail::forTypesReversed<Types2...>([&](auto t2) {
                    detail::forTypesReversed<Types...>([&](auto t) {
                        detail::forRange<r_min, r_max>([&](auto r) {
                            Tester<decltype(r)::value, typename decltype(t)::type, typename decltype(t2)::type>::testFunction(args...);
                        });
                    });
                });
            }
        };
    };

    //! For T in reverse(Types), r1 = r1_min..r1_max, r2 = r2_min..r2_max: Tester<r1, r2, T>::testFunction(args...).
    template<template<int, int, typename> class Tester, int r1_min, int r1_max, int r2_min, int r2_max, typename... Types>
    class RangeRangeTypes
    {
    public:
        template<typename... A>
        explicit RangeRangeTypes(A... args)
        {
            detail::forTypesReversed<Types...>([&](auto t) {
                detail::forRange<r1_min, r1_max>([&](auto r1) {
                    detail::forRange<r2_min, r2_max>([&](auto r2) {
                        Tester<decltype(r1)::value, decltype(r2)::value, typename decltype(t)::type>::testFunction(args...);
                    });
                });
            });
        }
    };
}
