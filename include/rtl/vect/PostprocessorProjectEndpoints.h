// PostprocessorProjectEndpoints: each approximation trimmed by the first and last point of its range (line
// segments between the projections of the two end points, or plane polygons of the projected points).
//
// representable() tells whether a result can be handed out in ElementType: the approximations are computed in
// ComputeType, so float points with coordinates beyond about sqrt(FLT_MAX) ~ 1.8e19 can give a squared error or a
// projected vertex that a float cannot hold (+inf). The 3D vectorizers reject such a result (false), as the 2D
// polylines do, rather than returning true with infinite numbers.
#pragma once

#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace rtl
{
    template<class Approximation>
    class PostprocessorProjectEndpoints
    {
    public:
        typedef typename Approximation::ElementType ElementType;
        typedef typename Approximation::ComputeType ComputeType;
        typedef typename Approximation::VectorType VectorType;
        typedef typename Approximation::ConstrainedType OutputType;
        typedef std::pair<size_t, size_t> IndexType;

        PostprocessorProjectEndpoints() = default;
        ~PostprocessorProjectEndpoints() = default;

        const std::vector<OutputType> &output() const { return out; }

        //! False if the inputs are empty, of different sizes, or a range is empty or out of bounds.
        bool operator()(const std::vector<VectorType> &pts, const std::vector<Approximation> &approximations,
                        const std::vector<IndexType> &indices)
        {
            out.clear();
            if (pts.empty() || approximations.empty() || approximations.size() != indices.size())
                return false;
            for (const auto &r : indices)
                if (r.first >= r.second || r.second > pts.size())
                    return false;
            out.reserve(indices.size());
            for (size_t i = 0; i < indices.size(); ++i)
                out.push_back(approximations[i].trim(pts.begin() + static_cast<std::ptrdiff_t>(indices[i].first),
                                                     pts.begin() + static_cast<std::ptrdiff_t>(indices[i].second)));
            return true;
        }

        //! Every approximation's errSquared() and every coordinate of the last output finite in ElementType.
        //! O(total output size).
        bool representable(const std::vector<Approximation> &approximations) const
        {
            for (const auto &a : approximations)
                if (!std::isfinite(static_cast<double>(a.errSquared())))
                    return false;
            for (const auto &o : out)
                if (!finite(o))
                    return false;
            return true;
        }

    private:
        std::vector<OutputType> out;

        static bool finite(const VectorType &v)
        {
            for (int k = 0; k < static_cast<int>(v.data().size()); ++k)
                if (!std::isfinite(static_cast<double>(v.data()(k))))
                    return false;
            return true;
        }
        //! A segment (beg, end) or a polygon (points, plane distance).
        template<class Output>
        static auto finite(const Output &o) -> decltype(o.beg(), bool())
        {
            return finite(o.beg()) && finite(o.end());
        }
        template<class Output>
        static auto finite(const Output &o) -> decltype(o.points(), bool())
        {
            for (const auto &p : o.points())
                if (!finite(p))
                    return false;
            return std::isfinite(static_cast<double>(o.distance()));
        }
    };
}
