// IA_Segmenter (Incremental, Adaptive): streaming segmentation of ordered points, one addPoint() at a time.
//
// The segmenter keeps a window of the last `step` points. A new point p joins every cluster that has a window point
// q with |p - q| <= t(p), t(p) = clamp(scaling * |p - origin|, lower_bound, upper_bound) (seg/ProximityCriterion.h);
// if it touches several clusters they are merged, completely, alive points included; otherwise it opens a cluster.
// A point leaving the window moves to its cluster's alive list (aliveClusters(), keyed by cluster id, ids growing
// with creation; a merge keeps the older id). A cluster whose last window point leaves is closed: it moves from the
// alive map to the closed queue, which grabCluster() empties in closing order. Every cluster lists its points in
// stream order and is non-empty. Points with a NaN (or infinite) coordinate are gaps: they take a window place but
// join no cluster. Nothing is ever lost: each point is in the window, in an alive cluster or in a closed cluster,
// however addPoint() and grabCluster() calls interleave. flush() (an addition to the published API) empties the
// window at the end of a stream, closing every cluster.
//
// The windows differ by one: IA at step s compares a new point with the s previous points, CAR_Segmenter at step
// s + 1 does (CAR's window is step - 1 points, RTL's definitions). With scaling = (s + 1) * 2 pi / N, CAR's
// threshold at step s + 1, both give the same clusters on the same points, except that CAR also links across the
// seam of a closed scan.
//
// Tracing (core/Trace.h): IA_Segmenter<Vector, Observer> with an observer set by setObserver() reports every step
// (addPoint, the window moves of setStepSize and flush) as the events of seg/SegTrace.h (use rtl::IaTraceLog to
// record them); a traced segmenter skips its fast path (same clusters). With the default rtl::NoTrace
// nothing is reported and the code is the untraced code.
//
// Bad input: step 0 is treated as 1; addPoint throws std::invalid_argument unless 0 <= lower_bound <= upper_bound
// (upper may be +inf), the scaling is not NaN and the origin is finite.
// Defaults: step 1, bounds [0, +inf), scaling 2 pi / 360 (one-degree beams).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <list>
#include <map>
#include <stdexcept>
#include <vector>

#include "rtl/core/Trace.h"
#include "rtl/core/VectorND.h"
#include "rtl/seg/ProximityCriterion.h"
#include "rtl/seg/SegTrace.h"

// Keeps the rare paths out of the inlined per-point code.
#ifndef RTL_SEG_NOINLINE
#if defined(__GNUC__) || defined(__clang__)
#define RTL_SEG_NOINLINE __attribute__((noinline))
#elif defined(_MSC_VER)
#define RTL_SEG_NOINLINE __declspec(noinline)
#else
#define RTL_SEG_NOINLINE
#endif
#endif

namespace rtl
{
    template<class Vector, class Observer = NoTrace>
    class IA_Segmenter
    {
    public:
        typedef typename Vector::ElementType ElementType;
        typedef Vector VectorType;
        typedef Observer ObserverType;

        IA_Segmenter() { resizeWindow(1); }
        IA_Segmenter(size_t step, ElementType lower_bound, ElementType upper_bound, ElementType scaling)
            : lower_(lower_bound), upper_(upper_bound), scaling_(scaling)
        {
            resizeWindow(step == 0 ? 1 : step);
        }
        //! Copies are deep: the copy continues the stream on its own, exactly as the source would.
        IA_Segmenter(const IA_Segmenter &) = default;
        //! Moves are noexcept and O(1) (no point is copied); the moved-from segmenter may only be destroyed or
        //! assigned to.
        IA_Segmenter(IA_Segmenter &&) noexcept = default;
        IA_Segmenter &operator=(const IA_Segmenter &) = default;
        IA_Segmenter &operator=(IA_Segmenter &&) noexcept = default;
        ~IA_Segmenter() = default;

        //! Changes the window size; when it shrinks, the oldest window points leave the window first.
        void setStepSize(unsigned int step) { resizeWindow(step == 0 ? 1 : step); }
        void setLowerBound(ElementType lb) { lower_ = lb; checked_ = false; }
        void setUpperBound(ElementType ub) { upper_ = ub; checked_ = false; }
        void setScaling(ElementType scale) { scaling_ = scale; checked_ = false; }
        //! The observer that receives the steps from now on (nullptr: none); not owned.
        void setObserver(Observer *observer) { observer_ = observer; }

        [[nodiscard]] size_t closedClustersAvailable() const { return closed_.size() - closed_head_; }
        [[nodiscard]] size_t aliveClustersAvailable() const { return lists_.alive.size(); }
        [[nodiscard]] const std::map<size_t, std::vector<VectorType>> &aliveClusters() const
        {
            untail();
            return lists_.alive;
        }

        void addPoint(const VectorType &pt, const VectorType &origin = VectorType::zeros())
        {
            // x - x is 0 for finite x, NaN otherwise, so one comparison of the sums checks every coordinate
            ElementType rsq = 0, pz = 0, oz = 0;
            for (int k = 0; k < D; ++k)
            {
                const ElementType a = pt.data()[k], o = origin.data()[k];
                rsq += (a - o) * (a - o);
                pz += a - a;
                oz += o - o;
            }
            const bool valid = pz == ElementType(0), origin_finite = oz == ElementType(0);
            if constexpr (traced)
                if (observer_)
                {
                    addPointSlow(pt, valid, origin_finite, rsq);
                    return;
                }
            // hot path, kept small enough to inline: the window is all in one cluster and sits at the end of its alive
            // list (tail mode, see enterTail); a point within reach of the newest joins it, and no other comparison
            // can change anything
            if (lists_.tail != nullptr && checked_ && origin_finite && valid)
            {
                std::vector<VectorType> &v = *lists_.tail;
                if (seg_detail::squaredDistance<D>(pt.data().data(), v.back().data().data()) <= thr_(rsq))
                {
                    v.push_back(pt);
                    return;
                }
            }
            addPointSlow(pt, valid, origin_finite, rsq);
        }

        //! Removes and returns the oldest closed cluster; an empty vector when none is closed.
        std::vector<VectorType> grabCluster()
        {
            if (closed_head_ == closed_.size()) return {};
            std::vector<VectorType> c = std::move(closed_[closed_head_++]);
            if (closed_head_ == closed_.size())
            {
                closed_.clear();
                closed_head_ = 0;
            }
            else if (closed_head_ >= 64 && 2 * closed_head_ >= closed_.size())
            {
                // a caller that never empties the queue: drop the handed-out front, amortised O(1) per cluster
                closed_.erase(closed_.begin(), closed_.begin() + static_cast<std::ptrdiff_t>(closed_head_));
                closed_head_ = 0;
            }
            return c;
        }

        //! End of stream: every window point leaves the window (oldest first), so every cluster closes.
        void flush()
        {
            untail();
            for (size_t k = 0; k < count_; ++k) evict(head_ + k < step_ ? head_ + k : head_ + k - step_);
            head_ = 0;
            count_ = 0;
        }

    private:
        static constexpr int D = VectorType::dimensionality();
        static constexpr size_t none = std::numeric_limits<size_t>::max();
        static constexpr bool traced = Observer::enabled;
        typedef std::map<size_t, std::vector<VectorType>> AliveMap;

        RTL_SEG_NOINLINE void addPointSlow(const VectorType &pt, bool valid, bool origin_finite, ElementType rsq)
        {
            untail();
            if (!checked_) checkParameters();
            if (!origin_finite) throw std::invalid_argument("IA_Segmenter::addPoint: the origin must be finite");
            if constexpr (traced)
                if (observer_)
                {
                    (*observer_)(ia_trace::Add{stream_, !valid});
                    if (valid)
                    {
                        const double range = std::sqrt(static_cast<double>(rsq));
                        (*observer_)(ia_trace::Threshold{stream_, range, std::abs(static_cast<double>(scaling_)) * range,
                                                         std::sqrt(static_cast<double>(thr_(rsq)))});
                    }
                }
            if (step_ == 1)
            {
                addToPairWindow(pt, valid, rsq);
                if (wrec_[0] != none) enterTail(wrec_[0]);
                return;
            }

            size_t rec = none;
            if (valid)
            {
                const ElementType tsq = thr_(rsq);
                const ElementType *p = pt.data().data();
                for (size_t w = 0; w < step_; ++w)
                {
                    const size_t r = wrec_[w];
                    if constexpr (traced)
                        if (observer_ && r != none)
                            reportComparison(stream_, widx_[w], seg_detail::squaredDistance<D>(p, wpts_[w].data().data()), tsq);
                    if (r == none || r == rec || !(seg_detail::squaredDistance<D>(p, wpts_[w].data().data()) <= tsq)) continue;
                    if constexpr (traced)
                        if (observer_)
                        {
                            if (rec == none) (*observer_)(ia_trace::Link{stream_, widx_[w], lists_.recs[r].id});
                            else (*observer_)(ia_trace::Merge{stream_, widx_[w], std::max(lists_.recs[rec].id, lists_.recs[r].id),
                                                              std::min(lists_.recs[rec].id, lists_.recs[r].id)});
                        }
                    rec = rec == none ? r : merge(rec, r);
                }
                if (rec == none)
                {
                    rec = newRecord();
                    if constexpr (traced) report(ia_trace::Open{stream_, lists_.recs[rec].id});
                }
                ++lists_.recs[rec].in_window;
            }
            size_t slot;
            if (count_ == step_)
            {
                slot = head_;
                evict(slot);
                head_ = head_ + 1 == step_ ? 0 : head_ + 1;
            }
            else
            {
                slot = head_ + count_;
                if (slot >= step_) slot -= step_;
                ++count_;
            }
            wpts_[slot] = pt;
            wrec_[slot] = rec;
            widx_[slot] = stream_++;
            // every slot holds rec exactly when rec counts step_ window points (in_window counts them)
            if (rec != none && lists_.recs[rec].in_window == step_) enterTail(rec);
        }

        // Tail mode: while the window is full and all in one cluster that has an alive list, the window points are
        // kept as the last step_ points of that list (lists_.tail), so that a point joining the cluster is one
        // push_back: no ring slot, no eviction. The list's points from tail_start_ on have the consecutive stream
        // indices tail_stream_, tail_stream_ + 1, ...; stream_ and the ring are stale meanwhile. untail() restores
        // the ring before anything else reads the window or the alive lists.
        void enterTail(size_t rec)
        {
            if constexpr (traced)
                if (observer_) return;
            Record &R = lists_.recs[rec];
            if (!R.has_alive || R.in_window != step_ || count_ != step_) return;
            std::vector<VectorType> &v = R.alive->second;
            const size_t first = step_ == 1 ? stream_ - 1 : widx_[head_];
            if (R.contiguous && R.base + v.size() != first) listIndices(R);
            tail_start_ = v.size();
            tail_stream_ = first;
            for (size_t k = 0; k < step_; ++k) v.push_back(wpts_[head_ + k < step_ ? head_ + k : head_ + k - step_]);
            lists_.tail_rec = rec;
            lists_.tail = &v;
        }

        // Leaves tail mode: the last step_ points of the tail's list go back to the ring (oldest in slot 0); the
        // others have left the window and stay alive. Const, for aliveClusters(): the members it changes are mutable.
        void untail() const
        {
            if (lists_.tail == nullptr) return;
            const size_t rec = lists_.tail_rec;
            Record &R = lists_.recs[rec];
            std::vector<VectorType> &v = *lists_.tail;
            const size_t total = v.size() - tail_start_, left = total - step_;
            for (size_t k = 0; k < step_; ++k)
            {
                wpts_[k] = v[tail_start_ + left + k];
                wrec_[k] = rec;
                widx_[k] = tail_stream_ + left + k;
            }
            if (!R.contiguous)
                for (size_t k = 0; k < left; ++k) R.index.push_back(tail_stream_ + k);
            v.resize(tail_start_ + left);
            head_ = 0;
            count_ = step_;
            stream_ = tail_stream_ + total;
            lists_.tail = nullptr;
            lists_.tail_rec = none;
        }

        struct Record
        {
            size_t id = 0;
            size_t in_window = 0;
            bool has_alive = false;
            typename AliveMap::iterator alive;      // valid when has_alive
            // stream indices of the alive points, needed to merge interleaved clusters in stream order: implicitly
            // base, base + 1, ... while `contiguous` (always so for step 1), else listed in `index`
            bool contiguous = true;
            size_t base = 0;
            std::vector<size_t> index;
        };

        // The records and the alive map they point into. A copy re-points each record's iterator into the copy's
        // own map (the implicit copy would keep iterators into the source's map); a move keeps them, since the
        // map's nodes move with it.
        struct ClusterLists
        {
            std::vector<Record> recs;
            AliveMap alive;
            size_t tail_rec = none;                           // tail mode: the record whose list holds the window
            std::vector<VectorType> *tail = nullptr;          // its alive list (a map node: kept by moves)

            ClusterLists() = default;
            ClusterLists(const ClusterLists &o) : recs(o.recs), alive(o.alive), tail_rec(o.tail_rec) { repoint(); }
            ClusterLists(ClusterLists &&) noexcept = default;
            ClusterLists &operator=(const ClusterLists &o)
            {
                if (this != &o)
                {
                    ClusterLists copy(o);
                    *this = std::move(copy);
                }
                return *this;
            }
            ClusterLists &operator=(ClusterLists &&) noexcept = default;
            ~ClusterLists() = default;

            void repoint()
            {
                for (Record &R : recs)
                    if (R.has_alive) R.alive = alive.find(R.id);
                tail = tail_rec == none ? nullptr : &recs[tail_rec].alive->second;
            }
        };

        void checkParameters()
        {
            seg_detail::checkParameters<ElementType>("IA_Segmenter::addPoint", lower_, upper_, true);
            if (scaling_ != scaling_) throw std::invalid_argument("IA_Segmenter::addPoint: the scaling must not be NaN");
            thr_ = seg_detail::SquaredThreshold<ElementType>(scaling_, lower_, upper_);
            checked_ = true;
        }

        size_t newRecord()
        {
            size_t r;
            if (free_.empty())
            {
                r = lists_.recs.size();
                lists_.recs.emplace_back();
            }
            else
            {
                r = free_.back();
                free_.pop_back();
            }
            Record &R = lists_.recs[r];
            R.id = next_id_++;
            R.in_window = 0;
            R.has_alive = false;
            return r;
        }

        // step 1, the common case: the window is one point, and a point that joins its predecessor's cluster just
        // pushes the predecessor into the alive list.
        void addToPairWindow(const VectorType &pt, bool valid, ElementType rsq)
        {
            const size_t prev = wrec_[0];
            if constexpr (traced)
                if (observer_ && valid && prev != none)
                    reportComparison(stream_, stream_ - 1, seg_detail::squaredDistance<D>(pt.data().data(), wpts_[0].data().data()), thr_(rsq));
            if (valid && prev != none && seg_detail::squaredDistance<D>(pt.data().data(), wpts_[0].data().data()) <= thr_(rsq))
            {
                if constexpr (traced)
                    if (observer_)
                    {
                        (*observer_)(ia_trace::Link{stream_, stream_ - 1, lists_.recs[prev].id});
                        (*observer_)(ia_trace::Slide{stream_ - 1, false});
                        (*observer_)(ia_trace::Alive{stream_ - 1, lists_.recs[prev].id});
                    }
                pushAlive(lists_.recs[prev], wpts_[0], stream_ - 1);
            }
            else
            {
                if constexpr (traced)
                    if (valid) report(ia_trace::Open{stream_, next_id_});   // the id newRecord() gives below
                if (count_ == 1) evict(0);
                size_t rec = none;
                if (valid)
                {
                    rec = newRecord();
                    lists_.recs[rec].in_window = 1;
                }
                wrec_[0] = rec;
                count_ = 1;
            }
            wpts_[0] = pt;
            ++stream_;
        }

        // Appends a point that leaves the window to its cluster's alive list (created on the first point).
        void pushAlive(Record &R, const VectorType &p, size_t idx)
        {
            if (!R.has_alive)
            {
                R.alive = lists_.alive.emplace_hint(lists_.alive.end(), R.id, takeVector());
                R.has_alive = true;
                R.contiguous = true;
                R.base = idx;
                R.index.clear();
            }
            std::vector<VectorType> &v = R.alive->second;
            if (R.contiguous && idx != R.base + v.size()) listIndices(R);
            if (!R.contiguous) R.index.push_back(idx);
            v.push_back(p);
        }

        std::vector<VectorType> takeVector()
        {
            if (pool_.empty()) return {};
            std::vector<VectorType> v = std::move(pool_.back());
            pool_.pop_back();
            return v;
        }

        // Keeps at most step + 2 spare lists: never more than step + 1 clusters are alive at once.
        void recycle(std::vector<VectorType> &&v)
        {
            v.clear();
            if (pool_.size() < step_ + 2) pool_.push_back(std::move(v));
        }

        static size_t indexAt(const Record &R, size_t k) { return R.contiguous ? R.base + k : R.index[k]; }

        static void listIndices(Record &R)
        {
            if (!R.contiguous) return;
            const size_t n = R.alive->second.size();
            R.index.resize(n);
            for (size_t k = 0; k < n; ++k) R.index[k] = R.base + k;
            R.contiguous = false;
        }

        // The window point in `slot` leaves the window for its cluster's alive list; the cluster closes if it was
        // its last window point.
        void evict(size_t slot)
        {
            const size_t r = wrec_[slot];
            if constexpr (traced)
                if (observer_)
                {
                    const size_t i = step_ == 1 ? stream_ - 1 : widx_[slot];
                    (*observer_)(ia_trace::Slide{i, r == none});
                    if (r != none) (*observer_)(ia_trace::Alive{i, lists_.recs[r].id});
                }
            if (r == none) return;
            wrec_[slot] = none;
            Record &R = lists_.recs[r];
            if (!R.has_alive && R.in_window == 1)
            {
                // the cluster closes with this point and never had an alive list: skip the alive map
                closed_.emplace_back(1, wpts_[slot]);
                if constexpr (traced) report(ia_trace::Close{R.id, 1});
                R.in_window = 0;
                free_.push_back(r);
                return;
            }
            const size_t idx = step_ == 1 ? stream_ - 1 : widx_[slot];
            pushAlive(R, wpts_[slot], idx);
            std::vector<VectorType> &v = R.alive->second;
            if (--R.in_window == 0)
            {
                // hand out an exact-size copy and keep the alive list's capacity for the next cluster: growing
                // vectors from scratch (and faulting in their pages) would cost more than the copy
                closed_.emplace_back(v.begin(), v.end());
                if constexpr (traced) report(ia_trace::Close{R.id, v.size()});
                recycle(std::move(v));
                lists_.alive.erase(R.alive);
                R.has_alive = false;
                free_.push_back(r);
            }
        }

        template<class Event>
        void report(const Event &e)
        {
            if (observer_) (*observer_)(e);
        }

        void reportComparison(size_t i, size_t j, ElementType dsq, ElementType tsq)
        {
            double distance, threshold;
            const bool linked = dsq <= tsq;
            seg_detail::traceDistances(static_cast<double>(dsq), static_cast<double>(tsq), linked, distance, threshold);
            (*observer_)(ia_trace::Compare{i, j, distance, threshold, linked});
        }

        // Merges two clusters that both have window points; the older id survives. Returns the survivor's record.
        size_t merge(size_t a, size_t b)
        {
            const size_t keep = lists_.recs[a].id < lists_.recs[b].id ? a : b, gone = keep == a ? b : a;
            for (size_t w = 0; w < step_; ++w)
                if (wrec_[w] == gone) wrec_[w] = keep;
            Record &K = lists_.recs[keep], &G = lists_.recs[gone];
            K.in_window += G.in_window;
            if (G.has_alive)
            {
                if (!K.has_alive)
                {
                    K.alive = lists_.alive.emplace(K.id, std::move(G.alive->second)).first;
                    K.has_alive = true;
                    K.contiguous = G.contiguous;
                    K.base = G.base;
                    K.index.swap(G.index);
                }
                else
                {
                    mergeAlive(K, G);
                    recycle(std::move(G.alive->second));
                }
                lists_.alive.erase(G.alive);
                G.has_alive = false;
            }
            G.in_window = 0;
            free_.push_back(gone);
            return keep;
        }

        // Moves G's alive points into K's, in stream order. Only the part of K newer than G's oldest point moves:
        // the cost is O(|G| + that part), not O(|K|).
        static void mergeAlive(Record &K, Record &G)
        {
            std::vector<VectorType> &kp = K.alive->second, &gp = G.alive->second;
            const size_t nk = kp.size(), ng = gp.size();
            if (indexAt(G, 0) > indexAt(K, nk - 1))
            {
                if (K.contiguous && G.contiguous && G.base == K.base + nk) { /* stays contiguous */ }
                else
                {
                    listIndices(K);
                    for (size_t j = 0; j < ng; ++j) K.index.push_back(indexAt(G, j));
                }
                kp.insert(kp.end(), gp.begin(), gp.end());
                return;
            }
            listIndices(K);
            listIndices(G);
            kp.resize(nk + ng);
            K.index.resize(nk + ng);
            size_t i = nk, j = ng, w = nk + ng;
            while (j > 0)
            {
                --w;
                if (i > 0 && K.index[i - 1] > G.index[j - 1])
                {
                    --i;
                    kp[w] = kp[i];
                    K.index[w] = K.index[i];
                }
                else
                {
                    --j;
                    kp[w] = gp[j];
                    K.index[w] = G.index[j];
                }
            }
        }

        void resizeWindow(size_t step)
        {
            if (step == step_ && !wrec_.empty()) return;
            untail();
            // the oldest points that do not fit leave first, in stream order
            size_t k = 0;
            for (; count_ - k > step; ++k) evict(head_ + k < step_ ? head_ + k : head_ + k - step_);
            std::vector<VectorType> pts(step, VectorType::zeros());
            std::vector<size_t> rec(step, none), idx(step, 0);
            for (size_t m = 0; k < count_; ++k, ++m)
            {
                const size_t w = head_ + k < step_ ? head_ + k : head_ + k - step_;
                pts[m] = wpts_[w];
                rec[m] = wrec_[w];
                idx[m] = step_ == 1 ? stream_ - 1 : widx_[w];
            }
            count_ = std::min(count_, step);
            head_ = 0;
            step_ = step;
            wpts_.swap(pts);
            wrec_.swap(rec);
            widx_.swap(idx);
        }

        ElementType lower_ = ElementType(0), upper_ = std::numeric_limits<ElementType>::infinity();
        ElementType scaling_ = seg_detail::circularScaling<ElementType>(1, 360);
        bool checked_ = false;                                    // parameters validated since the last setter
        seg_detail::SquaredThreshold<ElementType> thr_{0, 0, 0};

        // window: a ring of step_ slots, count_ of them used, head_ the oldest; wrec_ is none for gaps and free slots
        // (mutable: untail(), called by the const aliveClusters(), moves the window back into the ring)
        size_t step_ = 0;
        mutable size_t head_ = 0, count_ = 0;
        mutable std::vector<VectorType> wpts_;
        mutable std::vector<size_t> wrec_, widx_;                 // widx_ unused at step 1: its point is stream_ - 1

        mutable ClusterLists lists_;
        mutable size_t tail_start_ = 0, tail_stream_ = 0;        // tail mode: see enterTail
        std::vector<size_t> free_;
        std::vector<std::vector<VectorType>> closed_;           // closing order; closed_head_ is the next to hand out
        size_t closed_head_ = 0;
        std::vector<std::vector<VectorType>> pool_;             // emptied alive lists, capacity kept
        size_t next_id_ = 0;
        mutable size_t stream_ = 0;
        Observer *observer_ = nullptr;
    };
}
