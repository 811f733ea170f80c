// Checks shared by the ScanPolylines2D tests: the real scan excerpts of tests/data, and the budget property that a
// larger vertex budget never gives a worse map (the score never rises as J grows over every budget).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "rtl/Core.h"
#include "rtl/io/CarmenLog.h"
#include "rtl/vect/ScanPolylines2D.h"

namespace scan_polylines_checks
{
    using Scan = std::vector<rtl::VectorND<2, double>>;

    //! Every scan of the CARMEN log `file` in tests/data, as beam end points (NaN = no return).
    inline std::vector<Scan> excerptScans(const char *file)
    {
        std::vector<Scan> out;
        for (auto &s : rtl::readCarmenLogFile<double>(std::string(RTL_TEST_DATA_DIR) + "/" + file)) out.push_back(std::move(s.points));
        return out;
    }

    //! Runs `ex` on `scan` at every budget J = 2 … lastJ in turn and expects each map to use at most J vertices and to
    //! score no higher than the best smaller budget (relative tolerance 1e-9: only rounding, sums of a few hundred
    //! terms). `atBudget(J)`, when given, runs after budget J's checks (further checks at that budget). `where` names
    //! the case in failure messages. Call it inside ASSERT_NO_FATAL_FAILURE so that a failed run stops the test.
    inline void expectScoreNeverRisesWithBudget(rtl::ScanPolylines2D<double> &ex, const Scan &scan, std::size_t lastJ, const std::string &where,
                                                const std::function<void(std::size_t)> &atBudget = {})
    {
        double best = std::numeric_limits<double>::infinity();
        for (std::size_t J = 2; J <= lastJ; ++J)
        {
            ex.setMaxVertices(J);
            ASSERT_TRUE(ex(scan)) << where << " J " << J;
            EXPECT_LE(ex.score(), best * (1 + 1e-9)) << where << " J " << J;
            EXPECT_LE(ex.vertexCount(), J) << where << " J " << J;
            best = std::min(best, ex.score());
            if (atBudget) atBudget(J);
            if (::testing::Test::HasFatalFailure()) return;   // an assertion inside atBudget stops the run too
        }
    }
}
