// TfChain: a sequence of transformations applied in list order (front first), e.g. the path between two frames of
// a TfTree (docs/reference.md, "TfChain").
//
// Complexity: applying the chain or squash() costs one application (or composition) per element, O(length);
// applying an empty chain throws std::out_of_range, while squash() of an empty chain is T::identity(). The list is
// a std::list because TfTree::tf builds it from both ends.
#pragma once

#include <list>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <variant>

#include "rtl/tf/VariantResult.h"
#include "rtl/tf/GeneralTf.h"

namespace rtl
{
    namespace detail
    {
        //! Whether tf(x) is well-formed: for a GeneralTf, some alternative must be able to transform X.
        template<typename Tf, typename X>
        struct Applicable : std::bool_constant<!std::is_void_v<TransformedOrVoid_t<X, Tf>>> {};
        template<typename... Tfs, typename X>
        struct Applicable<GeneralTf<Tfs...>, X> : std::bool_constant<(VariantSize<VariantResultOTs<X, Tfs...>>::value > 0)> {};

        template<typename T> struct IsVariantResult : std::false_type {};
        template<typename... Rs> struct IsVariantResult<VariantResultType<Rs...>> : std::true_type {};

        //! tf(x) converted to the chain's result type R; dispatches on the held type when x is a VariantResultType.
        //! A held type that the step cannot transform throws std::bad_variant_access.
        template<typename R, typename Tf, typename X>
        R applyInto(const Tf &tf, const X &x)
        {
            if constexpr (IsVariantResult<X>::value)
                return x.visit([&tf](const auto &held) -> R { return applyInto<R>(tf, held); });
            else if constexpr (Applicable<Tf, X>::value)
                return R(tf(x));
            else
                throw std::bad_variant_access();
        }
    }

    template<typename T>
    class TfChain
    {
    public:
        using TransformationType = T;

        TfChain() = default;
        TfChain(const TfChain &cp) = default;
        TfChain(TfChain &&mv) noexcept : tfs(std::move(mv.tfs)) {}
        //! The list order is the application order.
        explicit TfChain(const std::list<TransformationType> &list) : tfs(list) {}
        explicit TfChain(std::list<TransformationType> &&list) noexcept : tfs(std::move(list)) {}
        TfChain &operator=(const TfChain &cp) = default;
        TfChain &operator=(TfChain &&mv) noexcept
        {
            tfs = std::move(mv.tfs);
            return *this;
        }
        ~TfChain() = default;

        /*! Applies every transformation, front first: {tf1, tf2, tf3}(x) == tf3(tf2(tf1(x))).
         *  Returns VariantResultRecursiveStripped<Object, T>: every type the chain can produce from an Object (a plain
         *  type when that is a single type). Throws std::out_of_range on an empty chain (there is no step to produce a
         *  result type from), and std::bad_variant_access when a step cannot transform the intermediate result. */
        template<typename Object>
        auto operator()(const Object &obj) const
        {
            using Result = VariantResultRecursiveStripped<Object, T>;
            static_assert(!std::is_same_v<Result, VariantResultType<>>, "The chain's transformations cannot transform this object.");
            if (tfs.empty())
                throw std::out_of_range("TfChain: cannot apply an empty chain");
            auto it = tfs.begin();
            Result current = detail::applyInto<Result>(*it, obj);
            for (++it; it != tfs.end(); ++it)
            {
                Result next = detail::applyInto<Result>(*it, current);
                current = std::move(next);
            }
            return current;
        }

        [[nodiscard]] const std::list<TransformationType> &list() const { return tfs; }

        //! The whole chain as one transformation: T::identity() transformed by each element in list order
        //! (the identity for an empty chain).
        [[nodiscard]] TransformationType squash() const
        {
            TransformationType r = TransformationType::identity();
            for (const auto &tf : tfs)
                r.transform(tf);
            return r;
        }

    private:
        std::list<TransformationType> tfs;
    };
}
