// PrecArray2D/3D: prefix sums of the PrecSums quantities over an ordered point set. Row i holds the sums of the
// first i points (row 0 is zero), so the sums of the half-open index range [beg, end) are row(end) - row(beg).
// Rows are stored row-major: one range query reads two contiguous rows. The count column is implicit (= row index).
#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/Dense>

#include "rtl/core/VectorND.h"
#include "rtl/vect/PrecSums.h"

namespace rtl
{
    //! Shared storage and range queries of PrecArray2D/3D ("Aray" is the published spelling).
    template<typename Compute, class SumType>
    struct PrecArayBase
    {
        typedef Compute ComputeType;
        static constexpr int cols = static_cast<int>(SumType::sumNr());
        typedef Eigen::Array<ComputeType, Eigen::Dynamic, cols, Eigen::RowMajor> EigenType;

        //! Rows in use: number of points + 1.
        [[nodiscard]] size_t size() const { return array_size; }

        //! Makes room for pts_cnt points and zeroes row 0. Never shrinks the allocation, so a buffer sized once for
        //! the largest scan is reused without allocating.
        void resize(size_t pts_cnt)
        {
            if (static_cast<size_t>(array.rows()) < pts_cnt + 1)
                array.conservativeResize(static_cast<Eigen::Index>(pts_cnt + 1), cols);
            array.row(0).setZero();
            array_size = pts_cnt + 1;
        }

        //! Sums of the first `index` points (count = index). Precondition: index < size().
        SumType sums(size_t index) const
        {
            SumType s;
            const ComputeType *r = array.data() + index * cols;
            for (int k = 0; k < cols; ++k)
                s.sums(k) = r[k];
            s.sums(cols) = static_cast<ComputeType>(index);
            return s;
        }

        //! Sums of the points [beg, end) (count = end - beg). Precondition: beg <= end < size().
        SumType sums(size_t beg, size_t end) const
        {
            SumType s;
            const ComputeType *rb = array.data() + beg * cols, *re = array.data() + end * cols;
            for (int k = 0; k < cols; ++k)
                s.sums(k) = re[k] - rb[k];
            s.sums(cols) = static_cast<ComputeType>(end - beg);
            return s;
        }

        //! True if every precomputed sum is finite (i.e. all points were finite).
        [[nodiscard]] bool allFinite() const
        {
            return array_size > 0 && array.row(static_cast<Eigen::Index>(array_size - 1)).allFinite();
        }

        EigenType array;
        size_t array_size{};
    };

    template<typename Element, typename Compute>
    struct PrecArray2D : public PrecArayBase<Compute, PrecSums2D<Compute>>
    {
        typedef PrecSums2D<Compute> SumsType;
        typedef PrecArayBase<Compute, SumsType> BaseType;
        typedef Element ElementType;
        typedef Compute ComputeType;
        typedef typename BaseType::EigenType EigenType;

        //! Fills the cumulative rows for `vec` (accumulated in ComputeType).
        void precompute(const std::vector<VectorND<2, ElementType>> &vec)
        {
            this->resize(vec.size());
            ComputeType x = 0, y = 0, x2 = 0, y2 = 0, xy = 0;
            ComputeType *row = this->array.data() + 5;
            for (const auto &p : vec)
            {
                const ComputeType px = static_cast<ComputeType>(p.x()), py = static_cast<ComputeType>(p.y());
                x += px; y += py; x2 += px * px; y2 += py * py; xy += px * py;
                row[0] = x; row[1] = y; row[2] = x2; row[3] = y2; row[4] = xy;
                row += 5;
            }
        }
    };

    template<typename Element, typename Compute>
    struct PrecArray3D : public PrecArayBase<Compute, PrecSums3D<Compute>>
    {
        typedef PrecSums3D<Compute> SumsType;
        typedef PrecArayBase<Compute, SumsType> BaseType;
        typedef Element ElementType;
        typedef Compute ComputeType;
        typedef typename BaseType::EigenType EigenType;

        void precompute(const std::vector<VectorND<3, ElementType>> &vec)
        {
            this->resize(vec.size());
            ComputeType x = 0, y = 0, z = 0, x2 = 0, y2 = 0, z2 = 0, xy = 0, yz = 0, zx = 0;
            ComputeType *row = this->array.data() + 9;
            for (const auto &p : vec)
            {
                const ComputeType px = static_cast<ComputeType>(p.x()), py = static_cast<ComputeType>(p.y()),
                                  pz = static_cast<ComputeType>(p.z());
                x += px; y += py; z += pz;
                x2 += px * px; y2 += py * py; z2 += pz * pz;
                xy += px * py; yz += py * pz; zx += pz * px;
                row[0] = x; row[1] = y; row[2] = z; row[3] = x2; row[4] = y2; row[5] = z2;
                row[6] = xy; row[7] = yz; row[8] = zx;
                row += 9;
            }
        }
    };
}
