// PostprocessorProjectEndpoints: each approximation trimmed by the first and last point of its range (line
// segments between the projections of the two end points, or plane polygons of the projected points).
#pragma once

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

    private:
        std::vector<OutputType> out;
    };
}
