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
// Complexity: addPoint compares the new point with at most `step` window points; a merge relabels the window (O(step))
// and moves the newer cluster's alive points into the older one's, interleaving in stream order (cost: the newer
// cluster's alive points plus the older one's points that are younger than them); when the whole window belongs to one
// cluster, a joining point is appended in O(1). Memory: the window plus the alive and closed clusters not yet grabbed.
// Invariant: every point added is in exactly one of the window, an alive cluster or a closed cluster.
//
// The windows differ by one: IA at step s compares a new point with the s previous points, CAR_Segmenter at step
// s + 1 does (CAR's window is step - 1 points, RTL's definitions). With scaling = (s + 1) * 2 pi / N, CAR's
// threshold at step s + 1, both give the same clusters on the same points, except that CAR also links across the
// seam of a closed scan.
//
// Tracing (core/Trace.h): IA_Segmenter<Vector, Observer> with an observer set by setObserver() reports every step
// (addPoint, the window moves of setStepSize and flush) as the events of seg/SegTrace.h (use rtl::IaTraceLog to
// record them); a traced type takes the slow path, with or without an observer (same clusters). With the default rtl::NoTrace
// nothing is reported and the code is the untraced code.
//
// Bad input: step 0 is treated as 1; addPoint throws std::invalid_argument unless 0 <= lower_bound <= upper_bound
// (upper may be +inf), the scaling is not NaN and the origin is finite.
// Defaults: step 1, bounds [0, +inf), scaling 2 pi / 360 (one-degree beams).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <list>
#include <map>
#include <stdexcept>
#include <type_traits>
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
// A branch the compiler should lay out as the fall-through path.
#ifndef RTL_SEG_LIKELY
#if defined(__GNUC__) || defined(__clang__)
#define RTL_SEG_LIKELY(x) __builtin_expect(!!(x), 1)
#else
#define RTL_SEG_LIKELY(x) (x)
#endif
#endif

namespace rtl
{
    namespace detail
    {
        //! IA_Segmenter's window test in 16-byte vectors (GCC/Clang vector extensions, any target: SSE2, AVX, NEON,
        //! wasm simd128 or scalar code); n = 0 (no vector test) for other element types and compilers.
        template<typename E>
        struct WindowLanes
        {
            static constexpr size_t n = 0;
            typedef std::int64_t Tag;
        };
#if defined(__GNUC__) || defined(__clang__)
        template<>
        struct WindowLanes<float>
        {
            static constexpr size_t n = 4;
            typedef std::int32_t Tag;
            typedef float V __attribute__((vector_size(16)));
            typedef std::int32_t M __attribute__((vector_size(16)));
        };
        template<>
        struct WindowLanes<double>
        {
            static constexpr size_t n = 2;
            typedef std::int64_t Tag;
            typedef double V __attribute__((vector_size(16)));
            typedef std::int64_t M __attribute__((vector_size(16)));
        };
#endif
    }

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

        [[nodiscard]] size_t closedClustersAvailable() const { return closed_left_; }
        [[nodiscard]] size_t aliveClustersAvailable() const { return lists_.alive.size() + lists_.parked; }
        [[nodiscard]] const std::map<size_t, std::vector<VectorType>> &aliveClusters() const
        {
            untail();
            lists_.attachParked();
            return lists_.alive;
        }

        void addPoint(const VectorType &pt, const VectorType &origin = VectorType::zeros())
        {
            // x - x is 0 for finite x, NaN otherwise, so one comparison of the sums checks every coordinate
            // the first coordinate's terms start the sums: 0 + x is x for them (a square or x - x is never -0), and
            // the compiler cannot drop the additions to 0 itself
            const ElementType a0 = pt.data()[0], o0 = origin.data()[0];
            ElementType rsq = (a0 - o0) * (a0 - o0), pz = a0 - a0, oz = o0 - o0;
            for (int k = 1; k < D; ++k)
            {
                const ElementType a = pt.data()[k], o = origin.data()[k];
                rsq += (a - o) * (a - o);
                pz += a - a;
                oz += o - o;
            }
            const bool valid = pz == ElementType(0), origin_finite = oz == ElementType(0);
            // a traced type always takes the slow path (observer or not): its fast paths are not compiled at all
            if constexpr (traced)
            {
                addPointSlow(pt, valid, origin_finite, rsq);
                return;
            }
            // hot path, kept small enough to inline: the window is all in one cluster and sits at the end of its alive
            // list (tail mode, see enterTail); a point within reach of the newest joins it, and no other comparison
            // can change anything
            if (checked_ && origin_finite && valid)
            {
                if (lists_.tail != nullptr)
                {
                    std::vector<VectorType> &v = *lists_.tail;
                    // likely: the join is then straight-line code in the caller's loop, not a jump out and back
                    if (RTL_SEG_LIKELY(detail::squaredDistance<D>(pt.data().data(), v.back().data().data()) <= thr_(rsq)))
                    {
                        v.push_back(pt);
                        return;
                    }
                }
                else if (pad_ != 0)
                {
                    addToRing(pt, rsq);
                    return;
                }
            }
            addPointSlow(pt, valid, origin_finite, rsq);
        }

        //! Removes and returns the oldest closed cluster; an empty vector when none is closed.
        std::vector<VectorType> grabCluster()
        {
            if (closed_left_ == 0) return {};
            const size_t head = closed_.size() - closed_left_--;
            std::vector<VectorType> c = std::move(closed_[head]);
            if (closed_left_ == 0) closed_.clear();
            else if (head >= 63 && 2 * (head + 1) >= closed_.size())
            {
                // a caller that never empties the queue: drop the handed-out front, amortised O(1) per cluster
                closed_.erase(closed_.begin(), closed_.begin() + static_cast<std::ptrdiff_t>(head + 1));
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

        // The slot path without addPointSlow's checks (short clusters take it for every point): untraced, window lanes
        // (so step > 1), a valid point and a finite origin, checked parameters, not in tail mode.
        RTL_SEG_NOINLINE void addToRing(const VectorType &pt, ElementType rsq)
        {
            const ElementType tsq = thr_(rsq);
            const ElementType *p = pt.data().data();
            size_t rec;
            if (!linkSameRecord(p, tsq, rec)) rec = linkInSlotOrder(p, tsq);
            if (rec == none) rec = newRecord();
            hint_ = rec;
            Record &R = lists_.recs[rec];   // stable from here on: no record is added below
            ++R.in_window;
            size_t slot;
            if (count_ == step_)
            {
                slot = head_;
                head_ = head_ + 1 == step_ ? 0 : head_ + 1;
                evictFromRing(slot);
            }
            else
            {
                slot = head_ + count_;
                if (slot >= step_) slot -= step_;
                ++count_;
            }
            // putSlot for a point with a record
            wpts_[slot] = pt;
            wrec_[slot] = rec;
            for (int k = 0; k < D; ++k) wc_[static_cast<size_t>(k) * pad_ + slot] = pt.data()[k];
            wtag_[slot] = slotTag(rec);
            widx_[slot] = stream_++;
            if (R.in_window == step_) enterTail(rec);
        }

        // addToRing's eviction, evict() without clearing the slot (the caller rewrites it): a point that extends
        // its cluster's alive list, or starts it with a pooled node, inline; the last point of a cluster whose alive
        // list it extends closes it in closeFromRing; anything else through evict().
        void evictFromRing(size_t slot)
        {
            const size_t r = wrec_[slot];
            if (r == none) return;
            Record &R = lists_.recs[r];
            const size_t idx = widx_[slot];
            if (R.in_window >= 2)
            {
                if (R.next != idx)
                {
                    if (R.has_alive || node_pool_.nodes.empty())
                    {
                        evict(slot);
                        return;
                    }
                    newAliveList(R);
                    R.contiguous = true;
                    R.base = idx;
                    R.index.clear();
                    R.next = idx;
                }
                --R.in_window;
                ++R.next;
                R.list->push_back(wpts_[slot]);
                return;
            }
            if (R.next == idx) closeFromRing(r, slot);
            else evict(slot);
        }

        // evict() of the last window point of a cluster whose alive list it extends: the list and the point go out
        // in one exact-size vector, without passing through the list.
        RTL_SEG_NOINLINE void closeFromRing(size_t r, size_t slot)
        {
            Record &R = lists_.recs[r];
            const std::vector<VectorType> &v = *R.list;
            std::vector<VectorType> c;
            c.reserve(v.size() + 1);
            c.insert(c.end(), v.begin(), v.end());
            c.push_back(wpts_[slot]);
            closed_.push_back(std::move(c));
            ++closed_left_;
            R.in_window = 0;
            dropAliveList(R);
            free_.push_back(r);
        }

        // The window loop of an untraced segmenter (addToRing, addPointSlow): every linked cluster in slot order, merged
        // into the first. addPointSlow's traced loop is the same with the trace's reports.
        RTL_SEG_NOINLINE size_t linkInSlotOrder(const ElementType *p, ElementType tsq)
        {
            size_t rec = none;
            for (size_t w = 0; w < step_; ++w)
            {
                const size_t r = wrec_[w];
                if (r == none || r == rec || !(detail::squaredDistance<D>(p, wpts_[w].data().data()) <= tsq)) continue;
                rec = rec == none ? r : merge(rec, r);
            }
            return rec;
        }

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
            Record *Rn = nullptr;   // rec's record
            if (valid)
            {
                const ElementType tsq = thr_(rsq);
                const ElementType *p = pt.data().data();
                if constexpr (!traced)
                {
                    if (!linkSameRecord(p, tsq, rec)) rec = linkInSlotOrder(p, tsq);
                }
                else
                    for (size_t w = 0; w < step_; ++w)   // linkInSlotOrder with the trace's reports
                    {
                        const size_t r = wrec_[w];
                        if (observer_ && r != none)
                            reportComparison(stream_, widx_[w], detail::squaredDistance<D>(p, wpts_[w].data().data()), tsq);
                        if (r == none || r == rec || !(detail::squaredDistance<D>(p, wpts_[w].data().data()) <= tsq)) continue;
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
                hint_ = rec;
                Rn = &lists_.recs[rec];   // stable from here on: no record is added below
                ++Rn->in_window;
            }
            size_t slot;
            if (count_ == step_)
            {
                slot = head_;
                head_ = head_ + 1 == step_ ? 0 : head_ + 1;
                if (!evictToAlive(slot)) evict(slot);
            }
            else
            {
                slot = head_ + count_;
                if (slot >= step_) slot -= step_;
                ++count_;
            }
            putSlot(slot, pt, rec);
            widx_[slot] = stream_++;
            // every slot holds rec exactly when rec counts step_ window points (in_window counts them)
            if (Rn != nullptr && Rn->in_window == step_) enterTail(rec);
        }

        // The common eviction, inline: the slot's point joins an alive list that stays alive and contiguous. The slot
        // is left as it is: the caller rewrites all of it (putSlot). False: evict() must do it.
        bool evictToAlive(size_t slot)
        {
            if constexpr (traced) return false;
            const size_t r = wrec_[slot];
            if (r == none) return false;
            Record &R = lists_.recs[r];
            if (R.next != widx_[slot] || R.in_window < 2) return false;
            --R.in_window;
            ++R.next;
            R.list->push_back(wpts_[slot]);
            return true;
        }

        // Most points link to window points of one cluster only, that of the last valid point (hint_), or to none.
        // One pass over the window's coordinate arrays (vectorised: independent per slot) tells: true with rec = that
        // cluster or none (a new cluster opens); false when other clusters are linked too, which the caller's loop
        // resolves in slot order, as before. Free and gap slots hold NaN coordinates, so they never link. hint_ is
        // the record of the last valid point added at step > 1 (also past gaps, unlike the newest slot's); it may be
        // stale (freed, or reused since): any guess gives the right answer, a wrong one costs the caller's loop.
        bool linkSameRecord(const ElementType *p, ElementType tsq, size_t &rec) const
        {
            if constexpr (Lanes::n == 0) return false;
            else
            {
                typedef typename Lanes::V V;
                typedef typename Lanes::M M;
                const size_t P = pad_;
                if (P == 0) return false;
                const size_t r0 = hint_;
                const ElementType *c = wc_.data();
                const Tag *tg = wtag_.data();
                const V tv = V{} + tsq;
                // slot tags are 2 rec + 1 (slotTag), t0 is 2 r0: t ^ t0 has bit 0 set and other bits exactly when
                // the slot's record is not r0, so one OR of the linked lanes' t ^ t0 tells both "any" and "other"
                const M t0 = M{} + static_cast<Tag>(2 * r0);
                M acc{};
                for (size_t b = 0; b < P; b += Lanes::n)
                {
                    // squaredDistance's arithmetic, in its order, lane by lane (0 + d0^2 is d0^2)
                    V q;
                    std::memcpy(&q, c + b, sizeof q);
                    // q - p is -(p - q) exactly (rounding is symmetric): the same squares, and SSE2 computes it in place
                    V d = q - p[0];
                    V sq = d * d;
                    for (int k = 1; k < D; ++k)
                    {
                        std::memcpy(&q, c + static_cast<size_t>(k) * P + b, sizeof q);
                        d = q - p[k];
                        sq += d * d;
                    }
                    M t;
                    std::memcpy(&t, tg + b, sizeof t);
                    const M l = (M)(sq <= tv);   // a same-size bitcast: the compare's lane type varies by platform
                    acc |= l & (t ^ t0);
                }
                // the lanes' OR in 64-bit words (each lane's bit 0 stays bit 0 of its lane): two words, not n lanes
                std::uint64_t w[sizeof(M) / 8], a = 0;
                std::memcpy(w, &acc, sizeof w);
                for (std::uint64_t x : w) a |= x;
                constexpr std::uint64_t bit0 = sizeof(Tag) == 4 ? 0x0000000100000001u : 1u;
                if ((a & ~bit0) != 0) return false;
                rec = a != 0 ? r0 : none;
                return true;
            }
        }

        // Writes a window slot (its ring entry and its coordinate-array copy: NaN for a gap).
        void putSlot(size_t w, const VectorType &pt, size_t rec) const
        {
            wpts_[w] = pt;
            wrec_[w] = rec;
            if (pad_ == 0) return;
            for (int k = 0; k < D; ++k)
                wc_[static_cast<size_t>(k) * pad_ + w] = rec == none ? std::numeric_limits<ElementType>::quiet_NaN() : pt.data()[k];
            wtag_[w] = slotTag(rec);
        }

        void clearSlot(size_t w)
        {
            wrec_[w] = none;
            if (pad_ == 0) return;
            for (int k = 0; k < D; ++k) wc_[static_cast<size_t>(k) * pad_ + w] = std::numeric_limits<ElementType>::quiet_NaN();
            wtag_[w] = slotTag(none);
        }

        void setSlotRecord(size_t w, size_t rec)
        {
            wrec_[w] = rec;
            if (pad_ != 0) wtag_[w] = slotTag(rec);
        }

        // Tail mode: while the window is full and all in one cluster that has an alive list, the window points are
        // kept as the last step_ points of that list (lists_.tail), so that a point joining the cluster is one
        // push_back: no ring slot, no eviction. The list's points from tail_start_ on have the consecutive stream
        // indices tail_stream_, tail_stream_ + 1, ...; stream_ and the ring are stale meanwhile. untail() restores
        // the ring before anything else reads the window or the alive lists.
        void enterTail(size_t rec)
        {
            if constexpr (traced)
                return;
            Record &R = lists_.recs[rec];
            if (!R.has_alive || R.in_window != step_ || count_ != step_) return;
            std::vector<VectorType> &v = *R.list;
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
                putSlot(k, v[tail_start_ + left + k], rec);
                widx_[k] = tail_stream_ + left + k;
            }
            if (!R.contiguous)
                for (size_t k = 0; k < left; ++k) R.index.push_back(tail_stream_ + k);
            v.resize(tail_start_ + left);
            syncNext(R);
            head_ = 0;
            count_ = step_;
            stream_ = tail_stream_ + total;
            lists_.tail = nullptr;
            lists_.tail_rec = none;
        }

        // A map node out of the map; a copy is deep (a node handle cannot be copied: the copy is made in a map of
        // its own and extracted from it).
        struct ParkedNode
        {
            typename AliveMap::node_type nh;
            ParkedNode() = default;
            ParkedNode(const ParkedNode &o)
            {
                if (o.nh.empty()) return;
                AliveMap m;
                m.emplace(o.nh.key(), o.nh.mapped());
                nh = m.extract(m.begin());
            }
            ParkedNode(ParkedNode &&) noexcept = default;
            ParkedNode &operator=(const ParkedNode &o)
            {
                if (this != &o) *this = ParkedNode(o);
                return *this;
            }
            ParkedNode &operator=(ParkedNode &&) noexcept = default;
            ~ParkedNode() = default;
        };

        struct Record
        {
            size_t id = 0;
            size_t in_window = 0;
            // the alive list is a map node: in the alive map (`attached`, at `alive`) or parked in `park`, out of the
            // map until aliveClusters() asks for it, so that a cluster that opens and closes in between costs no
            // map insertion or removal; `list` is the node's vector either way (a node never moves)
            bool has_alive = false, attached = false;
            typename AliveMap::iterator alive;      // valid when has_alive && attached
            std::vector<VectorType> *list = nullptr;   // valid when has_alive
            ParkedNode park;                        // holds the node when has_alive && !attached
            // stream indices of the alive points, needed to merge interleaved clusters in stream order: implicitly
            // base, base + 1, ... while `contiguous` (always so for step 1), else listed in `index`
            bool contiguous = true;
            size_t base = 0;
            std::vector<size_t> index;
            // evictToAlive's test in one comparison: the stream index that extends the alive list contiguously
            // (base + its size) while has_alive && contiguous, else none (syncNext); stale in tail mode
            size_t next = none;
        };

        static void syncNext(Record &R) { R.next = R.has_alive && R.contiguous ? R.base + R.list->size() : none; }
        // recs grows by moves only: a copy would leave `list` pointing into the old parked nodes
        static_assert(std::is_nothrow_move_constructible<Record>::value, "IA_Segmenter: Record must move without copying");

        // The records and the alive map they point into. A copy re-points each record's iterator and list into the
        // copy's own map and parked nodes (the implicit copy would keep pointers into the source's); a move keeps
        // them, since the nodes move with it.
        struct ClusterLists
        {
            std::vector<Record> recs;
            AliveMap alive;
            size_t parked = 0;                                // records whose alive list is parked (not in `alive`)
            size_t tail_rec = none;                           // tail mode: the record whose list holds the window
            std::vector<VectorType> *tail = nullptr;          // its alive list (a map node: kept by moves)

            ClusterLists() = default;
            ClusterLists(const ClusterLists &o) : recs(o.recs), alive(o.alive), parked(o.parked), tail_rec(o.tail_rec) { repoint(); }
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
                    if (R.has_alive)
                    {
                        if (R.attached)
                        {
                            R.alive = alive.find(R.id);
                            R.list = &R.alive->second;
                        }
                        else R.list = &R.park.nh.mapped();
                    }
                tail = tail_rec == none ? nullptr : recs[tail_rec].list;
            }

            // Puts every parked alive list into the map (const for aliveClusters(): the members are mutable).
            void attachParked()
            {
                if (parked == 0) return;
                for (Record &R : recs)
                    if (R.has_alive && !R.attached)
                    {
                        R.alive = alive.insert(std::move(R.park.nh)).position;
                        R.attached = true;
                    }
                parked = 0;
            }
        };

        void checkParameters()
        {
            detail::checkParameters<ElementType>("IA_Segmenter::addPoint", lower_, upper_, true);
            if (scaling_ != scaling_) throw std::invalid_argument("IA_Segmenter::addPoint: the scaling must not be NaN");
            thr_ = detail::SquaredThreshold<ElementType>(scaling_, lower_, upper_);
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
            R.next = none;
            return r;
        }

        // step 1, the common case: the window is one point, and a point that joins its predecessor's cluster just
        // pushes the predecessor into the alive list.
        void addToPairWindow(const VectorType &pt, bool valid, ElementType rsq)
        {
            const size_t prev = wrec_[0];
            if constexpr (traced)
                if (observer_ && valid && prev != none)
                    reportComparison(stream_, stream_ - 1, detail::squaredDistance<D>(pt.data().data(), wpts_[0].data().data()), thr_(rsq));
            if (valid && prev != none && detail::squaredDistance<D>(pt.data().data(), wpts_[0].data().data()) <= thr_(rsq))
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
                newAliveList(R);
                R.contiguous = true;
                R.base = idx;
                R.index.clear();
            }
            std::vector<VectorType> &v = *R.list;
            if (R.contiguous && idx != R.base + v.size()) listIndices(R);
            if (!R.contiguous) R.index.push_back(idx);
            v.push_back(p);
            syncNext(R);
        }

        // Alive lists are map nodes handed back and forth with extract/insert, so that a cluster that gets an alive
        // list costs no allocation once the pool holds nodes (an emptied node keeps its list's capacity). A pooled
        // node is parked in the record, out of the map (see Record); a new one goes straight into the map.
        void newAliveList(Record &R)
        {
            std::vector<typename AliveMap::node_type> &pool = node_pool_.nodes;
            R.has_alive = true;
            if (pool.empty())
            {
                R.alive = lists_.alive.emplace_hint(lists_.alive.end(), R.id, std::vector<VectorType>());   // ids grow
                R.attached = true;
                R.list = &R.alive->second;
                return;
            }
            R.park.nh = std::move(pool.back());
            pool.pop_back();
            R.park.nh.key() = R.id;
            R.attached = false;
            R.list = &R.park.nh.mapped();
            ++lists_.parked;
        }

        // Takes R's alive list out of the map (or out of its parking place): R.has_alive is false afterwards.
        typename AliveMap::node_type takeAliveList(Record &R)
        {
            R.has_alive = false;
            R.next = none;
            if (R.attached) return lists_.alive.extract(R.alive);
            --lists_.parked;
            return std::move(R.park.nh);
        }

        // Keeps at most step + 2 spare nodes: never more than step + 1 clusters are alive at once.
        void dropAliveList(Record &R)
        {
            typename AliveMap::node_type nh = takeAliveList(R);
            if (node_pool_.nodes.size() >= step_ + 2) return;
            nh.mapped().clear();
            node_pool_.nodes.push_back(std::move(nh));
        }

        static size_t indexAt(const Record &R, size_t k) { return R.contiguous ? R.base + k : R.index[k]; }

        static void listIndices(Record &R)
        {
            if (!R.contiguous) return;
            const size_t n = R.list->size();
            R.index.resize(n);
            for (size_t k = 0; k < n; ++k) R.index[k] = R.base + k;
            R.contiguous = false;
            R.next = none;
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
            clearSlot(slot);
            Record &R = lists_.recs[r];
            if (!R.has_alive && R.in_window == 1)
            {
                // the cluster closes with this point and never had an alive list: skip the alive map
                closed_.emplace_back(1, wpts_[slot]);
                ++closed_left_;
                if constexpr (traced) report(ia_trace::Close{R.id, 1});
                R.in_window = 0;
                free_.push_back(r);
                return;
            }
            const size_t idx = step_ == 1 ? stream_ - 1 : widx_[slot];
            pushAlive(R, wpts_[slot], idx);
            std::vector<VectorType> &v = *R.list;
            if (--R.in_window == 0)
            {
                // hand out an exact-size copy and keep the alive list's capacity for the next cluster: growing
                // vectors from scratch (and faulting in their pages) would cost more than the copy
                closed_.emplace_back(v.begin(), v.end());
                ++closed_left_;
                if constexpr (traced) report(ia_trace::Close{R.id, v.size()});
                dropAliveList(R);
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
            detail::traceDistances(static_cast<double>(dsq), static_cast<double>(tsq), linked, distance, threshold);
            (*observer_)(ia_trace::Compare{i, j, distance, threshold, linked});
        }

        // Merges two clusters that both have window points; the older id survives. Returns the survivor's record.
        size_t merge(size_t a, size_t b)
        {
            const size_t keep = lists_.recs[a].id < lists_.recs[b].id ? a : b, gone = keep == a ? b : a;
            for (size_t w = 0; w < step_; ++w)
                if (wrec_[w] == gone) setSlotRecord(w, keep);
            Record &K = lists_.recs[keep], &G = lists_.recs[gone];
            K.in_window += G.in_window;
            if (G.has_alive)
            {
                if (!K.has_alive)
                {
                    // G's node becomes K's, parked (K is older: a smaller key)
                    K.park.nh = takeAliveList(G);
                    K.park.nh.key() = K.id;
                    K.has_alive = true;
                    K.attached = false;
                    K.list = &K.park.nh.mapped();
                    ++lists_.parked;
                    K.contiguous = G.contiguous;
                    K.base = G.base;
                    K.index.swap(G.index);
                }
                else
                {
                    mergeAlive(K, G);
                    dropAliveList(G);
                }
                syncNext(K);
            }
            G.in_window = 0;
            free_.push_back(gone);
            return keep;
        }

        // Moves G's alive points into K's, in stream order. Only the part of K newer than G's oldest point moves:
        // the cost is O(|G| + that part), not O(|K|).
        static void mergeAlive(Record &K, Record &G)
        {
            std::vector<VectorType> &kp = *K.list, &gp = *G.list;
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
            // coordinate arrays for linkSameRecord: step rounded up to whole blocks of NaN-padded lanes; none at
            // step 1 (its own path) or beyond 2^30 (slotTag needs record indices < 2^31: there are at most step + 1)
            pad_ = lanes != 0 && step > 1 && step <= (size_t(1) << 30) ? (step + lanes - 1) / lanes * lanes : 0;
            wc_.assign(static_cast<size_t>(D) * pad_, std::numeric_limits<ElementType>::quiet_NaN());
            wtag_.assign(pad_, slotTag(none));
            for (size_t w = 0; w < count_ && pad_ != 0; ++w) putSlot(w, wpts_[w], wrec_[w]);
        }

        ElementType lower_ = ElementType(0), upper_ = std::numeric_limits<ElementType>::infinity();
        ElementType scaling_ = detail::circularScaling<ElementType>(1, 360);
        bool checked_ = false;                                    // parameters validated since the last setter
        detail::SquaredThreshold<ElementType> thr_{0, 0, 0};

        // window: a ring of step_ slots, count_ of them used, head_ the oldest; wrec_ is none for gaps and free slots
        // (mutable: untail(), called by the const aliveClusters(), moves the window back into the ring)
        size_t step_ = 0;
        mutable size_t head_ = 0, count_ = 0;
        mutable std::vector<VectorType> wpts_;
        mutable std::vector<size_t> wrec_, widx_;                 // widx_ unused at step 1: its point is stream_ - 1
        // the window again, per coordinate (wc_[k * pad_ + slot]; NaN for gaps, free and padding slots), and the
        // slots' records as same-width integers, so that linkSameRecord vectorises
        typedef detail::WindowLanes<ElementType> Lanes;
        typedef typename Lanes::Tag Tag;
        static constexpr size_t lanes = Lanes::n;
        // linkSameRecord's tag of a slot's record: odd, distinct for distinct records (record indices < 2^31)
        static Tag slotTag(size_t rec) { return static_cast<Tag>(2 * rec + 1); }

        size_t pad_ = 0;
        size_t hint_ = none;   // linkSameRecord's guess: the record of the last valid point
        mutable std::vector<ElementType> wc_;
        mutable std::vector<Tag> wtag_;

        mutable ClusterLists lists_;
        mutable size_t tail_start_ = 0, tail_stream_ = 0;        // tail mode: see enterTail
        std::vector<size_t> free_;
        // closing order; the last closed_left_ are not handed out yet (a count, so that closedClustersAvailable(),
        // called after every point, is one load)
        std::vector<std::vector<VectorType>> closed_;
        size_t closed_left_ = 0;
        // emptied alive-list nodes, capacity kept; spare storage only, so a copy starts without any
        struct NodePool
        {
            std::vector<typename AliveMap::node_type> nodes;
            NodePool() = default;
            NodePool(const NodePool &) {}
            NodePool(NodePool &&) noexcept = default;
            NodePool &operator=(const NodePool &) { return *this; }
            NodePool &operator=(NodePool &&) noexcept = default;
            ~NodePool() = default;
        };
        NodePool node_pool_;
        size_t next_id_ = 0;
        mutable size_t stream_ = 0;
        Observer *observer_ = nullptr;
    };
}
