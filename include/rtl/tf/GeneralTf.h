// GeneralTf: one transformation object holding any of several transformation types (a std::variant of Tfs...),
// dispatching at run time on the held alternative (docs/reference.md, "GeneralTf").
//
// Applying it to an object returns the plain result type when every alternative able to transform the object yields
// the same type, otherwise a VariantResultType of the possible results. An alternative that cannot do the requested
// operation throws std::bad_variant_access at run time; if no alternative can, the call does not compile.
//
// Complexity: one std::visit (a jump on the held index) plus the held alternative's own cost; no allocation. Why a
// variant and not a virtual base: the alternatives stay value types with their own static result types, so the
// result set of every operation is known at compile time (VariantResult.h).
#pragma once

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <variant>

#include "rtl/core/TypeTraits.h"
#include "rtl/tf/VariantResult.h"

namespace rtl
{
    namespace detail
    {
        template<typename T, typename = void> struct HasIdentity : std::false_type {};
        template<typename T> struct HasIdentity<T, std::void_t<decltype(T::identity())>> : std::true_type {};

        template<typename T, typename = void> struct HasInvert : std::false_type {};
        template<typename T> struct HasInvert<T, std::void_t<decltype(std::declval<T &>().invert())>> : std::true_type {};

        template<typename T, typename G, typename = void> struct HasRandom : std::false_type {};
        template<typename T, typename G>
        struct HasRandom<T, G, std::void_t<decltype(T::random(std::declval<const G &>()))>> : std::true_type {};

        template<typename T, typename = void> struct ElementOf { using type = void; };
        template<typename T> struct ElementOf<T, std::void_t<typename T::ElementType>> { using type = typename T::ElementType; };

        //! Wraps an element generator so that its values are static_cast to the alternative's element type.
        template<typename Element, typename G>
        struct CastingGenerator
        {
            const G &gen;
            Element operator()() const { return static_cast<Element>(gen()); }
        };

        template<typename T> struct IsGeneralTf : std::false_type {};
        template<typename... Tfs> struct IsGeneralTf<GeneralTf<Tfs...>> : std::true_type {};
    }

    template<typename... Tfs>
    class GeneralTf
    {
        static_assert(sizeof...(Tfs) > 0, "GeneralTf needs at least one alternative.");
        static_assert(detail::all_distinct<Tfs...>::value, "GeneralTf alternatives must be distinct.");
        template<typename... Os> friend class GeneralTf;

        using VariantType = std::variant<Tfs...>;
        template<typename T> static constexpr bool is_alternative = detail::is_one_of_v<T, Tfs...>;

    public:
        template<size_t I> using AlternativeType = std::variant_alternative_t<I, VariantType>;

        //! Holds a value-initialised first alternative.
        GeneralTf() = default;
        GeneralTf(const GeneralTf &cp) = default;
        GeneralTf(GeneralTf &&mv) noexcept : var(std::move(mv.var)) {}
        //! Implicit from any alternative.
        template<typename T, std::enable_if_t<is_alternative<T>, int> = 0>
        GeneralTf(const T &tf) : var(std::in_place_type<T>, tf) {}
        ~GeneralTf() = default;

        GeneralTf &operator=(const GeneralTf &cp) = default;
        GeneralTf &operator=(GeneralTf &&mv) noexcept
        {
            var = std::move(mv.var);
            return *this;
        }
        //! Assigns an alternative (switching the held type). Constrained to the alternatives, so that `a = b;` with a
        //! non-const GeneralTf lvalue b is an ordinary copy assignment.
        template<typename T, std::enable_if_t<is_alternative<std::decay_t<T>>, int> = 0>
        GeneralTf &operator=(T &&tf) noexcept
        {
            var.template emplace<std::decay_t<T>>(std::forward<T>(tf));
            return *this;
        }

        //! Position of the held type in Tfs...
        [[nodiscard]] constexpr size_t index() const noexcept { return var.index(); }

        template<typename Visitor>
        decltype(auto) visit(Visitor &&vis) { return std::visit(std::forward<Visitor>(vis), var); }
        template<typename Visitor>
        decltype(auto) visit(Visitor &&vis) const { return std::visit(std::forward<Visitor>(vis), var); }

        //! Inverts the held alternative in place; throws std::bad_variant_access if it has no invert().
        void invert()
        {
            static_assert((detail::HasInvert<Tfs>::value || ...), "No alternative of this GeneralTf is invertible.");
            std::visit([](auto &t) {
                if constexpr (detail::HasInvert<std::decay_t<decltype(t)>>::value)
                    t.invert();
                else
                    throw std::bad_variant_access();
            }, var);
        }
        [[nodiscard]] GeneralTf inverted() const
        {
            GeneralTf r(*this);
            r.invert();
            return r;
        }

        //! obj.transformed(held alternative). Returns VariantResultOTsStripped<T, Tfs...>.
        template<typename T>
        auto operator()(const T &obj) const
        {
            using Result = VariantResultOTsStripped<T, Tfs...>;
            static_assert(detail::VariantSize<VariantResultOTs<T, Tfs...>>::value > 0,
                          "No alternative of this GeneralTf can transform the object.");
            return std::visit([&obj](const auto &tf) -> Result {
                using Tf = std::decay_t<decltype(tf)>;
                if constexpr (!std::is_void_v<detail::TransformedOrVoid_t<T, Tf>>)
                    return Result(obj.transformed(tf));
                else
                    throw std::bad_variant_access();
            }, var);
        }

        //! Applies this transformation to another GeneralTf: gtf's held alternative followed by this one's. The result
        //! must be one of Tfs... (else std::bad_variant_access).
        template<typename... Tfs2>
        GeneralTf operator()(const GeneralTf<Tfs2...> &gtf) const
        {
            return std::visit([](const auto &inner, const auto &outer) { return compose(inner, outer); }, gtf.var, var);
        }

        //! The held alternative as T; throws std::bad_variant_access if another one is held.
        template<typename T>
        [[nodiscard]] T tf() const { return std::get<T>(var); }

        //! This transformation followed by tr (a plain transformation). The result must be one of Tfs...
        template<typename T>
        [[nodiscard]] GeneralTf transformed(const T &tr) const
        {
            return std::visit([&tr](const auto &inner) { return compose(inner, tr); }, var);
        }
        //! This transformation followed by gtf's held alternative.
        template<typename... Tfs2>
        [[nodiscard]] GeneralTf transformed(const GeneralTf<Tfs2...> &gtf) const
        {
            return std::visit([](const auto &inner, const auto &outer) { return compose(inner, outer); }, var, gtf.var);
        }

        //! Held alternative := tf(held alternative); throws std::bad_variant_access if that is not possible.
        template<typename T>
        void transform(const T &tf) { *this = transformed(tf); }
        template<typename... Tfs2>
        void transform(const GeneralTf<Tfs2...> &gtf) { *this = transformed(gtf); }

        //! identity() of the first alternative that has one.
        static GeneralTf identity()
        {
            constexpr size_t i = firstIndex<detail::HasIdentity>();
            static_assert(i < sizeof...(Tfs), "No alternative of this GeneralTf has identity().");
            return GeneralTf(AlternativeType<i>::identity());
        }

        //! random() of the first alternative that has one; generated elements are static_cast to its ElementType.
        template<class ElRndSrc>
        static GeneralTf random(const ElRndSrc &el_rnd_gen)
        {
            constexpr size_t i = firstRandomIndex<ElRndSrc>(std::index_sequence_for<Tfs...>{});
            static_assert(i < sizeof...(Tfs), "No alternative of this GeneralTf has random().");
            return randomAlternative<i>(el_rnd_gen);
        }

        //! random() of alternative number tf_rnd_gen() (0..N-1), elements static_cast to its ElementType.
        //! Throws std::out_of_range for an index >= N and std::invalid_argument if that alternative has no random().
        template<class ElRndSrc, class TfRndSrc>
        static GeneralTf random(const ElRndSrc &el_rnd_gen, const TfRndSrc &tf_rnd_gen)
        {
            const auto drawn = tf_rnd_gen();
            bool negative = false;
            if constexpr (std::is_signed_v<std::decay_t<decltype(drawn)>>)
                negative = drawn < 0;
            if (negative || static_cast<size_t>(drawn) >= sizeof...(Tfs))
                throw std::out_of_range("GeneralTf::random: alternative index out of range");
            return randomAt(static_cast<size_t>(drawn), el_rnd_gen, std::index_sequence_for<Tfs...>{});
        }

        //! Implicit conversion to an alternative type (std::get: throws std::bad_variant_access on the wrong one).
        //! Non-const, so it also serves `gtf.template operator()<T>(non_const_gtf)` and prvalue casts.
        template<typename T, std::enable_if_t<is_alternative<T>, int> = 0>
        operator T() { return std::get<T>(var); }
        template<typename T, std::enable_if_t<is_alternative<T>, int> = 0>
        operator T() const { return std::get<T>(var); }

    private:
        VariantType var;

        //! inner.transformed(outer) as a GeneralTf; throws std::bad_variant_access if that composition does not exist or
        //! its type is not an alternative.
        template<typename Inner, typename Outer>
        static GeneralTf compose(const Inner &inner, const Outer &outer)
        {
            using R = detail::TransformedOrVoid_t<Inner, Outer>;
            if constexpr (is_alternative<R>)
                return GeneralTf(inner.transformed(outer));
            else
                throw std::bad_variant_access();
        }

        template<template<typename...> class Trait>
        static constexpr size_t firstIndex()
        {
            constexpr bool has[] = {Trait<Tfs>::value...};
            for (size_t i = 0; i < sizeof...(Tfs); ++i)
                if (has[i]) return i;
            return sizeof...(Tfs);
        }

        template<class G, size_t... I>
        static constexpr size_t firstRandomIndex(std::index_sequence<I...>)
        {
            constexpr bool has[] = {canRandom<I, G>()...};
            for (size_t i = 0; i < sizeof...(Tfs); ++i)
                if (has[i]) return i;
            return sizeof...(Tfs);
        }

        template<size_t I, class G>
        static constexpr bool canRandom()
        {
            using Alt = AlternativeType<I>;
            using El = typename detail::ElementOf<Alt>::type;
            if constexpr (std::is_void_v<El>)
                return detail::HasRandom<Alt, G>::value;
            else
                return detail::HasRandom<Alt, detail::CastingGenerator<El, G>>::value;
        }

        template<size_t I, class G>
        static GeneralTf randomAlternative(const G &gen)
        {
            using Alt = AlternativeType<I>;
            using El = typename detail::ElementOf<Alt>::type;
            if constexpr (!canRandom<I, G>())
                throw std::invalid_argument("GeneralTf::random: the drawn alternative has no random()");
            else if constexpr (std::is_void_v<El>)
                return GeneralTf(Alt::random(gen));
            else
                return GeneralTf(Alt::random(detail::CastingGenerator<El, G>{gen}));
        }

        template<class G, size_t... I>
        static GeneralTf randomAt(size_t index, const G &gen, std::index_sequence<I...>)
        {
            std::optional<GeneralTf> r;
            ((I == index ? (r.emplace(randomAlternative<I>(gen)), true) : false) || ...);
            return std::move(*r);
        }
    };
}
