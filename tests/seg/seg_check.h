// Test helpers for the segmenters: a brute-force reference segmentation and invariant checks that map the clusters
// back to scan indices.
//
// Windows (docs/reference.md, "CAR_Segmenter", "IA_Segmenter"): CAR at step s compares each point with the s - 1
// previous points (cyclically), IA at step s with the s previous points. The helpers below take the window (how many
// previous points) explicitly; checkCar and checkIa derive it from the step. IA at step s and CAR at step s + 1
// therefore compare the same pairs, and with IA's scaling set to CAR's (s + 1) * 2 pi / N they apply the same
// threshold: checkIa uses that scaling, so that checkAgreement can compare the stream result at step s with the batch
// result at step s + 1.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <map>
#include <numeric>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "rtl/core/VectorND.h"
#include "rtl/seg/CAR_Segmenter.h"
#include "rtl/seg/IA_Segmenter.h"

namespace segcheck
{
    constexpr size_t gap = std::numeric_limits<size_t>::max();

    template<class V>
    bool isGap(const V &p)
    {
        for (int k = 0; k < V::dimensionality(); ++k)
            if (!std::isfinite(p[static_cast<size_t>(k)])) return true;
        return false;
    }

    struct UnionFind
    {
        std::vector<size_t> p;
        explicit UnionFind(size_t n) : p(n) { std::iota(p.begin(), p.end(), size_t(0)); }
        size_t find(size_t x) { while (p[x] != x) x = p[x] = p[p[x]]; return x; }
        void unite(size_t a, size_t b)
        {
            a = find(a);
            b = find(b);
            if (a != b) p[std::max(a, b)] = std::min(a, b);
        }
    };

    //! Calls f(j, i) for every ordered pair of the criterion's window: i the later point, j = i - k (cyclic or not),
    //! k = 1..window.
    template<class F>
    void forEachWindowPair(size_t n, size_t window, bool cyclic, F &&f)
    {
        for (size_t i = 0; i < n; ++i)
            for (size_t k = 1; k <= window; ++k)
            {
                if (cyclic ? k >= n : k > i) break;
                f((i + n - k) % n, i);
            }
    }

    //! Reference partition: label = smallest index of the point's component, `gap` for gaps.
    template<class V>
    std::vector<size_t> referenceLabels(const std::vector<V> &pts, const V &origin, size_t window, typename V::ElementType scaling,
                                        typename V::ElementType lb, typename V::ElementType ub, bool cyclic)
    {
        const size_t n = pts.size();
        UnionFind uf(n);
        forEachWindowPair(n, window, cyclic, [&](size_t j, size_t i) {
            if (!isGap(pts[i]) && !isGap(pts[j]) && rtl::detail::meetsCriterion(pts[j], pts[i], origin, scaling, lb, ub)) uf.unite(i, j);
        });
        std::vector<size_t> l(n);
        for (size_t i = 0; i < n; ++i) l[i] = isGap(pts[i]) ? gap : uf.find(i);
        return l;
    }

    //! Maps points back to their scan index; equal points get their indices in scan order, one per lookup.
    template<class V>
    class IndexOf
    {
    public:
        typedef std::array<typename V::ElementType, V::dimensionality()> Key;
        explicit IndexOf(const std::vector<V> &pts)
        {
            for (size_t i = 0; i < pts.size(); ++i)
                if (!isGap(pts[i])) map_[key(pts[i])].push_back(i);
        }
        size_t operator()(const V &p)
        {
            auto it = map_.find(key(p));
            EXPECT_TRUE(it != map_.end()) << "cluster point not in the scan";
            if (it == map_.end()) return gap;
            auto &next = used_[it->first];
            if (next >= it->second.size()) return gap;   // more copies than in the scan: counted as "not exactly once"
            return it->second[next++];
        }

    private:
        static Key key(const V &p)
        {
            Key k;
            for (size_t d = 0; d < k.size(); ++d) k[d] = p[d];
            return k;
        }
        std::map<Key, std::vector<size_t>> map_;
        std::map<Key, size_t> used_;
    };

    //! Index lists of clusters, checked to cover every non-gap point exactly once (and no gap). Returns labels
    //! (smallest index of the cluster) through `labels`.
    template<class V>
    std::vector<std::vector<size_t>> toIndices(const std::vector<V> &pts, const std::vector<std::vector<V>> &clusters,
                                               std::vector<size_t> &labels, const std::string &what)
    {
        IndexOf<V> index_of(pts);
        std::vector<std::vector<size_t>> idx;
        std::vector<int> seen(pts.size(), 0);
        labels.assign(pts.size(), gap);
        size_t unmapped = 0;
        for (const auto &c : clusters)
        {
            EXPECT_FALSE(c.empty()) << what << ": empty cluster";
            std::vector<size_t> ci;
            for (const auto &p : c)
            {
                const size_t i = index_of(p);
                if (i == gap)
                {
                    ++unmapped;
                    continue;
                }
                ++seen[i];
                ci.push_back(i);
            }
            const size_t lowest = ci.empty() ? gap : *std::min_element(ci.begin(), ci.end());
            for (size_t i : ci) labels[i] = lowest;
            idx.push_back(ci);
        }
        size_t wrong = 0;
        for (size_t i = 0; i < pts.size(); ++i) wrong += (seen[i] != (isGap(pts[i]) ? 0 : 1)) ? 1 : 0;
        EXPECT_EQ(unmapped, 0u) << what << ": cluster points that are not (or no longer) in the scan";
        EXPECT_EQ(wrong, 0u) << what << ": points not in exactly one cluster (or gaps in a cluster)";
        return idx;
    }

    //! Increasing indices, neighbours at most `window` apart (window - 1 indices skipped); with `may_wrap`, one
    //! descent is allowed where the cluster crosses the seam (then the distance is counted cyclically).
    inline void checkOrder(const std::vector<std::vector<size_t>> &clusters, size_t n, size_t window, bool may_wrap,
                           const std::string &what)
    {
        size_t bad = 0;
        for (const auto &c : clusters)
        {
            size_t descents = 0;
            for (size_t k = 1; k < c.size(); ++k)
            {
                const size_t a = c[k - 1], b = c[k];
                if (b > a)
                    bad += (b - a > window) ? 1 : 0;
                else
                {
                    ++descents;
                    bad += (!may_wrap || b + n - a > window) ? 1 : 0;
                }
            }
            bad += descents > 1 ? 1 : 0;
        }
        EXPECT_EQ(bad, 0u) << what << ": cluster order or gap size wrong";
    }

    //! Every point of a cluster of two or more has a partner of its cluster that meets the criterion.
    template<class V>
    void checkPartners(const std::vector<V> &pts, const V &origin, size_t window, typename V::ElementType scaling,
                       typename V::ElementType lb, typename V::ElementType ub, bool cyclic, const std::vector<size_t> &labels,
                       const std::string &what)
    {
        std::vector<size_t> size(pts.size(), 0);
        for (size_t l : labels)
            if (l != gap) ++size[l];
        std::vector<char> has_partner(pts.size(), 0);
        forEachWindowPair(pts.size(), window, cyclic, [&](size_t j, size_t i) {
            if (labels[i] != gap && labels[i] == labels[j] && rtl::detail::meetsCriterion(pts[j], pts[i], origin, scaling, lb, ub))
                has_partner[i] = has_partner[j] = 1;
        });
        size_t lonely = 0;
        for (size_t i = 0; i < pts.size(); ++i) lonely += (labels[i] != gap && size[labels[i]] >= 2 && !has_partner[i]) ? 1 : 0;
        EXPECT_EQ(lonely, 0u) << what << ": points without a partner in their cluster";
    }

    //! Complete merging: no pair meeting the criterion within the window is split.
    template<class V>
    void checkComplete(const std::vector<V> &pts, const V &origin, size_t window, typename V::ElementType scaling,
                       typename V::ElementType lb, typename V::ElementType ub, bool cyclic, const std::vector<size_t> &labels,
                       const std::string &what)
    {
        size_t split = 0;
        forEachWindowPair(pts.size(), window, cyclic, [&](size_t j, size_t i) {
            if (!isGap(pts[i]) && !isGap(pts[j]) && labels[i] != labels[j] &&
                rtl::detail::meetsCriterion(pts[j], pts[i], origin, scaling, lb, ub))
                ++split;
        });
        EXPECT_EQ(split, 0u) << what << ": pairs meeting the criterion in different clusters";
    }

    template<class V>
    std::vector<std::vector<V>> runCar(rtl::CAR_Segmenter<V> &car, const std::vector<V> &pts, const V &origin)
    {
        car.loadData(pts, origin);
        std::vector<std::vector<V>> out;
        const size_t available = car.clustersAvailable();
        while (car.clustersAvailable() > 0) out.push_back(car.grabCluster());
        EXPECT_EQ(out.size(), available);
        EXPECT_TRUE(car.grabCluster().empty());
        return out;
    }

    //! Streams the points, grabbing closed clusters after every point (grab_every = 1), every k-th point, or only at
    //! the end (0); checks after every point that grabbed + alive points are all valid points but the window.
    template<class V>
    std::vector<std::vector<V>> runIa(rtl::IA_Segmenter<V> &ia, const std::vector<V> &pts, const V &origin, size_t step,
                                      size_t grab_every, const std::string &what)
    {
        std::vector<std::vector<V>> out;
        step = std::max<size_t>(step, 1);   // step 0 means 1
        std::vector<size_t> valid_before(pts.size() + 1, 0);
        for (size_t i = 0; i < pts.size(); ++i) valid_before[i + 1] = valid_before[i] + (isGap(pts[i]) ? 0 : 1);
        size_t grabbed = 0, accounting_errors = 0, empty_alive = 0;
        for (size_t i = 0; i < pts.size(); ++i)
        {
            ia.addPoint(pts[i], origin);
            if (grab_every != 0 && (i + 1) % grab_every == 0)
                while (ia.closedClustersAvailable() > 0)
                {
                    out.push_back(ia.grabCluster());
                    grabbed += out.back().size();
                }
            if (grab_every == 1)
            {
                size_t alive = 0;
                for (const auto &kv : ia.aliveClusters())
                {
                    alive += kv.second.size();
                    empty_alive += kv.second.empty() ? 1 : 0;
                }
                EXPECT_EQ(ia.aliveClustersAvailable(), ia.aliveClusters().size());
                // the last `step` points are in the window, everything valid before them is grabbed or alive
                const size_t out_of_window = i + 1 > step ? valid_before[i + 1 - step] : 0;
                accounting_errors += (grabbed + alive != out_of_window) ? 1 : 0;
            }
        }
        EXPECT_EQ(accounting_errors, 0u) << what << ": points stuck or lost while streaming";
        EXPECT_EQ(empty_alive, 0u) << what << ": empty alive cluster";
        ia.flush();
        EXPECT_EQ(ia.aliveClustersAvailable(), 0u) << what << ": alive clusters after flush";
        while (ia.closedClustersAvailable() > 0) out.push_back(ia.grabCluster());
        EXPECT_TRUE(ia.grabCluster().empty());
        return out;
    }

    //! CAR's window at `step`: the step - 1 previous points (step 0 means 1).
    inline size_t carWindow(size_t step) { return step <= 1 ? 0 : step - 1; }

    //! All checks of the batch segmenter on one scan. Returns the labels.
    template<class V>
    std::vector<size_t> checkCar(const std::vector<V> &pts, const V &origin, size_t step, typename V::ElementType lb,
                                 typename V::ElementType ub, const std::string &what)
    {
        rtl::CAR_Segmenter<V> car(step, lb, ub);
        const auto clusters = runCar(car, pts, origin);
        std::vector<size_t> labels;
        const auto idx = toIndices(pts, clusters, labels, what);
        step = std::max<size_t>(step, 1);
        const auto scaling = rtl::detail::circularScaling<typename V::ElementType>(step, pts.size());
        const size_t window = carWindow(step);
        checkOrder(idx, pts.size(), window, true, what);
        checkComplete(pts, origin, window, scaling, lb, ub, true, labels, what);
        checkPartners(pts, origin, window, scaling, lb, ub, true, labels, what);
        EXPECT_EQ(labels, referenceLabels(pts, origin, window, scaling, lb, ub, true)) << what << ": differs from the reference";
        // handed out by smallest index
        std::vector<size_t> lowest;
        for (const auto &c : idx) lowest.push_back(*std::min_element(c.begin(), c.end()));
        EXPECT_TRUE(std::is_sorted(lowest.begin(), lowest.end())) << what << ": clusters not in index order";
        return labels;
    }

    //! All checks of the stream segmenter at `step` (window: the step previous points), fed with the scaling of CAR at
    //! step + 1, (step + 1) * 2 pi / N, the batch segmenter with the same window. Returns the labels.
    template<class V>
    std::vector<size_t> checkIa(const std::vector<V> &pts, const V &origin, size_t step, typename V::ElementType lb,
                                typename V::ElementType ub, size_t grab_every, const std::string &what)
    {
        step = std::max<size_t>(step, 1);
        const auto scaling = rtl::detail::circularScaling<typename V::ElementType>(step + 1, pts.size());
        rtl::IA_Segmenter<V> ia(step, lb, ub, scaling);
        const auto clusters = runIa(ia, pts, origin, step, grab_every, what);
        std::vector<size_t> labels;
        const auto idx = toIndices(pts, clusters, labels, what);
        checkOrder(idx, pts.size(), step, false, what);
        checkComplete(pts, origin, step, scaling, lb, ub, false, labels, what);
        checkPartners(pts, origin, step, scaling, lb, ub, false, labels, what);
        EXPECT_EQ(labels, referenceLabels(pts, origin, step, scaling, lb, ub, false)) << what << ": differs from the reference";
        // stream order: clusters close when their last point leaves the window
        std::vector<size_t> last;
        for (const auto &c : idx) last.push_back(c.back());
        EXPECT_TRUE(std::is_sorted(last.begin(), last.end())) << what << ": clusters not in stream order";
        return labels;
    }

    //! The batch result at step s + 1 (car_labels) equals the stream result at step s (ia_labels, from checkIa:
    //! scaling (s + 1) * 2 pi / N) once the seam pairs of the common window of s points are linked as well.
    template<class V>
    void checkAgreement(const std::vector<V> &pts, const V &origin, size_t ia_step, typename V::ElementType lb, typename V::ElementType ub,
                        const std::vector<size_t> &car_labels, const std::vector<size_t> &ia_labels, const std::string &what)
    {
        const size_t n = pts.size();
        ia_step = std::max<size_t>(ia_step, 1);
        const auto scaling = rtl::detail::circularScaling<typename V::ElementType>(ia_step + 1, n);
        UnionFind uf(n);
        for (size_t i = 0; i < n; ++i)
            if (ia_labels[i] != gap) uf.unite(i, ia_labels[i]);
        forEachWindowPair(n, ia_step, true, [&](size_t j, size_t i) {
            if (j > i && !isGap(pts[i]) && !isGap(pts[j]) && rtl::detail::meetsCriterion(pts[j], pts[i], origin, scaling, lb, ub))
                uf.unite(i, j);
        });
        std::vector<size_t> joined(n);
        for (size_t i = 0; i < n; ++i) joined[i] = ia_labels[i] == gap ? gap : uf.find(i);
        EXPECT_EQ(joined, car_labels) << what << ": stream and batch segmenters disagree";
    }
}
