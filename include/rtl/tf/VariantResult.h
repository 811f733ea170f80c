// VariantResultType: the result of an operation whose type depends on which alternative a GeneralTf holds at run
// time, plus the type-level machinery that computes those result sets
// (docs/reference.md, "VariantResultType").
//
// A result set is written as VariantResultType<R...>: distinct types in first-appearance order. Transformations
// that cannot be applied contribute nothing (they are detected as void and dropped). A set with a single type is
// "stripped" to that plain type where the API says so.
#pragma once

#include <cstddef>
#include <type_traits>
#include <utility>
#include <variant>

#include "rtl/core/TypeTraits.h"

namespace rtl
{
    template<typename... Tfs> class GeneralTf;
    template<typename... Res> class VariantResultType;

    namespace detail
    {
        template<typename T, typename... Ts>
        constexpr bool is_one_of_v = (std::is_same_v<T, Ts> || ...);

        template<typename... Ts> struct all_distinct : std::true_type {};
        template<typename T, typename... Ts>
        struct all_distinct<T, Ts...> : std::bool_constant<!is_one_of_v<T, Ts...> && all_distinct<Ts...>::value> {};

        //! decltype(obj.transformed(tf)) for const operands, or void when that expression is ill-formed.
        template<typename Obj, typename Tf, typename = void>
        struct TransformedOrVoid { using type = void; };
        template<typename Obj, typename Tf>
        struct TransformedOrVoid<Obj, Tf, std::void_t<decltype(std::declval<const Obj &>().transformed(std::declval<const Tf &>()))>>
        {
            using type = std::decay_t<decltype(std::declval<const Obj &>().transformed(std::declval<const Tf &>()))>;
        };
        template<typename Obj, typename Tf>
        using TransformedOrVoid_t = typename TransformedOrVoid<Obj, Tf>::type;

        template<typename VR> struct VariantSize;
        template<typename... Res> struct VariantSize<VariantResultType<Res...>> : std::integral_constant<size_t, sizeof...(Res)> {};

        template<typename T> struct Identity { using type = T; };
    }

    //! `Unique<VariantResultType<Known...>, Ts...>::type`: Known... followed by those Ts that are neither void nor
    //! already present, in first-appearance order.
    template<typename T, typename... Ts> struct Unique;
    template<typename... Known>
    struct Unique<VariantResultType<Known...>> { using type = VariantResultType<Known...>; };
    template<typename... Known, typename T, typename... Ts>
    struct Unique<VariantResultType<Known...>, T, Ts...>
    {
        using type = typename std::conditional_t<std::is_void_v<T> || detail::is_one_of_v<T, Known...>,
                                                 Unique<VariantResultType<Known...>, Ts...>,
                                                 Unique<VariantResultType<Known..., T>, Ts...>>::type;
    };

    namespace detail
    {
        //! Union of several result sets, in first-appearance order.
        template<typename Acc, typename... Sets> struct UnionOf { using type = Acc; };
        template<typename Acc, typename... Res, typename... Sets>
        struct UnionOf<Acc, VariantResultType<Res...>, Sets...>
        {
            using type = typename UnionOf<typename Unique<Acc, Res...>::type, Sets...>::type;
        };
    }

    //! The set of types obtained by transforming an Obj with any one of Tfs.
    template<typename Obj, typename... Tfs>
    using VariantResultOTs = typename Unique<VariantResultType<>, detail::TransformedOrVoid_t<Obj, Tfs>...>::type;

    //! The set of types obtained by transforming any one of Objs with Tf.
    template<typename Tf, typename... Objs>
    using VariantResultTOs = typename Unique<VariantResultType<>, detail::TransformedOrVoid_t<Objs, Tf>...>::type;

    //! VariantResultType<X> -> X; anything else is left unchanged.
    template<typename T> struct StripIfUnique { using type = T; };
    template<typename T> struct StripIfUnique<VariantResultType<T>> { using type = T; };

    template<typename Obj, typename... Tfs>
    using VariantResultOTsStripped = typename StripIfUnique<VariantResultOTs<Obj, Tfs...>>::type;
    template<typename Tf, typename... Objs>
    using VariantResultTOsStripped = typename StripIfUnique<VariantResultTOs<Tf, Objs...>>::type;

    //! One closure step: `Expansion<Known, New, Tfs...>::type` is Known together with every type obtained by
    //! transforming a member of New with one of Tfs.
    template<typename VRTKnown, typename VRTNew, typename... Tfs> struct Expansion;
    template<typename... Known, typename... New, typename... Tfs>
    struct Expansion<VariantResultType<Known...>, VariantResultType<New...>, Tfs...>
    {
        using type = typename detail::UnionOf<VariantResultType<Known...>, VariantResultOTs<New, Tfs...>...>::type;
    };

    //! Closure of the set VR1 under repeated application of Tfs: expands until a step adds no new type
    //! (Unique only ever appends, so an unchanged size means a fixed point).
    template<typename VR1, typename... Tfs>
    struct Recursion
    {
    private:
        using Next = typename Expansion<VR1, VR1, Tfs...>::type;
    public:
        using type = typename std::conditional_t<detail::VariantSize<Next>::value == detail::VariantSize<VR1>::value,
                                                 detail::Identity<VR1>, Recursion<Next, Tfs...>>::type;
    };

    //! Every type reachable from Obj by applying one or more of Tfs in sequence (e.g. along a TfChain).
    template<typename Obj, typename... Tfs>
    struct VariantResultRecursiveType
    {
        using type = typename Recursion<VariantResultOTs<Obj, Tfs...>, Tfs...>::type;
    };
    //! A GeneralTf step may apply any of its alternatives.
    template<typename Obj, typename... Tfs>
    struct VariantResultRecursiveType<Obj, GeneralTf<Tfs...>>
    {
        using type = typename Recursion<VariantResultOTs<Obj, Tfs...>, Tfs...>::type;
    };
    template<typename Obj, typename... Tfs>
    using VariantResultRecursive = typename VariantResultRecursiveType<Obj, Tfs...>::type;
    template<typename Obj, typename... Tfs>
    using VariantResultRecursiveStripped = typename StripIfUnique<VariantResultRecursive<Obj, Tfs...>>::type;

    //! An Obj is transformable by a GeneralTf when at least one alternative can transform it; the member `type` is the result.
    template<typename Obj, typename... Tfs>
    struct is_transformable<Obj, GeneralTf<Tfs...>>
    {
        using type = VariantResultOTsStripped<Obj, Tfs...>;
        static constexpr bool value = detail::VariantSize<VariantResultOTs<Obj, Tfs...>>::value > 0;
    };

    //! A value of one of Res..., known only at run time. Converts implicitly from each Res and to each Res
    //! (converting to a type that is not the held one throws std::bad_variant_access).
    template<typename... Res>
    class VariantResultType
    {
        static_assert(detail::all_distinct<Res...>::value, "VariantResultType alternatives must be distinct.");
        template<typename... Os> friend class VariantResultType;

    public:
        using VariantType = std::variant<Res...>;
        static constexpr size_t alternatives_cnt = sizeof...(Res);

        VariantResultType(const VariantResultType &cp) = default;
        VariantResultType(VariantResultType &&mv) noexcept : var(std::move(mv.var)) {}

        template<typename T, std::enable_if_t<detail::is_one_of_v<T, Res...>, int> = 0>
        VariantResultType(const T &t) : var(std::in_place_type<T>, t) {}

        //! From a result set that is a subset of this one (e.g. one chain step's results into the chain's closure).
        template<typename... Os, std::enable_if_t<!std::is_same_v<VariantResultType<Os...>, VariantResultType>
                                                  && (detail::is_one_of_v<Os, Res...> && ...), int> = 0>
        VariantResultType(const VariantResultType<Os...> &o)
                : var(std::visit([](const auto &x) { return VariantType(std::in_place_type<std::decay_t<decltype(x)>>, x); }, o.var)) {}

        VariantResultType &operator=(const VariantResultType &cp) = default;
        VariantResultType &operator=(VariantResultType &&mv) noexcept
        {
            var = std::move(mv.var);
            return *this;
        }

        //! Position of the held type in Res...
        [[nodiscard]] constexpr size_t index() const noexcept { return var.index(); }

        //! The held value as T; throws std::bad_variant_access if another alternative is held.
        template<typename T, std::enable_if_t<detail::is_one_of_v<T, Res...>, int> = 0>
        operator T() const { return std::get<T>(var); }

        //! Calls vis with the held value.
        template<typename Visitor>
        decltype(auto) visit(Visitor &&vis) const { return std::visit(std::forward<Visitor>(vis), var); }

        [[nodiscard]] const VariantType &variant() const noexcept { return var; }

    private:
        VariantType var;
    };

    //! The empty result set: only a type-level marker (nothing can be held), so it is never instantiated as a variant.
    template<>
    class VariantResultType<>
    {
    public:
        static constexpr size_t alternatives_cnt = 0;
        VariantResultType() = delete;
    };
}
