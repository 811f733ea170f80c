// Trace events of the FTLS and AFTLS 2D vectorizers (VectorizerFTLSPolyline2D / VectorizerAFTLSPolyline2D with an
// Observer, e.g. rtl::FtlsTraceLog), for rtl::TraceLog (see rtl/core/Trace.h).
//
// Indices are point indices of the input chain; ranges are half-open [first, end) as in indices(). Errors are mean
// squared orthogonal residuals (meanSquaredError, compare with sigma^2) or totals of squared residuals, in double.
// `branch`: 0 = the FTLS partition, 1 = AFTLS's optimized partition (AFTLS keeps both until `choice`).
// Replay (ends in the state the call returns):
//   ranges[0] = []; each `range` (extraction) first drops the ranges that end after its `first` (the extractor's
//   tail re-partition re-does the last ranges), then appends {first, end}. After extraction AFTLS copies ranges[0]
//   to ranges[1] (`start` says aftls = true). A `repair` replaces, in ranges[branch], the ranges inside the chain
//   span [first, end) by the `inserted` `repairRange` events that follow it; a `move` (AFTLS, branch 1) moves the
//   boundary `breakpoint` (between ranges breakpoint - 1 and breakpoint) from `from` to `to`; `choice` names the
//   branch kept (without a `choice`, the result is ranges[0]: FTLS, or AFTLS when extraction itself failed and the
//   exact search, a `repair` of branch 0, decided). An `infeasible` event ends a strict call with no result
//   (ranges = []); in split mode a `repair` of branch 0 with method 6 (split search) follows it and gives the
//   result (several polylines); when no partition into fitting ranges exists at all, that repair has method 8
//   (cover search) instead, and its ranges, in chain order, may share one point with the next (end = next first
//   + 1); the replay is the same (the repair spans the whole chain). The `segment` events then list every final range with its polyline
//   segment: they equal indices(), polylineOffsets() and lineSegments() exactly.
// Nothing is reported for a call that fails its preconditions (fewer than 2 points, invalid sigma or delta, a
// non-finite point): the result is then empty, as the empty replay.
#pragma once

#include <cstddef>

#include "rtl/core/Trace.h"

namespace rtl
{
    //! A call begins: `count` points, sigma, delta; aftls: the optimizer runs (two branches); split: split mode.
    struct FtlsStart
    {
        static constexpr const char *kind = "start";
        size_t count; double sigma, delta; bool aftls, split;
        template<class F> void fields(F &&f) const
        {
            f("count", count); f("sigma", sigma); f("delta", delta); f("aftls", aftls); f("split", split);
        }
    };

    //! Phases of FtlsTrial: the whole remainder of the chain from `first`, the gallop (lengths 4, 8, 16, ...), the
    //! bisection between the last passing and the first failing end, the single-point-tail adjustment.
    enum FtlsTrialPhase : int { FtlsWholeRemainder = 0, FtlsGallop = 1, FtlsBisection = 2, FtlsTailAdjust = 3 };

    //! The extractor tried range [first, end): `meanSquaredError` of its TLS fit against sigma^2 (`sigma` given);
    //! pass = end - first == 2 or meanSquaredError < sigma^2 (decided as the extractor decides it). phase: FtlsTrialPhase.
    struct FtlsTrial
    {
        static constexpr const char *kind = "trial";
        size_t first, end; int phase; double meanSquaredError, sigma; bool pass;
        template<class F> void fields(F &&f) const
        {
            f("first", first); f("end", end); f("phase", phase); f("meanSquaredError", meanSquaredError);
            f("sigma", sigma); f("pass", pass);
        }
    };

    //! The extractor accepted range [first, end) (see the replay rule above).
    struct FtlsRange
    {
        static constexpr const char *kind = "range";
        size_t first, end;
        template<class F> void fields(F &&f) const { f("first", first); f("end", end); }
    };

    //! The continuity check of the corner between ranges `index` and `index` + 1 of `branch`, at chain index
    //! `boundary`: the lines cross `crossingDistance` from the midpoint of points boundary - 1 and boundary
    //! (+infinity: parallel); ok = crossingDistance <= delta.
    struct FtlsCorner
    {
        static constexpr const char *kind = "corner";
        int branch; size_t index, boundary; double crossingDistance, delta; bool ok;
        template<class F> void fields(F &&f) const
        {
            f("branch", branch); f("index", index); f("boundary", boundary); f("crossingDistance", crossingDistance);
            f("delta", delta); f("ok", ok);
        }
    };

    //! Repair methods of FtlsRepair.
    enum FtlsRepairMethod : int
    {
        FtlsMoveBoundary = 1, FtlsMerge = 2, FtlsThirds = 3, FtlsWindow = 4, FtlsExactSearch = 5, FtlsSplitSearch = 6,
        FtlsBridge = 7, FtlsCoverSearch = 8
    };

    //! A repair of `branch` replaced the ranges inside the chain span [first, end) by the `inserted` ranges of the
    //! `repairRange` events that follow. method: FtlsRepairMethod (1 move the boundary, 2 merge, 3 three equal parts,
    //! 4 re-partition a window, 5 exact search over the whole chain, 6 split-mode search, 7 unchecked bridge,
    //! 8 split-mode cover whose consecutive ranges may share one point, when no partition exists at all).
    struct FtlsRepair
    {
        static constexpr const char *kind = "repair";
        int branch, method; size_t first, end, inserted;
        template<class F> void fields(F &&f) const
        {
            f("branch", branch); f("method", method); f("first", first); f("end", end); f("inserted", inserted);
        }
    };

    //! One range inserted by the preceding `repair`.
    struct FtlsRepairRange
    {
        static constexpr const char *kind = "repairRange";
        size_t first, end;
        template<class F> void fields(F &&f) const { f("first", first); f("end", end); }
    };

    //! AFTLS optimizer: boundary `breakpoint` moved from `from` to `to`; totalError = the total squared residual of
    //! the whole partition after the move.
    struct FtlsMove
    {
        static constexpr const char *kind = "move";
        size_t breakpoint, from, to; double totalError;
        template<class F> void fields(F &&f) const
        {
            f("breakpoint", breakpoint); f("from", from); f("to", to); f("totalError", totalError);
        }
    };

    //! AFTLS: total squared residuals of both branches (+infinity for a branch that found no valid result) and the
    //! branch kept (the lower; FTLS's only when strictly lower).
    struct FtlsChoice
    {
        static constexpr const char *kind = "choice";
        double ftlsError, aftlsError; int kept;
        template<class F> void fields(F &&f) const { f("ftlsError", ftlsError); f("aftlsError", aftlsError); f("kept", kept); }
    };

    //! Strict mode found no valid partition (proven by the exact search): the corner that cannot be met.
    struct FtlsInfeasible
    {
        static constexpr const char *kind = "infeasible";
        size_t boundary; double crossingDistance, delta;
        template<class F> void fields(F &&f) const
        {
            f("boundary", boundary); f("crossingDistance", crossingDistance); f("delta", delta);
        }
    };

    //! A final segment: range `index` = [first, end) of polyline `polyline`, from (x0, y0) to (x1, y1).
    struct FtlsSegment
    {
        static constexpr const char *kind = "segment";
        size_t index, first, end, polyline; double x0, y0, x1, y1;
        template<class F> void fields(F &&f) const
        {
            f("index", index); f("first", first); f("end", end); f("polyline", polyline);
            f("x0", x0); f("y0", y0); f("x1", x1); f("y1", y1);
        }
    };

    //! A TraceLog of every FTLS/AFTLS event.
    typedef TraceLog<FtlsStart, FtlsTrial, FtlsRange, FtlsCorner, FtlsRepair, FtlsRepairRange, FtlsMove, FtlsChoice,
                     FtlsInfeasible, FtlsSegment> FtlsTraceLog;
}
