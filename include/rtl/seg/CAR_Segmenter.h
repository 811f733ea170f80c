// CAR_Segmenter (Cyclic, Adaptive, Retroactive): batch segmentation of one closed, ordered scan of a rotating
// LiDAR into clusters of nearby points.
//
// loadData(points, origin) treats the scan as a closed loop of N points. Each point is compared with up to
// step - 1 preceding points (RTL's window: step 1 compares none, step 2 the previous point), cyclically across the
// seam (N - 1 -> 0): point i joins an earlier point j when 1 <= i - j <= step - 1 (indices modulo N) and
// |p_i - p_j| <= t_i, where
//     t_i = clamp((step * 2 pi / N) * |p_i - origin|, lower_bound, upper_bound)
// (seg/ProximityCriterion.h; the threshold scales with `step`, the window holds step - 1 points). The seam pass
// compares the first step points with the last ones: point i < step with the points N - (step - 1 - i) .. N - 1.
// Clusters are the connected components of that relation: merging is complete, so no two points meeting the
// criterion end up in different clusters. Points with a NaN (or infinite) coordinate are gaps and belong to no
// cluster; they still occupy their index. Each cluster lists its points in increasing scan order, with at most
// step - 2 indices skipped between consecutive points; a cluster that wraps the seam (its indices in increasing
// order skip more than step - 2 once) starts with its end-of-scan part, after that skip. A cluster that covers
// every index without such a skip is listed in increasing order, even if it was joined across the seam. grabCluster() hands clusters out in the order of their smallest index. Step 1 gives one cluster per valid
// point.
//
// Tracing (core/Trace.h): CAR_Segmenter<Vector, Observer> with an observer set by setObserver() reports every step
// of loadData as the events of seg/SegTrace.h (use rtl::CarTraceLog to record them). A traced loadData runs the
// general window algorithm for every step (same clusters); with the default rtl::NoTrace nothing is reported and
// the code is the untraced code.
//
// Bad input: step 0 is treated as 1; an empty scan gives no cluster; loadData throws std::invalid_argument unless
// 0 <= lower_bound <= upper_bound (upper may be +inf) and the origin is finite. Defaults: step 2 (each point compared
// with the previous one, so that a default segmenter links consecutive points, as before the window fix; RTL does
// not document its default), bounds [0, +inf).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <list>
#include <map>
#include <vector>

#include "rtl/core/Trace.h"
#include "rtl/core/VectorND.h"
#include "rtl/seg/ProximityCriterion.h"
#include "rtl/seg/SegTrace.h"

namespace rtl
{
    template<class Vector, class Observer = NoTrace>
    class CAR_Segmenter
    {
    public:
        typedef typename Vector::ElementType ElementType;
        typedef Vector VectorType;
        typedef Observer ObserverType;

        CAR_Segmenter() = default;
        CAR_Segmenter(size_t step, ElementType lower_bound, ElementType upper_bound)
            : step_(step == 0 ? 1 : step), lower_(lower_bound), upper_(upper_bound) {}
        // Copies are deep (the segmenter holds no iterators or pointers into itself). Moves are noexcept and O(1);
        // a moved-from segmenter has no clusters left and can load a new scan.
        CAR_Segmenter(const CAR_Segmenter &) = default;
        CAR_Segmenter(CAR_Segmenter &&) noexcept = default;
        CAR_Segmenter &operator=(const CAR_Segmenter &) = default;
        CAR_Segmenter &operator=(CAR_Segmenter &&) noexcept = default;
        ~CAR_Segmenter() = default;

        void setStepSize(size_t step) { step_ = step == 0 ? 1 : step; }
        void setLowerBound(ElementType lb) { lower_ = lb; }
        void setUpperBound(ElementType ub) { upper_ = ub; }
        //! The observer that receives the steps of the next loadData calls (nullptr: none); not owned.
        void setObserver(Observer *observer) { observer_ = observer; }

        //! Reserves the work buffers for scans of up to max_size points. Optional: larger scans grow them as needed.
        void setMaxSize(size_t max_size)
        {
            flags_.reserve(max_size);
            if (step_ > 2)
            {
                tsq_.reserve(max_size);
                parent_.reserve(max_size);
            }
        }

        [[nodiscard]] size_t clustersAvailable() const { return next_ < clusters_.size() ? clusters_.size() - next_ : 0; }

        //! Segments a closed scan, replacing any clusters not grabbed yet.
        void loadData(const std::vector<VectorType> &points, const VectorType &origin = VectorType::zeros())
        {
            seg_detail::checkParameters<ElementType>("CAR_Segmenter::loadData", lower_, upper_,
                                                     seg_detail::isFinite<D>(origin.data().data()));
            clusters_.clear();
            next_ = 0;
            if (points.empty()) return;
            const ElementType scaling = seg_detail::circularScaling<ElementType>(step_, points.size());
            if constexpr (traced)
                if (observer_)
                {
                    (*observer_)(car_trace::Scan{points.size(), step_, step_ - 1, static_cast<double>(scaling),
                                                 static_cast<double>(lower_), static_cast<double>(upper_)});
                    segmentWindow(points, origin, scaling);
                    return;
                }
            if (step_ == 1) segmentAlone(points);
            else if (step_ == 2) segmentNeighbours(points, origin, scaling);
            else segmentRuns(points, origin, scaling);
        }

        //! Removes and returns the next cluster (never empty); an empty vector when none is left.
        std::vector<VectorType> grabCluster()
        {
            if (next_ >= clusters_.size()) return {};
            std::vector<VectorType> c = std::move(clusters_[next_++]);
            if (next_ == clusters_.size())
            {
                clusters_.clear();
                next_ = 0;
            }
            return c;
        }

    private:
        static constexpr int D = VectorType::dimensionality();
        static constexpr size_t none = std::numeric_limits<size_t>::max();
        static constexpr bool traced = Observer::enabled;
        static const ElementType *ptr(const VectorType &v) { return v.data().data(); }

        // step 1: the window is empty, every valid point is a cluster of its own.
        void segmentAlone(const std::vector<VectorType> &pts)
        {
            for (const VectorType &p : pts)
                if (seg_detail::isFinite<D>(ptr(p))) clusters_.emplace_back(1, p);
        }

        // flags_[i]: bit 0 = point i is valid, bit 1 = it meets the criterion with point i - 1 (i >= 1).
        void neighbourFlags(const std::vector<VectorType> &pts, const VectorType &origin, const seg_detail::SquaredThreshold<ElementType> &thr)
        {
            const size_t n = pts.size();
            ElementType o[D];
            for (int k = 0; k < D; ++k) o[k] = origin.data()[k];
            flags_.resize(n);
            unsigned char *f = flags_.data();
            f[0] = seg_detail::isFinite<D>(ptr(pts[0])) ? 1 : 0;
            // Branch-free loops, so that the compiler vectorises them. 2D points are loaded as they are; other
            // dimensions are transposed block-wise to one array per coordinate first (the compiler does not
            // vectorise loads with a 3-element stride).
            if constexpr (D == 2)
            {
                const VectorType *v = pts.data();
                for (size_t i = 1; i < n; ++i)
                {
                    ElementType rsq = 0, dsq = 0;
                    bool valid = true, valid_prev = true;
                    for (int k = 0; k < D; ++k)
                    {
                        const ElementType a = v[i][static_cast<size_t>(k)], b = v[i - 1][static_cast<size_t>(k)];
                        rsq += (a - o[k]) * (a - o[k]);
                        dsq += (a - b) * (a - b);
                        valid &= (a - a) == ElementType(0);
                        valid_prev &= (b - b) == ElementType(0);
                    }
                    const bool link = valid & valid_prev & (dsq <= thr(rsq));
                    f[i] = static_cast<unsigned char>(static_cast<unsigned>(valid) | (static_cast<unsigned>(link) << 1));
                }
            }
            else
            {
                constexpr size_t block = 256;
                ElementType c[D][block + 1];
                for (size_t i0 = 1; i0 < n; i0 += block)
                {
                    const size_t m = std::min(block, n - i0);
                    for (size_t j = 0; j <= m; ++j)
                        for (int k = 0; k < D; ++k) c[k][j] = pts[i0 - 1 + j].data()[k];
                    unsigned char *fb = f + i0;
                    for (size_t j = 0; j < m; ++j)
                    {
                        ElementType rsq = 0, dsq = 0;
                        bool valid = true, valid_prev = true;
                        for (int k = 0; k < D; ++k)
                        {
                            const ElementType a = c[k][j + 1], b = c[k][j];
                            rsq += (a - o[k]) * (a - o[k]);
                            dsq += (a - b) * (a - b);
                            valid &= (a - a) == ElementType(0);
                            valid_prev &= (b - b) == ElementType(0);
                        }
                        const bool link = valid & valid_prev & (dsq <= thr(rsq));
                        fb[j] = static_cast<unsigned char>(static_cast<unsigned>(valid) | (static_cast<unsigned>(link) << 1));
                    }
                }
            }
        }

        //! The end of the run of predecessor-linked points that starts at b: the first i > b without bit 1.
        static size_t runEnd(const unsigned char *f, size_t b, size_t n)
        {
            constexpr std::uint64_t all_linked = 0x0202020202020202ull;
            size_t i = b + 1;
            for (std::uint64_t w; i + 8 <= n; i += 8)
            {
                std::memcpy(&w, f + i, 8);
                if ((w & all_linked) != all_linked) break;
            }
            while (i < n && (f[i] & 2u)) ++i;
            return i;
        }

        // step 2 (the previous point): every cluster is a run of consecutive points, except one that may wrap the
        // seam. One vectorisable pass marks which points are valid (bit 0) and linked to their predecessor (bit 1);
        // runs are then copied out whole.
        void segmentNeighbours(const std::vector<VectorType> &pts, const VectorType &origin, ElementType scaling)
        {
            const size_t n = pts.size();
            neighbourFlags(pts, origin, seg_detail::SquaredThreshold<ElementType>(scaling, lower_, upper_));
            const unsigned char *f = flags_.data();
            size_t i = 0;
            while (i < n)
            {
                if (!(f[i] & 1u))
                {
                    ++i;
                    continue;
                }
                const size_t b = i;
                i = runEnd(f, b, n);
                clusters_.emplace_back(pts.begin() + static_cast<std::ptrdiff_t>(b), pts.begin() + static_cast<std::ptrdiff_t>(i));
            }

            // Seam: point 0 follows point n - 1. With two or more clusters, point 0 opens the first and n - 1 closes
            // the last; the joined cluster keeps the first place (smallest index). It starts with its end part only
            // if gaps separate the two parts (an index skipped): two adjacent runs that cover every index stay in
            // increasing order, as the general step lists them.
            if (n >= 2 && clusters_.size() >= 2 && (f[0] & 1u) && (f[n - 1] & 1u) &&
                closeTo(pts[n - 1], pts[0], origin, scaling))
            {
                std::vector<VectorType> &first = clusters_.front(), &last = clusters_.back();
                if (first.size() + last.size() == n) first.insert(first.end(), last.begin(), last.end());
                else
                {
                    last.insert(last.end(), first.begin(), first.end());
                    first = std::move(last);
                }
                clusters_.pop_back();
            }
        }

        // General step: union-find over point indices, the root of a component being its smallest index; each point
        // looks s = step - 1 places back. Also every traced run (any step): the reports compile away untraced.
        void segmentWindow(const std::vector<VectorType> &pts, const VectorType &origin, ElementType scaling)
        {
            const size_t n = pts.size(), s = step_ - 1;
            const ElementType *o = ptr(origin);
            const seg_detail::SquaredThreshold<ElementType> thr(scaling, lower_, upper_);
            tsq_.resize(n);
            parent_.resize(n);
            for (size_t i = 0; i < n; ++i)
            {
                const ElementType *p = ptr(pts[i]);
                tsq_[i] = thr(seg_detail::squaredDistance<D>(p, o));
                parent_[i] = seg_detail::isFinite<D>(p) ? i : none;
            }

            for (size_t i = 0; i < n; ++i)
            {
                if (parent_[i] == none)
                {
                    if constexpr (traced) report(car_trace::Gap{i});
                    continue;
                }
                const ElementType *p = ptr(pts[i]);
                if constexpr (traced)
                    if (observer_)
                    {
                        const double range = std::sqrt(static_cast<double>(seg_detail::squaredDistance<D>(p, o)));
                        (*observer_)(car_trace::Threshold{i, range, std::abs(static_cast<double>(scaling)) * range,
                                                          std::sqrt(static_cast<double>(tsq_[i]))});
                    }
                size_t root = none;
                for (size_t k = 1, kmax = std::min(s, i); k <= kmax; ++k)
                {
                    const size_t j = i - k, pj = parent_[j];
                    if constexpr (traced)
                        if (observer_ && pj != none) reportComparison<car_trace::Compare>(i, j, seg_detail::squaredDistance<D>(p, ptr(pts[j])), tsq_[i]);
                    // pj == root: j is already in i's cluster (the usual case inside a cluster), no need to look
                    if (pj == none || pj == root || !(seg_detail::squaredDistance<D>(p, ptr(pts[j])) <= tsq_[i])) continue;
                    const size_t r = find(j);
                    if (root == none)
                    {
                        root = r;
                        if constexpr (traced) report(car_trace::Link{i, j, r});
                    }
                    else if (r < root)
                    {
                        if constexpr (traced) report(car_trace::Merge{i, j, root, r});
                        parent_[root] = r;
                        root = r;
                    }
                    else if (r > root)
                    {
                        if constexpr (traced) report(car_trace::Merge{i, j, r, root});
                        parent_[r] = root;
                    }
                }
                if constexpr (traced)
                    if (root == none) report(car_trace::Start{i});
                parent_[i] = root == none ? i : root;
            }

            finishWindow(pts);
        }

        // Steps >= 3, untraced: the components of segmentWindow, without comparing points of one run. A run is a
        // maximal sequence of valid points each linked to its predecessor (one vectorised pass, neighbourFlags); its
        // points are one component, so only the links of its first step - 1 points that reach back past its start
        // can join it to other runs. Union-find works on runs (root: the smallest run index), and clusters are
        // copied out run by run. A scan of long runs costs about one distance per point, whatever the step.
        void segmentRuns(const std::vector<VectorType> &pts, const VectorType &origin, ElementType scaling)
        {
            const size_t n = pts.size(), s = step_ - 1;
            const seg_detail::SquaredThreshold<ElementType> thr(scaling, lower_, upper_);
            const ElementType *o = ptr(origin);
            neighbourFlags(pts, origin, thr);
            const unsigned char *f = flags_.data();
            run_begin_.clear();
            run_end_.clear();
            parent_.clear();
            for (size_t i = 0; i < n;)
            {
                if (!(f[i] & 1u))
                {
                    ++i;
                    continue;
                }
                const size_t b = i, r = run_begin_.size();
                i = runEnd(f, b, n);
                run_begin_.push_back(b);
                run_end_.push_back(i);
                parent_.push_back(r);
                // point q compares with q - k, k = 1..s; those with k <= q - b lie in this run
                for (size_t q = b; q < i && q - b < s; ++q)
                {
                    const ElementType *p = ptr(pts[q]);
                    const ElementType tq = thr(seg_detail::squaredDistance<D>(p, o));
                    size_t rj = r;   // the run holding j, found walking back (j decreases)
                    for (size_t k = q - b + 1; k <= s && k <= q; ++k)
                    {
                        const size_t j = q - k;
                        if (!(f[j] & 1u) || !(seg_detail::squaredDistance<D>(p, ptr(pts[j])) <= tq)) continue;
                        while (run_begin_[rj] > j) --rj;
                        unite(r, rj);
                    }
                }
            }
            const size_t runs = run_begin_.size();
            if (runs == 0) return;

            // Seam: point i < s (the later point) with j = i + n - k, k = i + 1..s.
            for (size_t i = 0, ri = 0; i < std::min(s, n); ++i)
            {
                if (!(f[i] & 1u)) continue;
                while (run_end_[ri] <= i) ++ri;
                const ElementType *p = ptr(pts[i]);
                const ElementType tq = thr(seg_detail::squaredDistance<D>(p, o));
                size_t rj = runs - 1;
                for (size_t k = i + 1; k <= s; ++k)
                {
                    const size_t j = i + n - k;
                    if (j <= i) break;
                    if (!(f[j] & 1u) || !(seg_detail::squaredDistance<D>(p, ptr(pts[j])) <= tq)) continue;
                    while (run_begin_[rj] > j) --rj;
                    unite(ri, rj);
                }
            }

            // Output: a cluster per root run, in run order, sized first. A skip of more than step - 2 indices between
            // two runs of one cluster can only come from the seam: the cluster is rotated there.
            slot_.resize(runs);
            last_.clear();
            rotate_at_.clear();
            std::vector<size_t> &size = cluster_size_;   // points per cluster
            size.clear();
            for (size_t r = 0; r < runs; ++r)
            {
                const size_t root = find(r);
                if (root == r)
                {
                    slot_[r] = size.size();
                    size.push_back(0);
                }
                size[slot_[root]] += run_end_[r] - run_begin_[r];
            }
            const size_t first = clusters_.size();
            clusters_.resize(first + size.size());
            last_.assign(size.size(), 0);
            rotate_at_.assign(size.size(), 0);
            for (size_t c = 0; c < size.size(); ++c) clusters_[first + c].reserve(size[c]);
            for (size_t r = 0; r < runs; ++r)
            {
                const size_t c = slot_[find(r)], b = run_begin_[r];
                std::vector<VectorType> &cl = clusters_[first + c];
                if (!cl.empty() && b - last_[c] > s) rotate_at_[c] = cl.size();
                cl.insert(cl.end(), pts.begin() + static_cast<std::ptrdiff_t>(b), pts.begin() + static_cast<std::ptrdiff_t>(run_end_[r]));
                last_[c] = run_end_[r] - 1;
            }
            for (size_t c = 0; c < size.size(); ++c)
                if (rotate_at_[c] > 0)
                {
                    std::vector<VectorType> &cl = clusters_[first + c];
                    std::rotate(cl.begin(), cl.begin() + static_cast<std::ptrdiff_t>(rotate_at_[c]), cl.end());
                }
        }

        // The seam and the output of segmentWindow, from parent_ (none for gaps) and, for the
        // first step - 1 points, tsq_.
        void finishWindow(const std::vector<VectorType> &pts)
        {
            const size_t n = pts.size(), s = step_ - 1;
            // Seam: pairs (j, i) with j near the end, i near the beginning and i + n - j <= step - 1; i is the later
            // point. Only the first step - 1 points have partners across the seam.
            for (size_t i = 0; i < std::min(s, n); ++i)
            {
                if (parent_[i] == none) continue;
                for (size_t k = i + 1; k <= s; ++k)
                {
                    const size_t j = i + n - k;
                    if (j <= i) break;
                    if constexpr (traced)
                        if (observer_ && parent_[j] != none)
                        {
                            const ElementType dsq = seg_detail::squaredDistance<D>(ptr(pts[i]), ptr(pts[j]));
                            reportComparison<car_trace::Seam>(i, j, dsq, tsq_[i]);
                            const size_t a = find(i), b = find(j);
                            if (dsq <= tsq_[i] && a != b) (*observer_)(car_trace::Merge{i, j, std::max(a, b), std::min(a, b)});
                        }
                    if (parent_[j] != none && seg_detail::squaredDistance<D>(ptr(pts[i]), ptr(pts[j])) <= tsq_[i]) unite(i, j);
                }
            }

            // Copy runs of equal root into their cluster. A gap of more than step - 2 indices inside a cluster can
            // only come from the seam: the cluster is rotated there, so that it starts with its end-of-scan part.
            slot_.resize(n);
            last_.clear();
            rotate_at_.clear();
            size_t i = 0;
            while (i < n)
            {
                if (parent_[i] == none)
                {
                    ++i;
                    continue;
                }
                const size_t r = find(i), b = i++;
                while (i < n && parent_[i] != none && (parent_[i] == r || find(i) == r)) ++i;
                size_t c;
                if (r == b)
                {
                    c = clusters_.size();
                    slot_[r] = c;
                    clusters_.emplace_back();
                    last_.push_back(b);
                    rotate_at_.push_back(0);
                    if constexpr (traced) trace_first_.push_back(b);
                }
                else
                {
                    c = slot_[r];
                    if (b - last_[c] > s)
                    {
                        rotate_at_[c] = clusters_[c].size();
                        if constexpr (traced) trace_first_[c] = b;
                    }
                }
                clusters_[c].insert(clusters_[c].end(), pts.begin() + static_cast<std::ptrdiff_t>(b), pts.begin() + static_cast<std::ptrdiff_t>(i));
                last_[c] = i - 1;
            }
            for (size_t c = 0; c < clusters_.size(); ++c)
                if (rotate_at_[c] > 0)
                    std::rotate(clusters_[c].begin(), clusters_[c].begin() + static_cast<std::ptrdiff_t>(rotate_at_[c]), clusters_[c].end());
            if constexpr (traced)
                if (observer_)
                {
                    size_t label = 0;
                    for (size_t c = 0; c < clusters_.size(); ++c, ++label)
                    {
                        while (parent_[label] != label) ++label;   // cluster c's label: the c-th root in scan order
                        (*observer_)(car_trace::Cluster{c, label, trace_first_[c], clusters_[c].size()});
                    }
                    trace_first_.clear();
                }
        }

        template<class Event>
        void report(const Event &e)
        {
            if (observer_) (*observer_)(e);
        }

        template<class Event>
        void reportComparison(size_t i, size_t j, ElementType dsq, ElementType tsq)
        {
            double distance, threshold;
            const bool linked = dsq <= tsq;
            seg_detail::traceDistances(static_cast<double>(dsq), static_cast<double>(tsq), linked, distance, threshold);
            (*observer_)(Event{i, j, distance, threshold, linked});
        }

        bool closeTo(const VectorType &earlier, const VectorType &later, const VectorType &origin, ElementType scaling) const
        {
            return seg_detail::meetsCriterion(earlier, later, origin, scaling, lower_, upper_);
        }

        size_t find(size_t x)
        {
            while (parent_[x] != x)
            {
                parent_[x] = parent_[parent_[x]];
                x = parent_[x];
            }
            return x;
        }

        void unite(size_t a, size_t b)
        {
            a = find(a);
            b = find(b);
            if (a < b) parent_[b] = a;
            else if (b < a) parent_[a] = b;
        }

        size_t step_ = 2;
        ElementType lower_ = ElementType(0), upper_ = std::numeric_limits<ElementType>::infinity();

        std::vector<std::vector<VectorType>> clusters_;
        size_t next_ = 0;

        // work buffers, kept between calls
        std::vector<unsigned char> flags_;
        std::vector<ElementType> tsq_;
        std::vector<size_t> parent_, slot_, last_, rotate_at_;
        std::vector<size_t> trace_first_;                     // traced runs: the scan index each cluster starts with
        std::vector<size_t> run_begin_, run_end_, cluster_size_;   // segmentRuns: runs [begin, end), points per cluster
        Observer *observer_ = nullptr;
    };
}
