// PrecSums2D/3D: the sums of coordinates, squares and cross products of a set of points (plus the count),
// from which a total-least-squares fit of the set follows in O(1). Sums of disjoint sets add, so prefix sums
// (PrecArray) give the sums of any index range by one subtraction.
#pragma once

#include <cstddef>

#include <Eigen/Dense>

#include "rtl/core/VectorND.h"

namespace rtl
{
    struct PrecSums2DNames { enum { cx = 0, cy, cx2, cy2, cxy, cn }; };
    struct PrecSums3DNames { enum { cx = 0, cy, cz, cx2, cy2, cz2, cxy, cyz, czx, cn }; };

    //! Shared arithmetic of PrecSums2D/3D (CRTP). `sums` holds the Names::cn sums followed by the point count.
    template<typename Compute, class Derived, class Names>
    struct PrecSumsBase : public Names
    {
        typedef Compute ComputeType;
        typedef Eigen::Array<ComputeType, 1, Names::cn + 1> EigenType;

        Derived operator+(const Derived &o) const { return Derived(EigenType(sums + o.sums)); }
        Derived &operator+=(const Derived &o) { sums += o.sums; return self(); }
        Derived operator-(const Derived &o) const { return Derived(EigenType(sums - o.sums)); }
        Derived &operator-=(const Derived &o) { sums -= o.sums; return self(); }

        //! Divides every entry, the count included, by the count (so the count becomes 1). No-op for an empty set.
        void average() { if (sums(Names::cn) != ComputeType(0)) sums /= sums(Names::cn); }
        Derived averaged() const { Derived d(self()); d.average(); return d; }
        void setZero() { sums.setZero(); }

        //! Number of sums without the count: 5 in 2D, 9 in 3D.
        [[nodiscard]] static constexpr size_t sumNr() { return static_cast<size_t>(Names::cn); }

        EigenType sums{EigenType::Zero()};

    protected:
        PrecSumsBase() = default;
        explicit PrecSumsBase(EigenType &&raw) : sums(std::move(raw)) {}
        ~PrecSumsBase() = default;

    private:
        Derived &self() { return static_cast<Derived &>(*this); }
        const Derived &self() const { return static_cast<const Derived &>(*this); }
    };

    template<typename Compute>
    struct PrecSums2D : public PrecSumsBase<Compute, PrecSums2D<Compute>, PrecSums2DNames>
    {
        typedef PrecSumsBase<Compute, PrecSums2D<Compute>, PrecSums2DNames> BaseType;
        typedef typename BaseType::ComputeType ComputeType;
        typedef typename BaseType::EigenType EigenType;
        using BaseType::cx, BaseType::cy, BaseType::cx2, BaseType::cy2, BaseType::cxy, BaseType::cn;
        using BaseType::sums;

        PrecSums2D() = default;
        explicit PrecSums2D(EigenType &&raw_sums) : BaseType(std::move(raw_sums)) {}
        PrecSums2D(ComputeType sum_x, ComputeType sum_y, ComputeType sum_x2, ComputeType sum_y2, ComputeType sum_xy,
                   size_t count)
        {
            sums << sum_x, sum_y, sum_x2, sum_y2, sum_xy, static_cast<ComputeType>(count);
        }
        explicit PrecSums2D(const VectorND<2, ComputeType> &v)
        {
            const ComputeType x = v.x(), y = v.y();
            sums << x, y, x * x, y * y, x * y, ComputeType(1);
        }

        ComputeType sx() const { return sums(cx); }
        ComputeType sy() const { return sums(cy); }
        ComputeType sx2() const { return sums(cx2); }
        ComputeType sy2() const { return sums(cy2); }
        ComputeType sxy() const { return sums(cxy); }
        ComputeType cnt() const { return sums(cn); }
    };

    template<typename Compute>
    struct PrecSums3D : public PrecSumsBase<Compute, PrecSums3D<Compute>, PrecSums3DNames>
    {
        typedef PrecSumsBase<Compute, PrecSums3D<Compute>, PrecSums3DNames> BaseType;
        typedef typename BaseType::ComputeType ComputeType;
        typedef typename BaseType::EigenType EigenType;
        using BaseType::cx, BaseType::cy, BaseType::cz, BaseType::cx2, BaseType::cy2, BaseType::cz2;
        using BaseType::cxy, BaseType::cyz, BaseType::czx, BaseType::cn;
        using BaseType::sums;

        PrecSums3D() = default;
        explicit PrecSums3D(EigenType &&raw_sums) : BaseType(std::move(raw_sums)) {}
        PrecSums3D(ComputeType sum_x, ComputeType sum_y, ComputeType sum_z, ComputeType sum_x2, ComputeType sum_y2,
                   ComputeType sum_z2, ComputeType sum_xy, ComputeType sum_yz, ComputeType sum_zx, size_t count)
        {
            sums << sum_x, sum_y, sum_z, sum_x2, sum_y2, sum_z2, sum_xy, sum_yz, sum_zx,
                    static_cast<ComputeType>(count);
        }
        explicit PrecSums3D(const VectorND<3, ComputeType> &v)
        {
            const ComputeType x = v.x(), y = v.y(), z = v.z();
            sums << x, y, z, x * x, y * y, z * z, x * y, y * z, z * x, ComputeType(1);
        }

        ComputeType sx() const { return sums(cx); }
        ComputeType sy() const { return sums(cy); }
        ComputeType sz() const { return sums(cz); }
        ComputeType sx2() const { return sums(cx2); }
        ComputeType sy2() const { return sums(cy2); }
        ComputeType sz2() const { return sums(cz2); }
        ComputeType sxy() const { return sums(cxy); }
        ComputeType syz() const { return sums(cyz); }
        ComputeType szx() const { return sums(czx); }
        ComputeType cnt() const { return sums(cn); }
    };
}
