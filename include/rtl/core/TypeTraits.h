// STL-style detection traits over the RTL object vocabulary (ElementType, dimensionality(), distance(), inverted(),
// identity(), nan(), random(), transformed()). Each trait has a member `type` (std::true_type / std::false_type,
// consistent with its member `value`), a _t alias and a _v constant. Self-contained: the detection idiom is implemented here.
#pragma once

#include <type_traits>
#include <utility>

namespace rtl
{
    namespace detail
    {
        struct nonesuch
        {
            nonesuch() = delete;
            ~nonesuch() = delete;
            nonesuch(const nonesuch &) = delete;
            void operator=(const nonesuch &) = delete;
        };

        template<typename Default, typename AlwaysVoid, template<typename...> class Op, typename... Args>
        struct detector
        {
            using value_t = std::false_type;
            using type = Default;
        };
        template<typename Default, template<typename...> class Op, typename... Args>
        struct detector<Default, std::void_t<Op<Args...>>, Op, Args...>
        {
            using value_t = std::true_type;
            using type = Op<Args...>;
        };

        //! std::true_type if Op<Args...> is well formed, std::false_type otherwise.
        template<template<typename...> class Op, typename... Args>
        using is_detected = typename detector<nonesuch, void, Op, Args...>::value_t;

        //! A nullary callable returning R, standing in for an element generator.
        template<typename R>
        struct GeneratorOf
        {
            R operator()() const;
        };
    }

    // ---- ElementType ------------------------------------------------------------------------------------------
    template<typename T> using ElementTypeType = typename T::ElementType;
    template<typename T> struct has_element_type
    {
        using type = detail::is_detected<ElementTypeType, T>;
        static constexpr bool value = type::value;
    };
    template<typename T> using has_element_type_t = typename has_element_type<T>::type;
    template<typename T> constexpr bool has_element_type_v = has_element_type<T>::value;

    // ---- VariantResultType (defined in tf/VariantResult.h) ------------------------------------------------------
    template<typename... Res> class VariantResultType;
    template<typename T> struct is_variant_result : std::false_type {};
    template<typename... Res> struct is_variant_result<VariantResultType<Res...>> : std::true_type {};
    template<typename T> constexpr bool is_variant_result_v = is_variant_result<T>::value;

    // ---- transformed() ----------------------------------------------------------------------------------------
    template<typename O, typename T>
    using TransformedResult = decltype(std::declval<O &>().transformed(std::declval<T &>()));
    //! Whether obj.transformed(tf) is valid. tf/VariantResult.h specialises this for GeneralTf, where the member
    //! `type` is the result type.
    template<typename Obj, typename Tf> struct is_transformable
    {
        using type = detail::is_detected<TransformedResult, Obj, Tf>;
        static constexpr bool value = type::value;
    };
    template<typename Obj, typename Tf> using is_transformable_t = typename is_transformable<Obj, Tf>::type;
    template<typename Obj, typename Tf> constexpr bool is_transformable_v = is_transformable<Obj, Tf>::value;

    // ---- inverted() -------------------------------------------------------------------------------------------
    template<typename T> using InvertedResult = decltype(std::declval<T &>().inverted());
    template<typename T> struct is_invertible
    {
        using type = detail::is_detected<InvertedResult, T>;
        static constexpr bool value = type::value;
    };
    template<typename T> using is_invertible_t = typename is_invertible<T>::type;
    template<typename T> constexpr bool is_invertible_v = is_invertible<T>::value;

    // ---- identity() -------------------------------------------------------------------------------------------
    template<typename T> using IdentityResult = decltype(T::identity());
    template<typename T> struct has_identity
    {
        using type = detail::is_detected<IdentityResult, T>;
        static constexpr bool value = type::value;
    };
    template<typename T> using has_identity_t = typename has_identity<T>::type;
    template<typename T> constexpr bool has_identity_v = has_identity<T>::value;

    // ---- nan() ------------------------------------------------------------------------------------------------
    template<typename T> using NaNResult = decltype(T::nan());
    template<typename T> struct has_nan
    {
        using type = detail::is_detected<NaNResult, T>;
        static constexpr bool value = type::value;
    };
    template<typename T> using has_nan_t = typename has_nan<T>::type;
    template<typename T> constexpr bool has_nan_v = has_nan<T>::value;

    // ---- random(generators...) --------------------------------------------------------------------------------
    template<typename Obj, typename... Gs> using RandomResult = decltype(Obj::random(std::declval<Gs &>()...));

    //! `HasRandomImpl<Obj, Gs...>::type`: whether Obj::random(Gs&...) is valid; a void generator type gives false.
    template<typename... Ts> struct HasRandomImpl;
    template<typename Obj, typename... Gs> struct HasRandomImpl<Obj, Gs...>
    {
        using type = std::conditional_t<(std::is_void_v<Gs> || ...), std::false_type,
                                        detail::is_detected<RandomResult, Obj, Gs...>>;
    };

    //! has_random<Obj>: Obj::random(g) with a generator g returning Obj::ElementType; has_random<Obj, G, Gs...>:
    //! Obj::random(G&, Gs&...).
    template<typename Obj, typename... RndGen> struct has_random
    {
        using type = typename HasRandomImpl<Obj, RndGen...>::type;
        static constexpr bool value = type::value;
    };
    template<typename Obj> struct has_random<Obj>
    {
        static_assert(has_element_type_v<Obj>, "has_random<Obj> without generator types needs Obj::ElementType.");
        using type = typename HasRandomImpl<Obj, detail::GeneratorOf<typename Obj::ElementType>>::type;
        static constexpr bool value = type::value;
    };
    template<typename Obj, typename... RndGen> using has_random_t = typename has_random<Obj, RndGen...>::type;
    template<typename Obj, typename... RndGen> constexpr bool has_random_v = has_random<Obj, RndGen...>::value;

    // ---- distance(a, b) ---------------------------------------------------------------------------------------
    template<typename T> using DistanceResult = decltype(T::distance(std::declval<T &>(), std::declval<T &>()));
    template<typename T> struct has_metric
    {
        using type = detail::is_detected<DistanceResult, T>;
        static constexpr bool value = type::value;
    };
    template<typename T> using has_metric_t = typename has_metric<T>::type;
    template<typename T> constexpr bool has_metric_v = has_metric<T>::value;

    // ---- dimensionality() -------------------------------------------------------------------------------------
    template<typename T> using DimensionalityResult = decltype(T::dimensionality());
    template<typename T> struct is_dimensional
    {
        using type = detail::is_detected<DimensionalityResult, T>;
        static constexpr bool value = type::value;
    };
    template<typename T> using is_dimensional_t = typename is_dimensional<T>::type;
    template<typename T> constexpr bool is_dimensional_v = is_dimensional<T>::value;
}
