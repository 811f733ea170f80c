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
// every index without such a skip is listed in increasing order, even if it was joined across the seam.
// grabCluster() hands clusters out in the order of their smallest index. Step 1 gives one cluster per valid point.
// loadData keeps a copy of the scan (reused by the next call); grabCluster copies each cluster out of it, so that a
// caller that drops each cluster before grabbing the next reuses one block of memory.
//
// Complexity: loadData makes at most N * (step - 1) distance comparisons plus near-linear union-find work; on
// real scans, made of long runs of neighbouring points, it costs about one distance per point whatever the step
// (only a run's first step - 1 points can reach back past its start). Memory O(N), reused between calls.
// grabCluster is O(cluster size). Invariant: the clusters partition the valid points of the last scan, and no two
// points that meet the criterion within the window lie in different clusters (the published merge was incomplete;
// docs/reference.md, "Segmentation defects fixed here").
//
// Tracing (core/Trace.h): CAR_Segmenter<Vector, Observer> with an observer set by setObserver() reports every step
// of loadData as the events of seg/SegTrace.h (use rtl::CarTraceLog to record them). A traced loadData runs the
// general window algorithm for every step (same clusters); with the default rtl::NoTrace nothing is reported and
// the code is the untraced code.
//
// Bad input: step 0 is treated as 1; an empty scan gives no cluster; loadData throws std::invalid_argument unless
// 0 <= lower_bound <= upper_bound (upper may be +inf) and the origin is finite. Defaults: step 2 (each point compared
// with the previous one, so that a default segmenter links consecutive points; RTL does not document its default),
// bounds [0, +inf).
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
            store_.reserve(max_size);
            if (step_ > 2)
            {
                tsq_.reserve(max_size);
                parent_.reserve(max_size);
            }
        }

        [[nodiscard]] size_t clustersAvailable() const { return next_ < out_.size() ? out_.size() - next_ : 0; }

        //! Segments a closed scan, replacing any clusters not grabbed yet.
        void loadData(const std::vector<VectorType> &points, const VectorType &origin = VectorType::zeros())
        {
            detail::checkParameters<ElementType>("CAR_Segmenter::loadData", lower_, upper_,
                                                     detail::isFinite<D>(origin.data().data()));
            out_.clear();
            pieces_.clear();
            next_ = 0;
            if (points.empty()) return;
            // the clusters are copied out of this copy when grabbed: a caller that frees each cluster before grabbing
            // the next reuses one block of memory, where clusters allocated up front would be fresh pages each scan.
            // 2D scans at step >= 2 fill it in the pass that reads the points anyway (neighbourFlags).
            if (D != 2 || step_ == 1 || traced) store_.assign(points.begin(), points.end());
            else store_.resize(points.size());
            const ElementType scaling = detail::circularScaling<ElementType>(step_, points.size());
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
            if (next_ >= out_.size()) return {};
            const Cluster &cl = out_[next_++];
            std::vector<VectorType> c;
            if (cl.piece_end - cl.piece_begin == 1)
                c.assign(store_.begin() + static_cast<std::ptrdiff_t>(pieces_[cl.piece_begin].begin),
                         store_.begin() + static_cast<std::ptrdiff_t>(pieces_[cl.piece_begin].end));
            else
            {
                c.reserve(cl.points);
                for (size_t k = cl.piece_begin; k < cl.piece_end; ++k)
                    c.insert(c.end(), store_.begin() + static_cast<std::ptrdiff_t>(pieces_[k].begin),
                             store_.begin() + static_cast<std::ptrdiff_t>(pieces_[k].end));
            }
            if (next_ == out_.size())
            {
                out_.clear();
                pieces_.clear();
                next_ = 0;
            }
            return c;
        }

        //! Removes the next cluster as grabCluster() does, but gives its points as scan indices instead of copies:
        //! appends the half-open index ranges [begin, end) of its points to `ranges` (two numbers a range, in
        //! grabCluster()'s order, so a cluster that wraps the seam starts with its end-of-scan range) and returns
        //! the cluster's number of points; 0, appending nothing, when no cluster is left. An addition to RTL's API
        //! for callers that want labels or indices rather than points (no per-cluster allocation or point copy).
        size_t grabClusterRanges(std::vector<size_t> &ranges)
        {
            if (next_ >= out_.size()) return 0;
            const Cluster &cl = out_[next_++];
            const size_t points = cl.points;
            for (size_t k = cl.piece_begin; k < cl.piece_end; ++k)
                ranges.insert(ranges.end(), {pieces_[k].begin, pieces_[k].end});
            if (next_ == out_.size())
            {
                out_.clear();
                pieces_.clear();
                next_ = 0;
            }
            return points;
        }

    private:
        static constexpr int D = VectorType::dimensionality();
        static constexpr size_t none = std::numeric_limits<size_t>::max();
        static constexpr bool traced = Observer::enabled;
        static const ElementType *ptr(const VectorType &v) { return v.data().data(); }

        // step 1: the window is empty, every valid point is a cluster of its own.
        void segmentAlone(const std::vector<VectorType> &pts)
        {
            for (size_t i = 0; i < pts.size(); ++i)
                if (detail::isFinite<D>(ptr(pts[i])))
                {
                    out_.push_back(Cluster{pieces_.size(), pieces_.size() + 1, 1});
                    pieces_.push_back(Piece{i, i + 1});
                }
        }

        // flags_[i]: bit 0 = point i is valid, bit 1 = it meets the criterion with point i - 1 (i >= 1).
        void neighbourFlags(const std::vector<VectorType> &pts, const VectorType &origin, const detail::SquaredThreshold<ElementType> &thr)
        {
            // With a finite squared upper bound, a pair with a non-finite coordinate never links, without the
            // validity tests: that coordinate's difference is NaN or infinite, so the squared distance is NaN or
            // +inf, and no threshold (at most upper^2, or NaN) admits it. Only the point's own test (bit 0) is left.
            if (thr.upper_sq <= std::numeric_limits<ElementType>::max())
                neighbourFlagPass<false>(pts, origin, thr);
            else
                neighbourFlagPass<true>(pts, origin, thr);
        }

        template<bool CheckPrevious>
        void neighbourFlagPass(const std::vector<VectorType> &pts, const VectorType &origin, const detail::SquaredThreshold<ElementType> &thr)
        {
            const size_t n = pts.size();
            ElementType o[D];
            for (int k = 0; k < D; ++k) o[k] = origin.data()[k];
            flags_.resize(n);
            unsigned char *f = flags_.data();
            f[0] = detail::isFinite<D>(ptr(pts[0])) ? 1 : 0;
            // Branch-free loops, so that the compiler vectorises them. 2D points are loaded as they are; other
            // dimensions are transposed block-wise to one array per coordinate first (the compiler does not
            // vectorise loads with a 3-element stride).
            if constexpr (D == 2)
            {
                const VectorType *v = pts.data();
                VectorType *st = store_.data();
                if (!traced) st[0] = v[0];
                size_t i = 1;
#if defined(__GNUC__)
                // Double points, two per step on vector lanes (de-interleaved by shuffles): the same operations per
                // point as the loop below, in the same order (rsq and dsq are (0 + t0) + t1 = t0 + t1), so the same
                // flags. Written out because GCC and clang turn the scalar loop into per-point (x, y) vectors with
                // horizontal sums instead, which is slower (docs/seg.md, "CAR neighbour flags on vector lanes").
                // Both flag bytes come from one mask vector (two lane reads, not four).
                if constexpr (std::is_same_v<ElementType, double> && sizeof(VectorType) == 2 * sizeof(double))
                {
                    typedef double V __attribute__((vector_size(16)));
                    typedef long long M __attribute__((vector_size(16)));
                    const double *in = ptr(v[0]);
                    const V o0 = V{} + o[0], o1 = V{} + o[1];
                    const V s2 = V{} + thr.scaling_sq, l2 = V{} + thr.lower_sq, u2 = V{} + thr.upper_sq;
                    for (; i + 2 <= n; i += 2)
                    {
                        V pa, pb, qa, qb;   // points i, i + 1 and i - 1, i
                        std::memcpy(&pa, in + 2 * i, sizeof(V));
                        std::memcpy(&pb, in + 2 * i + 2, sizeof(V));
                        std::memcpy(&qa, in + 2 * i - 2, sizeof(V));
                        qb = pa;
#if defined(__clang__)
                        const V ax = __builtin_shufflevector(pa, pb, 0, 2), ay = __builtin_shufflevector(pa, pb, 1, 3);
                        const V bx = __builtin_shufflevector(qa, qb, 0, 2), by = __builtin_shufflevector(qa, qb, 1, 3);
#else
                        const V ax = __builtin_shuffle(pa, pb, M{0, 2}), ay = __builtin_shuffle(pa, pb, M{1, 3});
                        const V bx = __builtin_shuffle(qa, qb, M{0, 2}), by = __builtin_shuffle(qa, qb, M{1, 3});
#endif
                        if (!traced)
                        {
                            std::memcpy(static_cast<void *>(st + i), &pa, sizeof(V));
                            std::memcpy(static_cast<void *>(st + i + 1), &pb, sizeof(V));
                        }
                        const V rsq = (ax - o0) * (ax - o0) + (ay - o1) * (ay - o1);
                        const V dsq = (ax - bx) * (ax - bx) + (ay - by) * (ay - by);
                        V t = s2 * rsq;
                        t = t < l2 ? l2 : t;
                        t = t > u2 ? u2 : t;
                        const M own = ((ax - ax) == V{}) & ((ay - ay) == V{});
                        M link = dsq <= t;
                        if constexpr (CheckPrevious) link &= own & ((bx - bx) == V{}) & ((by - by) == V{});
                        const M fl = (own & 1) | ((link & 1) << 1);
                        f[i] = static_cast<unsigned char>(fl[0]);
                        f[i + 1] = static_cast<unsigned char>(fl[1]);
                    }
                }
#endif
                for (; i < n; ++i)
                {
                    if (!traced) st[i] = v[i];
                    ElementType rsq = 0, dsq = 0;
                    bool valid = true, valid_prev = true;
                    for (int k = 0; k < D; ++k)
                    {
                        const ElementType a = v[i][static_cast<size_t>(k)], b = v[i - 1][static_cast<size_t>(k)];
                        rsq += (a - o[k]) * (a - o[k]);
                        dsq += (a - b) * (a - b);
                        valid &= (a - a) == ElementType(0);
                        if constexpr (CheckPrevious) valid_prev &= (b - b) == ElementType(0);
                    }
                    const bool link = (!CheckPrevious || (valid & valid_prev)) & (dsq <= thr(rsq));
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
                            if constexpr (CheckPrevious) valid_prev &= (b - b) == ElementType(0);
                        }
                        const bool link = (!CheckPrevious || (valid & valid_prev)) & (dsq <= thr(rsq));
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
            neighbourFlags(pts, origin, detail::SquaredThreshold<ElementType>(scaling, lower_, upper_));
            const unsigned char *f = flags_.data();
            run_begin_.clear();
            run_end_.clear();
            run_slot_.clear();
            for (size_t i = 0; i < n;)
            {
                if (!(f[i] & 1u))
                {
                    ++i;
                    continue;
                }
                const size_t b = i;
                i = runEnd(f, b, n);
                run_slot_.push_back(run_begin_.size());
                run_begin_.push_back(b);
                run_end_.push_back(i);
            }
            size_t clusters = run_begin_.size();

            // Seam: point 0 follows point n - 1. With two or more clusters, point 0 opens the first and n - 1 closes
            // the last; the joined cluster keeps the first place (smallest index). emitClusters starts it with its
            // end part only if an index is skipped between the two: two adjacent runs that cover every index stay in
            // increasing order, as the general step lists them.
            if (n >= 2 && clusters >= 2 && (f[0] & 1u) && (f[n - 1] & 1u) && closeTo(pts[n - 1], pts[0], origin, scaling))
            {
                run_slot_.back() = 0;
                --clusters;
            }
            emitClusters(clusters, 1);
        }

        // General step: union-find over point indices, the root of a component being its smallest index; each point
        // looks s = step - 1 places back. Also every traced run (any step): the reports compile away untraced.
        void segmentWindow(const std::vector<VectorType> &pts, const VectorType &origin, ElementType scaling)
        {
            const size_t n = pts.size(), s = step_ - 1;
            const ElementType *o = ptr(origin);
            const detail::SquaredThreshold<ElementType> thr(scaling, lower_, upper_);
            tsq_.resize(n);
            parent_.resize(n);
            for (size_t i = 0; i < n; ++i)
            {
                const ElementType *p = ptr(pts[i]);
                tsq_[i] = thr(detail::squaredDistance<D>(p, o));
                parent_[i] = detail::isFinite<D>(p) ? i : none;
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
                        const double range = std::sqrt(static_cast<double>(detail::squaredDistance<D>(p, o)));
                        (*observer_)(car_trace::Threshold{i, range, std::abs(static_cast<double>(scaling)) * range,
                                                          std::sqrt(static_cast<double>(tsq_[i]))});
                    }
                size_t root = none;
                for (size_t k = 1, kmax = std::min(s, i); k <= kmax; ++k)
                {
                    const size_t j = i - k, pj = parent_[j];
                    if constexpr (traced)
                        if (observer_ && pj != none) reportComparison<car_trace::Compare>(i, j, detail::squaredDistance<D>(p, ptr(pts[j])), tsq_[i]);
                    // pj == root: j is already in i's cluster (the usual case inside a cluster), no need to look
                    if (pj == none || pj == root || !(detail::squaredDistance<D>(p, ptr(pts[j])) <= tsq_[i])) continue;
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
            const detail::SquaredThreshold<ElementType> thr(scaling, lower_, upper_);
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
                // point q compares with q - k, k = 1..s; those with k <= q - b lie in this run. Most run starts
                // reach no earlier point: the boxes of the run's first s points and of the s points before it
                // are farther apart than any of their thresholds, and nothing is compared.
                if (b == 0) continue;
                const size_t qend = std::min(i, b + s);
                if (!boxesWithin(pts.data(), b >= s ? b - s : 0, b, qend, thr, o)) continue;
                for (size_t q = b; q < qend; ++q)
                {
                    const ElementType *p = ptr(pts[q]);
                    const ElementType tq = thr(detail::squaredDistance<D>(p, o));
                    if (!anyWithin(pts.data(), q >= s ? q - s : 0, b, p, tq)) continue;
                    size_t rj = r;   // the run holding j, found walking back (j decreases)
                    for (size_t k = q - b + 1; k <= s && k <= q; ++k)
                    {
                        const size_t j = q - k;
                        if (!(f[j] & 1u) || !(detail::squaredDistance<D>(p, ptr(pts[j])) <= tq)) continue;
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
                const ElementType tq = thr(detail::squaredDistance<D>(p, o));
                size_t rj = runs - 1;
                for (size_t k = i + 1; k <= s; ++k)
                {
                    const size_t j = i + n - k;
                    if (j <= i) break;
                    if (!(f[j] & 1u) || !(detail::squaredDistance<D>(p, ptr(pts[j])) <= tq)) continue;
                    while (run_begin_[rj] > j) --rj;
                    unite(ri, rj);
                }
            }

            // Output: a cluster per root run, numbered in run order.
            run_slot_.resize(runs);
            size_t clusters = 0;
            for (size_t r = 0; r < runs; ++r)
            {
                const size_t root = find(r);
                run_slot_[r] = root == r ? clusters++ : run_slot_[root];
            }
            emitClusters(clusters, s);
        }

        //! Widens a squared threshold a little, so that a first look whose sums are rounded differently (or
        //! contracted) than the exact comparison's cannot miss a link.
        static ElementType widened(ElementType tsq) { return tsq * ElementType(1.0009765625) + std::numeric_limits<ElementType>::min(); }

        //! A first look at the links from the points [b, qend) back to [jlo, b): false only when the bounding
        //! boxes of the two sets are farther apart than every threshold of the first (the box gap is a lower
        //! bound of each pair's distance, also in rounded arithmetic). Gaps' NaN coordinates are ignored by the
        //! comparisons; their infinities only widen a box.
        static bool boxesWithin(const VectorType *v, size_t jlo, size_t b, size_t qend,
                                const detail::SquaredThreshold<ElementType> &thr, const ElementType *o)
        {
            ElementType qlo[D], qhi[D], jl[D], jh[D], tmax = ElementType(0);
            for (int k = 0; k < D; ++k)
            {
                qlo[k] = jl[k] = std::numeric_limits<ElementType>::infinity();
                qhi[k] = jh[k] = -std::numeric_limits<ElementType>::infinity();
            }
            for (size_t q = b; q < qend; ++q)
            {
                const ElementType *p = ptr(v[q]), t = thr(detail::squaredDistance<D>(p, o));
                tmax = t > tmax ? t : tmax;
                for (int k = 0; k < D; ++k)
                {
                    qlo[k] = p[k] < qlo[k] ? p[k] : qlo[k];
                    qhi[k] = p[k] > qhi[k] ? p[k] : qhi[k];
                }
            }
            for (size_t j = jlo; j < b; ++j)
                for (int k = 0; k < D; ++k)
                {
                    const ElementType a = v[j].data()[k];
                    jl[k] = a < jl[k] ? a : jl[k];
                    jh[k] = a > jh[k] ? a : jh[k];
                }
            ElementType gap = ElementType(0);
            for (int k = 0; k < D; ++k)
            {
                const ElementType g1 = qlo[k] - jh[k], g2 = jl[k] - qhi[k];
                const ElementType g = g1 > g2 ? g1 : g2;
                if (g > ElementType(0)) gap += g * g;
            }
            return gap <= widened(tmax);
        }

        //! A branch-free first look (most run starts reach no earlier point): false only when no point j in
        //! [jlo, jhi) is within tsq of p. The threshold is widened a little, so that a vectorised sum rounded
        //! differently (or contracted) cannot miss a link the exact comparison makes; gaps are left to that one.
        static bool anyWithin(const VectorType *v, size_t jlo, size_t jhi, const ElementType *p, ElementType tsq)
        {
            const ElementType t = widened(tsq);
            bool any = false;
            for (size_t j = jlo; j < jhi; ++j) any |= detail::squaredDistance<D>(p, ptr(v[j])) <= t;
            return any;
        }

        //! The clusters from the runs [run_begin_[r], run_end_[r]) in scan order and the cluster of each run
        //! (run_slot_, numbered by first run): pieces grouped by cluster, in scan order. A skip of more than s indices
        //! between two runs of one cluster can only come from the seam: the cluster is rotated there, so that it
        //! starts with its end-of-scan part.
        void emitClusters(size_t clusters, size_t s)
        {
            const size_t runs = run_begin_.size();
            out_.assign(clusters, Cluster{0, 0, 0});
            for (size_t r = 0; r < runs; ++r)
            {
                Cluster &c = out_[run_slot_[r]];
                ++c.piece_end;   // a count for now
                c.points += run_end_[r] - run_begin_[r];
            }
            size_t at = 0;
            for (Cluster &c : out_)
            {
                c.piece_begin = at;
                at += c.piece_end;
                c.piece_end = c.piece_begin;   // the fill cursor below
            }
            pieces_.resize(runs);
            rotate_at_.assign(clusters, 0);
            for (size_t r = 0; r < runs; ++r)
            {
                const size_t c = run_slot_[r];
                Cluster &cl = out_[c];
                const size_t b = run_begin_[r];
                if (cl.piece_end > cl.piece_begin && b - (pieces_[cl.piece_end - 1].end - 1) > s) rotate_at_[c] = cl.piece_end;
                pieces_[cl.piece_end++] = Piece{b, run_end_[r]};
            }
            for (size_t c = 0; c < clusters; ++c)
                if (rotate_at_[c] > 0)
                    std::rotate(pieces_.begin() + static_cast<std::ptrdiff_t>(out_[c].piece_begin),
                                pieces_.begin() + static_cast<std::ptrdiff_t>(rotate_at_[c]),
                                pieces_.begin() + static_cast<std::ptrdiff_t>(out_[c].piece_end));
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
                            const ElementType dsq = detail::squaredDistance<D>(ptr(pts[i]), ptr(pts[j]));
                            reportComparison<car_trace::Seam>(i, j, dsq, tsq_[i]);
                            const size_t a = find(i), b = find(j);
                            if (dsq <= tsq_[i] && a != b) (*observer_)(car_trace::Merge{i, j, std::max(a, b), std::min(a, b)});
                        }
                    if (parent_[j] != none && detail::squaredDistance<D>(ptr(pts[i]), ptr(pts[j])) <= tsq_[i]) unite(i, j);
                }
            }

            // Runs of equal root, each a piece of its cluster (numbered by smallest index).
            slot_.resize(n);
            run_begin_.clear();
            run_end_.clear();
            run_slot_.clear();
            size_t clusters = 0;
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
                if (r == b) slot_[r] = clusters++;
                run_begin_.push_back(b);
                run_end_.push_back(i);
                run_slot_.push_back(slot_[r]);
            }
            emitClusters(clusters, s);
            if constexpr (traced)
                if (observer_)
                {
                    size_t label = 0;
                    for (size_t c = 0; c < out_.size(); ++c, ++label)
                    {
                        while (parent_[label] != label) ++label;   // cluster c's label: the c-th root in scan order
                        (*observer_)(car_trace::Cluster{c, label, pieces_[out_[c].piece_begin].begin, out_[c].points});
                    }
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
            detail::traceDistances(static_cast<double>(dsq), static_cast<double>(tsq), linked, distance, threshold);
            (*observer_)(Event{i, j, distance, threshold, linked});
        }

        bool closeTo(const VectorType &earlier, const VectorType &later, const VectorType &origin, ElementType scaling) const
        {
            return detail::meetsCriterion(earlier, later, origin, scaling, lower_, upper_);
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

        // the clusters not grabbed yet: out_[next_..] as pieces (index ranges) of store_, a copy of the scan
        struct Piece
        {
            size_t begin, end;
        };
        struct Cluster
        {
            size_t piece_begin, piece_end, points;
        };
        std::vector<VectorType> store_;
        std::vector<Piece> pieces_;
        std::vector<Cluster> out_;
        size_t next_ = 0;

        // work buffers, kept between calls
        std::vector<unsigned char> flags_;
        std::vector<ElementType> tsq_;
        std::vector<size_t> parent_, slot_, rotate_at_;
        std::vector<size_t> run_begin_, run_end_, run_slot_;   // runs [begin, end) and their clusters (emitClusters)
        Observer *observer_ = nullptr;
    };
}
