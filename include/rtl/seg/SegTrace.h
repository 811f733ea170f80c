// The steps of CAR_Segmenter and IA_Segmenter, as events for an observer (core/Trace.h): what each segmenter
// actually does, in order, so that a teaching tool can replay it and a test can check it.
//
//     rtl::CarTraceLog log;
//     rtl::CAR_Segmenter<rtl::Vector2f, rtl::CarTraceLog> car(3, 0.05f, 0.5f);
//     car.setObserver(&log);
//     car.loadData(points);            // log.events: car_trace::Scan, Threshold, Compare, Link, ..., Cluster
//
// Indices are scan (CAR) or stream (IA) indices of points; distances and thresholds are in the points' units, as
// doubles. In every Compare/Seam event, linked == (distance <= threshold), the test the segmenter made (it compares
// squared values; distance and threshold are their square roots, reported so that they compare the same way).
//
// CAR replay (one loadData): start with no point in a cluster. Start{i} puts i in a new cluster labelled i;
// Link{i, j, cluster} puts i in cluster `cluster` (j's); Merge{from, into} relabels every point of cluster `from`
// as `into` (labels are always the smallest index of the cluster). The Cluster events at the end list the returned
// clusters in grabCluster() order, each with its label, first point and size: the labels then held by the replay
// are exactly the returned clusters.
//
// IA replay (any sequence of addPoint, setStepSize, flush): keep the window (stream indices, each with its cluster
// id or none for gaps), the alive map (id -> stream indices in stream order) and the closed list. Add{i} puts i in
// the window; Open/Link give it a cluster; Merge{from, into} renames `from` to `into` in the window and merges the
// alive lists in stream order; Slide{i} removes i from the window; Alive{i, cluster} appends i to the cluster's
// alive list; Close{cluster} moves the cluster's alive list to the end of the closed list. The replayed alive map
// equals aliveClusters() and the closed list the clusters grabCluster() hands out, in order.
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>

#include "rtl/core/Trace.h"

namespace rtl
{
    //! The events CAR_Segmenter and IA_Segmenter share, the same steps of the same test (car_trace and ia_trace
    //! name them too). Indices are scan (CAR) or stream (IA) indices.
    namespace seg_trace
    {
        //! Point i's threshold: range = |p_i - origin|, raw = scaling * range, threshold = raw clamped to the
        //! segmenter's bounds (the radius of the circle around p_i within which an earlier point is close).
        struct Threshold
        {
            static constexpr const char *kind = "threshold";
            size_t i;
            double range, raw, threshold;
            template<class F> void fields(F &&f) const
            {
                f("i", i); f("range", range); f("raw", raw); f("threshold", threshold);
            }
        };

        //! Point i compared with an earlier point j of its window (CAR: the step - 1 previous scan points; IA: the
        //! step previous stream points; gaps are never compared). linked: distance <= i's threshold. A linked j
        //! already in i's cluster changes nothing.
        struct Compare
        {
            static constexpr const char *kind = "compare";
            size_t i, j;
            double distance, threshold;
            bool linked;
            template<class F> void fields(F &&f) const
            {
                f("i", i); f("j", j); f("distance", distance); f("threshold", threshold); f("linked", linked);
            }
        };

        //! Point i joins the cluster of j (`cluster`: CAR's label, the cluster's smallest scan index; IA's cluster
        //! id): its first linked comparison.
        struct Link
        {
            static constexpr const char *kind = "link";
            size_t i, j, cluster;
            template<class F> void fields(F &&f) const { f("i", i); f("j", j); f("cluster", cluster); }
        };

        //! Point i, already in a cluster, is linked to j of another cluster: cluster `from` merges into `into`
        //! retroactively. CAR: every point of `from` is relabelled, the smaller label survives (into < from); also
        //! emitted by CAR's seam pass. IA: the older id survives, window and alive points included, alive points
        //! kept in stream order.
        struct Merge
        {
            static constexpr const char *kind = "merge";
            size_t i, j, from, into;
            template<class F> void fields(F &&f) const { f("i", i); f("j", j); f("from", from); f("into", into); }
        };
    }

    namespace car_trace
    {
        //! loadData starts: the scan's size, the step, the window (step - 1 previous points), the threshold scaling
        //! step * 2 pi / size and the bounds it is clamped to.
        struct Scan
        {
            static constexpr const char *kind = "scan";
            size_t size, step, window;
            double scaling, lowerBound, upperBound;
            template<class F> void fields(F &&f) const
            {
                f("size", size); f("step", step); f("window", window);
                f("scaling", scaling); f("lowerBound", lowerBound); f("upperBound", upperBound);
            }
        };

        //! Point i has a non-finite coordinate: it is a gap, in no cluster, never compared.
        struct Gap
        {
            static constexpr const char *kind = "gap";
            size_t i;
            template<class F> void fields(F &&f) const { f("i", i); }
        };

        using seg_trace::Threshold;
        using seg_trace::Compare;
        using seg_trace::Link;
        using seg_trace::Merge;

        //! Point i is close to no earlier point of its window: it starts a new cluster, labelled i.
        struct Start
        {
            static constexpr const char *kind = "start";
            size_t i;
            template<class F> void fields(F &&f) const { f("i", i); }
        };

        //! Seam pass, after the whole scan: point i among the first step - 1 compared with point j among the last,
        //! i + size - j <= step - 1 places apart across the seam, with i's threshold. A linked pair in different
        //! clusters is followed by a Merge.
        struct Seam
        {
            static constexpr const char *kind = "seam";
            size_t i, j;
            double distance, threshold;
            bool linked;
            template<class F> void fields(F &&f) const
            {
                f("i", i); f("j", j); f("distance", distance); f("threshold", threshold); f("linked", linked);
            }
        };

        //! One returned cluster, in grabCluster() order (index 0, 1, ...): its label (smallest scan index), the scan
        //! index of its first point (the start of the end-of-scan part for a cluster that wraps the seam) and its
        //! number of points.
        struct Cluster
        {
            static constexpr const char *kind = "cluster";
            size_t index, label, first, size;
            template<class F> void fields(F &&f) const
            {
                f("index", index); f("label", label); f("first", first); f("size", size);
            }
        };
    }

    namespace ia_trace
    {
        //! Point i (stream index: 0 for the first point ever added) enters the window; gap: a non-finite coordinate,
        //! it takes a window place but joins no cluster and is never compared.
        struct Add
        {
            static constexpr const char *kind = "add";
            size_t i;
            bool gap;
            template<class F> void fields(F &&f) const { f("i", i); f("gap", gap); }
        };

        using seg_trace::Threshold;
        using seg_trace::Compare;
        using seg_trace::Link;
        using seg_trace::Merge;

        //! Point i is close to no window point: it opens a new cluster with id `cluster` (ids grow from 0).
        struct Open
        {
            static constexpr const char *kind = "open";
            size_t i, cluster;
            template<class F> void fields(F &&f) const { f("i", i); f("cluster", cluster); }
        };

        //! The oldest window point i leaves the window (the window is full, shrinks, or is flushed). A gap leaves
        //! without a trace elsewhere; a valid point is followed by Alive.
        struct Slide
        {
            static constexpr const char *kind = "slide";
            size_t i;
            bool gap;
            template<class F> void fields(F &&f) const { f("i", i); f("gap", gap); }
        };

        //! Point i, out of the window, is appended to the alive list of its cluster.
        struct Alive
        {
            static constexpr const char *kind = "alive";
            size_t i, cluster;
            template<class F> void fields(F &&f) const { f("i", i); f("cluster", cluster); }
        };

        //! Cluster `cluster` has no point left in the window: it closes, with `size` points, and moves from the alive
        //! map to the end of the closed queue (grabCluster() order).
        struct Close
        {
            static constexpr const char *kind = "close";
            size_t cluster, size;
            template<class F> void fields(F &&f) const { f("cluster", cluster); f("size", size); }
        };
    }

    namespace detail
    {
        //! The distance and threshold reported for a comparison of squared values (linked = dsq <= tsq): their square
        //! roots, with the distance nudged above the threshold in the rare case that the square roots of two
        //! different squares round to the same double, so that linked == (distance <= threshold) always holds.
        inline void traceDistances(double dsq, double tsq, bool linked, double &distance, double &threshold)
        {
            threshold = std::sqrt(tsq);
            distance = std::sqrt(dsq);
            if (linked && distance > threshold) distance = threshold;
            if (!linked && !(distance > threshold)) distance = std::nextafter(threshold, std::numeric_limits<double>::infinity());
        }
    }

    //! Records every step of CAR_Segmenter: CAR_Segmenter<Vector, CarTraceLog>.
    typedef TraceLog<car_trace::Scan, car_trace::Gap, car_trace::Threshold, car_trace::Compare, car_trace::Link,
                     car_trace::Merge, car_trace::Start, car_trace::Seam, car_trace::Cluster>
        CarTraceLog;

    //! Records every step of IA_Segmenter: IA_Segmenter<Vector, IaTraceLog>.
    typedef TraceLog<ia_trace::Add, ia_trace::Threshold, ia_trace::Compare, ia_trace::Link, ia_trace::Merge,
                     ia_trace::Open, ia_trace::Slide, ia_trace::Alive, ia_trace::Close>
        IaTraceLog;
}
