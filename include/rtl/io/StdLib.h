// Stream output (operator<<) for the core and transformation types.
//
// Every overload lives in namespace rtl and is found by argument-dependent lookup. The published implementation
// declared them in the global namespace, which newer libstdc++ cannot find from its rvalue-stream operator<<
// (e.g. `std::ostringstream() << "text" << v`), so code using that idiom failed to compile
// (docs/reference.md, "Stream operators and argument-dependent lookup").
// Formats: vectors [a, b, c]; matrices [a, b; c, d]; quaternions w + xi - yj + zk; translations "t: <vector>";
// rotations "R: <matrix>" (3D adds "   axix: <axis>   angle: <angle>", label spelled as in the published version);
// rigid transformations "<rotation>   <translation>"; line segments "<beg>--><end>"; tree nodes "<key>   <tf>";
// trees print the root key, then one line per node, depth-first, indented by one tab per level.
// Additions (not in the published version): bounding boxes "min: <v>   max: <v>", polygons "{<v>, <v>, ...}"
// (3D prefixed by "n: <normal>   d: <distance>   "), frusta "origin: <v>   near: <v>, <v>, <v>, <v>   depth: <d>".
#pragma once

#include <cmath>
#include <cstddef>
#include <ostream>
#include <string>

#include "rtl/core/VectorND.h"
#include "rtl/core/Matrix.h"
#include "rtl/core/Quaternion.h"
#include "rtl/core/LineSegmentND.h"
#include "rtl/core/BoundingBoxND.h"
#include "rtl/core/Frustum3D.h"
#include "rtl/core/Polygon2D.h"
#include "rtl/core/Polygon3D.h"
#include "rtl/tf/TranslationND.h"
#include "rtl/tf/RotationND.h"
#include "rtl/tf/RigidTfND.h"
#include "rtl/tf/GeneralTf.h"
#include "rtl/tf/TfTreeNode.h"
#include "rtl/tf/TfTree.h"

namespace rtl
{
    namespace io {}

    template<int dimensions, typename Element>
    std::ostream &operator<<(std::ostream &os, const VectorND<dimensions, Element> &v)
    {
        os << "[";
        for (int i = 0; i < dimensions; ++i)
            os << (i > 0 ? ", " : "") << v[static_cast<size_t>(i)];
        return os << "]";
    }

    template<int rows, int cols, typename Element>
    std::ostream &operator<<(std::ostream &os, const Matrix<rows, cols, Element> &m)
    {
        os << "[";
        for (Eigen::Index r = 0; r < m.data().rows(); ++r)
        {
            if (r > 0)
                os << "; ";
            for (Eigen::Index c = 0; c < m.data().cols(); ++c)
                os << (c > 0 ? ", " : "") << m.data()(r, c);
        }
        return os << "]";
    }

    template<typename Element>
    std::ostream &operator<<(std::ostream &os, const Quaternion<Element> &q)
    {
        os << q.w();
        const Element parts[] = {q.x(), q.y(), q.z()};
        const char suffix[] = {'i', 'j', 'k'};
        for (int i = 0; i < 3; ++i)
            os << (parts[i] >= Element(0) ? " + " : " - ") << std::abs(parts[i]) << suffix[i];
        return os;
    }

    template<int dimensions, typename Element>
    std::ostream &operator<<(std::ostream &os, const TranslationND<dimensions, Element> &tr)
    {
        return os << "t: " << tr.trVec();
    }

    template<int dimensions, typename Element>
    std::ostream &operator<<(std::ostream &os, const RotationND<dimensions, Element> &rot)
    {
        return os << "R: " << rot.rotMat();
    }

    template<typename Element>
    std::ostream &operator<<(std::ostream &os, const RotationND<3, Element> &rot)
    {
        return os << "R: " << rot.rotMat() << "   axix: " << rot.rotAxis() << "   angle: " << rot.rotAngle();
    }

    template<int dimensions, typename Element>
    std::ostream &operator<<(std::ostream &os, const RigidTfND<dimensions, Element> &tf)
    {
        return os << tf.rot() << "   " << tf.tr();
    }

    template<typename T, typename... Tfs>
    std::ostream &operator<<(std::ostream &os, const GeneralTf<T, Tfs...> &gtf)
    {
        gtf.visit([&os](const auto &tf) { os << tf; });
        return os;
    }

    template<typename K, typename T>
    std::ostream &operator<<(std::ostream &os, const TfTreeNode<K, T> &node)
    {
        return os << node.key() << "   " << node.tf();
    }

    namespace detail
    {
        template<typename Node>
        void printSubtree(std::ostream &os, const Node &node, size_t level)
        {
            for (const auto *child : node.children())
            {
                os << std::string(level, '\t') << *child << "\n";
                printSubtree(os, *child, level + 1);
            }
        }
    }

    template<typename K, typename T>
    std::ostream &operator<<(std::ostream &os, const TfTree<K, T> &tree)
    {
        os << tree.root().key() << "\n";
        detail::printSubtree(os, tree.root(), 1);
        return os;
    }

    template<int dimensions, typename Element>
    std::ostream &operator<<(std::ostream &os, const LineSegmentND<dimensions, Element> &ls)
    {
        return os << ls.beg() << "-->" << ls.end();
    }

    template<int dimensions, typename Element>
    std::ostream &operator<<(std::ostream &os, const BoundingBoxND<dimensions, Element> &bb)
    {
        return os << "min: " << bb.min() << "   max: " << bb.max();
    }

    namespace detail
    {
        template<typename Points>
        std::ostream &printPoints(std::ostream &os, const Points &pts)
        {
            os << "{";
            for (size_t i = 0; i < pts.size(); ++i)
                os << (i > 0 ? ", " : "") << pts[i];
            return os << "}";
        }
    }

    template<typename Element>
    std::ostream &operator<<(std::ostream &os, const Polygon2D<Element> &p)
    {
        return detail::printPoints(os, p.points());
    }

    template<typename Element>
    std::ostream &operator<<(std::ostream &os, const Polygon3D<Element> &p)
    {
        os << "n: " << p.normal() << "   d: " << p.distance() << "   ";
        return detail::printPoints(os, p.points());
    }

    template<typename Element>
    std::ostream &operator<<(std::ostream &os, const Frustum3D<Element> &f)
    {
        return os << "origin: " << f.getOrigin() << "   near: " << f.getNearTopLeft() << ", " << f.getNearTopRight() << ", "
                  << f.getNearBottomLeft() << ", " << f.getNearBottomRight() << "   depth: " << f.getDepth();
    }
}
