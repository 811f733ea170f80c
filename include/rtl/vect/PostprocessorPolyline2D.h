// PostprocessorPolyline2D: turns consecutive 2D lines into a polyline. Vertices: the first point projected onto
// the first line, the crossing of each consecutive pair (computed in ComputeType; docs/reference.md,
// "Vectorization defects fixed here", defect 2), and the last point projected onto the last line. Segment i lies on
// line i.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "rtl/core/VectorND.h"

namespace rtl
{
    template<class Approximation>
    class PostprocessorPolyline2D
    {
    public:
        typedef typename Approximation::ElementType ElementType;
        typedef typename Approximation::ComputeType ComputeType;
        typedef typename Approximation::VectorType VectorType;
        typedef typename Approximation::ConstrainedType LineSegmentType;
        typedef std::pair<size_t, size_t> IndexType;
        typedef VectorND<2, ComputeType> ComputeVectorType;

        PostprocessorPolyline2D() = default;
        ~PostprocessorPolyline2D() = default;

        //! Segments joining consecutive vertices (directed along the chain); empty if fewer than 2 vertices.
        std::vector<LineSegmentType> lineSegments() const
        {
            std::vector<LineSegmentType> out;
            if (vertices_.size() < 2)
                return out;
            out.reserve(vertices_.size() - 1);
            for (size_t i = 0; i + 1 < vertices_.size(); ++i)
                out.emplace_back(vertices_[i], vertices_[i + 1], directions_[i]);
            return out;
        }
        //! The polyline vertices (lines + 1 of them after a successful call).
        const std::vector<VectorType> &vertices() const { return vertices_; }

        //! False if the inputs are empty or of different sizes, an index is out of range, or two consecutive lines
        //! are parallel.
        bool operator()(const std::vector<VectorType> &pts, const std::vector<Approximation> &lines, const std::vector<IndexType> &indices)
        {
            vertices_.clear();
            directions_.clear();
            if (pts.empty() || lines.empty() || lines.size() != indices.size() || indices.back().second > pts.size() ||
                indices.front().first >= indices.front().second)
                return false;
            vertices_.reserve(lines.size() + 1);
            directions_.reserve(lines.size());
            vertices_.push_back(lines.front().project(pts[indices.front().first]));
            for (size_t i = 0; i + 1 < lines.size(); ++i)
            {
                VectorType x;
                if (!Approximation::getCrossing(lines[i], lines[i + 1], x))
                {
                    vertices_.clear();
                    return false;
                }
                vertices_.push_back(x);
            }
            vertices_.push_back(lines.back().project(pts[indices.back().second - 1]));
            for (size_t i = 0; i < lines.size(); ++i)
            {
                // Orient each segment along the chain (from its first towards its last point).
                const auto &r = indices[i];
                const VectorType d = lines[i].direction(), span = pts[r.second - 1] - pts[r.first];
                directions_.push_back(span.dot(d) < 0 ? VectorType(-d) : d);
            }
            return true;
        }

    private:
        std::vector<VectorType> vertices_, directions_;
    };
}
