// Trace events of the incremental TLS vectorizers (ITLS, 2D and 3D) and of the point-elimination vectorizers
// (Douglas-Peucker, Reumann-Witkam, any dimension), for rtl::TraceLog (see rtl/core/Trace.h).
//
// Indices are point indices of the input chain; ranges are half-open [first, end) as in indices(). Distances and
// RMS values are in the input's units, computed in double. Replays (each ends in the state the call returns):
//  - ITLS: ranges = []; each `close` appends {first, end}; a `tail` truncates the list to `kept` ranges and the
//    `tailRange` events after it append the new last ranges. The `segment` events then list every final range with
//    its trimmed line segment: they equal indices() and lineSegments() exactly.
//  - DP: kept = {0, count - 1} (from `start`); each `range` with split = true adds `farthest`. Sorted, kept is the
//    list of polyline vertices (the output's segments run between consecutive kept points).
//  - RW: kept = the `keep` events' indices in order (the polyline vertices).
// Nothing is reported for a call that fails its preconditions (fewer than 2 points, invalid sigma, a non-finite
// point for ITLS); then the result is empty, as the empty replay.
#pragma once

#include <cstddef>

#include "rtl/core/Trace.h"

namespace rtl
{
    // ---- Incremental TLS (VectorizerITLSProjections2D/3D, ExtractorChainIncremental) ----

    //! A call begins: `count` points, the RMS bound `sigma`.
    struct ItlsStart
    {
        static constexpr const char *kind = "start";
        size_t count; double sigma;
        template<class F> void fields(F &&f) const { f("count", count); f("sigma", sigma); }
    };

    //! Point `index` joined the running range that starts at `first` (now `count` points). `rms` is the root mean
    //! squared orthogonal residual of the fit of those points. `tested`: ranges of 3 and more points are tested
    //! against sigma (1 or 2 points always fit). `fits` = !tested || rms < sigma; when false the point is taken
    //! out again and a `close` follows (then the point starts the next range).
    struct ItlsAdd
    {
        static constexpr const char *kind = "add";
        size_t index, first, count; double rms, sigma; bool tested, fits;
        template<class F> void fields(F &&f) const
        {
            f("index", index); f("first", first); f("count", count); f("rms", rms); f("sigma", sigma);
            f("tested", tested); f("fits", fits);
        }
    };

    //! Range [first, end) is closed with RMS `rms`. Either the next point (index `end`) would lift the RMS to
    //! `rmsWithNext` >= sigma (atEnd false), or the chain ended (atEnd true, rmsWithNext NaN).
    struct ItlsClose
    {
        static constexpr const char *kind = "close";
        size_t first, end; double rms, rmsWithNext, sigma; bool atEnd;
        template<class F> void fields(F &&f) const
        {
            f("first", first); f("end", end); f("rms", rms); f("rmsWithNext", rmsWithNext); f("sigma", sigma);
            f("atEnd", atEnd);
        }
    };

    //! How the last point, left alone when the chain ended, was placed (ItlsTail::method).
    enum ItlsTailMethod : int
    {
        itlsTailLeftOut = 0,       //!< no partition of the tail within sigma: the point stays out (indices end at N - 1)
        itlsTailAppended = 1,      //!< appended to the last range (it still fits)
        itlsTailLastSplit = 2,     //!< the last range gives up its last point: the final two points pair up
        itlsTailPrevGrown = 3,     //!< the previous range takes a point: [.., N - 2) [N - 2, N)
        itlsTailPrevShrunk = 4,    //!< the previous range gives up a point: [.., N - 4) [N - 4, N - 2) [N - 2, N)
        itlsTailRepartitioned = 5  //!< the last ranges re-partitioned into the fewest ranges within sigma
    };

    //! The single last point `index` is placed by `method` (ItlsTailMethod): the first `kept` ranges stay, the
    //! `tailRange` events that follow replace the rest.
    struct ItlsTail
    {
        static constexpr const char *kind = "tail";
        size_t index, kept; int method;
        template<class F> void fields(F &&f) const { f("index", index); f("kept", kept); f("method", method); }
    };

    //! A range [first, end) of the repaired tail, with its RMS.
    struct ItlsTailRange
    {
        static constexpr const char *kind = "tailRange";
        size_t first, end; double rms;
        template<class F> void fields(F &&f) const { f("first", first); f("end", end); f("rms", rms); }
    };

    //! Final range number `range` = [first, end) and its line segment, trimmed by the projections of the range's
    //! first and last point: from (x0, y0[, z0]) to (x1, y1[, z1]); z only when dimensions == 3.
    struct ItlsSegment
    {
        static constexpr const char *kind = "segment";
        size_t range, first, end; int dimensions; double x0, y0, z0, x1, y1, z1;
        template<class F> void fields(F &&f) const
        {
            f("range", range); f("first", first); f("end", end);
            f("x0", x0); f("y0", y0);
            if (dimensions == 3) f("z0", z0);
            f("x1", x1); f("y1", y1);
            if (dimensions == 3) f("z1", z1);
        }
    };

    typedef TraceLog<ItlsStart, ItlsAdd, ItlsClose, ItlsTail, ItlsTailRange, ItlsSegment> ItlsTraceLog;

    // ---- Douglas-Peucker (VectorizerDouglasPeuckerND) ----

    //! A call begins: `count` points, tolerance `epsilon`; points 0 and count - 1 are kept.
    struct DpStart
    {
        static constexpr const char *kind = "start";
        size_t count; double epsilon;
        template<class F> void fields(F &&f) const { f("count", count); f("epsilon", epsilon); }
    };

    //! Range [first, last] (inclusive; ranges with interior points only, in the recursion's order: depth first, the
    //! left part before the right) is examined: `farthest` is the first interior point farthest from the line
    //! through points first and last (the distance to point first if they coincide), at `distance`. split =
    //! distance > epsilon: farthest is kept and [first, farthest], [farthest, last] are examined next. Points with
    //! a non-finite coordinate are never farthest; without a finite interior point, farthest = first, distance 0.
    //! The distance is computed in double; the split is the vectorizer's own decision (in its element type).
    struct DpRange
    {
        static constexpr const char *kind = "range";
        size_t first, last, farthest; double distance, epsilon; bool split;
        template<class F> void fields(F &&f) const
        {
            f("first", first); f("last", last); f("farthest", farthest); f("distance", distance);
            f("epsilon", epsilon); f("split", split);
        }
    };

    typedef TraceLog<DpStart, DpRange> DpTraceLog;

    // ---- Reumann-Witkam (VectorizerReumannWitkamND) ----

    //! A call begins: `count` points, strip half-width `epsilon`.
    struct RwStart
    {
        static constexpr const char *kind = "start";
        size_t count; double epsilon;
        template<class F> void fields(F &&f) const { f("count", count); f("epsilon", epsilon); }
    };

    //! Point `index` is kept (a polyline vertex): point 0, each key point, and the last point.
    struct RwKeep
    {
        static constexpr const char *kind = "keep";
        size_t index;
        template<class F> void fields(F &&f) const { f("index", index); }
    };

    //! A strip of half-width `epsilon` around the line from key point `key` through point `through`; the scan
    //! continues at point `through` + 1.
    struct RwStrip
    {
        static constexpr const char *kind = "strip";
        size_t key, through; double epsilon;
        template<class F> void fields(F &&f) const { f("key", key); f("through", through); f("epsilon", epsilon); }
    };

    //! Point `index` lies outside the strip of key point `key`, at `distance` > epsilon from its axis (the line
    //! through the strip's key and through points, computed in double; the vectorizer decides in its element type,
    //! so in float the two may differ by rounding right at epsilon); the point before it (index - 1) becomes the
    //! next key (a `keep` and a new `strip` follow). Points between the strip's through point and `index` lie
    //! inside it.
    struct RwExit
    {
        static constexpr const char *kind = "exit";
        size_t index, key; double distance, epsilon;
        template<class F> void fields(F &&f) const
        {
            f("index", index); f("key", key); f("distance", distance); f("epsilon", epsilon);
        }
    };

    typedef TraceLog<RwStart, RwKeep, RwStrip, RwExit> RwTraceLog;
}
