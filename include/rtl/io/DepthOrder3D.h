// Painter's ordering of a camera-space scene (Camera3D.h): the faces form a BSP tree, split where they cross;
// lines and marks are sorted into it; a traversal from the camera's point of view visits everything back to front.
//
// Complexity: building the tree costs O(F log F) for F faces that rarely cross and up to O(F^2) fragments when
// many do (each node's splitter is the best of up to 5 candidates: balanced sides, few splits); inserting an item
// costs the depth of the tree (a line crossing planes is split into pieces); the items of one leaf list are sorted
// by distance to the camera, O(n log n).
// Invariants: every polygon fragment keeps the index of its face and which of its edges are original outline
// edges; the camera is at the origin, so a plane n.p = d faces it when -d > 0.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

#include "rtl/io/Camera3D.h"
#include "rtl/io/Drawing3D.h"

namespace rtl
{
    namespace detail
    {
        //! A BSP node: the plane n.p = d, the polygons on it, and what lies in front of and behind it (a subtree,
        //! or, where there is none, a list of items).
        struct DepthNode3D
        {
            V3 n;
            double d;
            std::vector<CameraPoly3D> polys;
            std::vector<CameraItem3D> on, front_items, back_items;
            std::unique_ptr<DepthNode3D> front, back;
        };

        //! Splits p by the plane (n, d) with tolerance eps into front/back parts; coplanar polygons go to `on`.
        inline void splitPoly3D(const CameraPoly3D &p, const V3 &n, double d, double eps, std::vector<CameraPoly3D> &front,
                                std::vector<CameraPoly3D> &back, std::vector<CameraPoly3D> &on)
        {
            size_t k = p.v.size();
            std::vector<double> s(k);
            bool any_f = false, any_b = false;
            for (size_t i = 0; i < k; ++i)
            {
                s[i] = n.dot(p.v[i]) - d;
                any_f |= s[i] > eps;
                any_b |= s[i] < -eps;
            }
            if (!any_f && !any_b)
                return on.push_back(p);
            if (!any_b)
                return front.push_back(p);
            if (!any_f)
                return back.push_back(p);
            CameraPoly3D f{{}, {}, p.face, p.normal}, b{{}, {}, p.face, p.normal};
            for (size_t i = 0; i < k; ++i)
            {
                size_t j = (i + 1) % k;
                bool a_f = s[i] >= -eps, a_b = s[i] <= eps, b_f = s[j] >= -eps, b_b = s[j] <= eps;
                if (a_f)
                {
                    f.v.push_back(p.v[i]);
                    f.edge.push_back((s[i] > eps || b_f) ? p.edge[i] : 0);
                }
                if (a_b)
                {
                    b.v.push_back(p.v[i]);
                    b.edge.push_back((s[i] < -eps || b_b) ? p.edge[i] : 0);
                }
                if ((s[i] > eps && s[j] < -eps) || (s[i] < -eps && s[j] > eps))
                {
                    V3 x = p.v[i] + (p.v[j] - p.v[i]) * (s[i] / (s[i] - s[j]));
                    f.v.push_back(x);
                    f.edge.push_back(s[j] > eps ? p.edge[i] : 0);
                    b.v.push_back(x);
                    b.edge.push_back(s[j] < -eps ? p.edge[i] : 0);
                }
            }
            if (f.v.size() >= 3)
                front.push_back(std::move(f));
            if (b.v.size() >= 3)
                back.push_back(std::move(b));
        }

        //! The BSP tree of the polygons (nullptr if there are none); eps is the plane tolerance.
        inline std::unique_ptr<DepthNode3D> buildDepthTree3D(std::vector<CameraPoly3D> polys, double eps)
        {
            if (polys.empty())
                return nullptr;
            auto node = std::make_unique<DepthNode3D>();
            auto planeOf = [](const CameraPoly3D &p, V3 &n, double &d) {
                n = Drawing3D::newell(p.v);
                if (n.dot(p.normal) < 0)
                    n = -n;
                n.normalize();
                V3 centroid = V3::Zero();
                for (const auto &v : p.v)
                    centroid += v;
                d = n.dot(centroid / static_cast<double>(p.v.size()));
            };
            // Splitter: the best of up to 5 evenly spaced candidates (balanced sides, few splits), so that e.g. a
            // stack of parallel faces gives a tree of logarithmic depth instead of a list.
            size_t best = 0;
            if (polys.size() > 8)
            {
                double best_cost = std::numeric_limits<double>::infinity();
                for (size_t k = 0; k < 5; ++k)
                {
                    size_t c = k * (polys.size() - 1) / 4;
                    V3 n;
                    double d;
                    planeOf(polys[c], n, d);
                    size_t nf = 0, nb = 0, ns = 0;
                    for (const auto &p : polys)
                    {
                        bool f = false, b = false;
                        for (const auto &v : p.v)
                        {
                            double sd = n.dot(v) - d;
                            f |= sd > eps;
                            b |= sd < -eps;
                        }
                        nf += f && !b;
                        nb += b && !f;
                        ns += f && b;
                    }
                    double cost = std::abs(static_cast<double>(nf) - static_cast<double>(nb)) + 3.0 * static_cast<double>(ns);
                    if (cost < best_cost)
                    {
                        best_cost = cost;
                        best = c;
                    }
                }
            }
            std::swap(polys[0], polys[best]);
            const CameraPoly3D &sp = polys.front();
            V3 n;
            planeOf(sp, n, node->d);
            node->n = n;
            std::vector<CameraPoly3D> front, back;
            node->polys.push_back(sp);
            for (size_t i = 1; i < polys.size(); ++i)
                splitPoly3D(polys[i], n, node->d, eps, front, back, node->polys);
            polys.clear();
            node->front = buildDepthTree3D(std::move(front), eps);
            node->back = buildDepthTree3D(std::move(back), eps);
            return node;
        }

        inline void insertDepthItem3D(DepthNode3D *node, const CameraItem3D &it, double eps);

        //! Puts an item that lies on `side` of node's plane into that subtree (or the node's side list).
        inline void placeDepthItem3D(DepthNode3D *node, const CameraItem3D &it, int side, double eps)
        {
            std::unique_ptr<DepthNode3D> &child = side > 0 ? node->front : node->back;
            if (!child)
                (side > 0 ? node->front_items : node->back_items).push_back(it);
            else
                insertDepthItem3D(child.get(), it, eps);
        }

        //! Sorts a mark or line into the tree; a line crossing a node's plane is split there.
        inline void insertDepthItem3D(DepthNode3D *node, const CameraItem3D &it, double eps)
        {
            while (true)
            {
                double sa = node->n.dot(it.a) - node->d;
                double sb = it.is_mark ? sa : node->n.dot(it.b) - node->d;
                int side;   // 1 front, -1 back, 0 on
                if (std::abs(sa) <= eps && std::abs(sb) <= eps)
                    side = 0;
                else if (sa >= -eps && sb >= -eps)
                    side = 1;
                else if (sa <= eps && sb <= eps)
                    side = -1;
                else
                {
                    V3 x = it.a + (it.b - it.a) * (sa / (sa - sb));
                    CameraItem3D fa = it, fb = it;
                    fa.b = x;
                    fb.a = x;
                    // Each half goes to its end's side without being tested against this plane again: with large
                    // coordinates the rounded split point can miss the plane by more than eps, and re-testing
                    // recursed without end (fuzz_tikz3d: stack overflow).
                    placeDepthItem3D(node, fa, sa > 0 ? 1 : -1, eps);
                    placeDepthItem3D(node, fb, sb > 0 ? 1 : -1, eps);
                    return;
                }
                if (side == 0)
                    return node->on.push_back(it);
                std::unique_ptr<DepthNode3D> &child = side > 0 ? node->front : node->back;
                if (!child)
                    return (side > 0 ? node->front_items : node->back_items).push_back(it);
                node = child.get();
            }
        }

        //! Sorts items far to near (distance from the camera of a mark, of a line's midpoint).
        inline void sortFarToNear3D(std::vector<CameraItem3D> &items)
        {
            std::sort(items.begin(), items.end(),
                      [](const CameraItem3D &a, const CameraItem3D &b) { return a.depth() > b.depth(); });
        }

        //! Visits the tree back to front: `onPoly(const CameraPoly3D &)` for each polygon,
        //! `onItems(const std::vector<CameraItem3D> &)` for each item list, sorted far to near (in place).
        template<class OnPoly, class OnItems>
        void paintBackToFront3D(DepthNode3D *node, OnPoly &&onPoly, OnItems &&onItems)
        {
            bool cam_front = -node->d > 0;   // camera at the origin
            auto side = [&](bool front) {
                DepthNode3D *child = front ? node->front.get() : node->back.get();
                if (child)
                    paintBackToFront3D(child, onPoly, onItems);
                else
                {
                    std::vector<CameraItem3D> &items = front ? node->front_items : node->back_items;
                    sortFarToNear3D(items);
                    onItems(items);
                }
            };
            side(!cam_front);
            for (const auto &p : node->polys)
                onPoly(p);
            sortFarToNear3D(node->on);
            onItems(node->on);
            side(cam_front);
        }

        //! Paints the whole camera scene back to front (its items are consumed into the tree).
        template<class OnPoly, class OnItems>
        void paintScene3D(CameraScene3D &cs, OnPoly &&onPoly, OnItems &&onItems)
        {
            std::unique_ptr<DepthNode3D> root = buildDepthTree3D(std::move(cs.polys), cs.eps);
            if (!root)
            {
                sortFarToNear3D(cs.items);
                onItems(cs.items);
                return;
            }
            for (const auto &it : cs.items)
                insertDepthItem3D(root.get(), it, cs.eps);
            paintBackToFront3D(root.get(), onPoly, onItems);
        }
    }
}
