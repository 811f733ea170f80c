// Core module: vectors, matrices, quaternions, line segments, bounding boxes, frusta and polygons, plus the
// dimension- and element-fixed aliases (Vector3f, LineSegment2d, BoundingBox3f, Polygon2Df, ...).
#pragma once

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include "rtl/core/Utility.h"
#include "rtl/core/Constants.h"
#include "rtl/core/TypeTraits.h"
#include "rtl/core/VectorND.h"
#include "rtl/core/LineSegmentND.h"
#include "rtl/core/Matrix.h"
#include "rtl/core/BoundingBoxND.h"
#include "rtl/core/Frustum3D.h"
#include "rtl/core/Quaternion.h"
#include "rtl/core/Polygon2D.h"
#include "rtl/core/Polygon3D.h"

namespace rtl
{
    template<typename E> using Vector2D = VectorND<2, E>;
    using Vector2f = Vector2D<float>;
    using Vector2d = Vector2D<double>;
    template<typename E> using Vector3D = VectorND<3, E>;
    using Vector3f = Vector3D<float>;
    using Vector3d = Vector3D<double>;

    template<typename T> using MatrixD = Matrix<Eigen::Dynamic, Eigen::Dynamic, T>;
    using Matrix22f = Matrix<2, 2, float>;
    using Matrix33f = Matrix<3, 3, float>;
    using Matrix22d = Matrix<2, 2, double>;
    using Matrix33d = Matrix<3, 3, double>;

    template<typename E> using LineSegment2D = LineSegmentND<2, E>;
    using LineSegment2f = LineSegment2D<float>;
    using LineSegment2d = LineSegment2D<double>;
    template<typename E> using LineSegment3D = LineSegmentND<3, E>;
    using LineSegment3f = LineSegment3D<float>;
    using LineSegment3d = LineSegment3D<double>;

    template<typename E> using BoundingBox2D = BoundingBoxND<2, E>;
    using BoundingBox2f = BoundingBox2D<float>;
    using BoundingBox2d = BoundingBox2D<double>;
    template<typename E> using BoundingBox3D = BoundingBoxND<3, E>;
    using BoundingBox3f = BoundingBox3D<float>;
    using BoundingBox3d = BoundingBox3D<double>;

    using Frustum3f = Frustum3D<float>;
    using Frustum3d = Frustum3D<double>;

    using Quaternionf = Quaternion<float>;
    using Quaterniond = Quaternion<double>;

    using Polygon2Df = Polygon2D<float>;
    using Polygon2Dd = Polygon2D<double>;
    using Polygon3Df = Polygon3D<float>;
    using Polygon3Dd = Polygon3D<double>;
}
