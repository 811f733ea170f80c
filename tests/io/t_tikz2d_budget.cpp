// Drawings beyond pdflatex's memory: the TikZ writer thins them to Drawing2D::texMarkLimit() mark
// equivalents with a note in the picture, keeps drawings within it byte for byte, and throws std::length_error where
// nothing can be thinned; 1, 15,000 and ~3x the measured limit (9,000 dot marks) of scan points with clusters and
// segments compile with the real pdflatex (one batched run) and the note is in the PDF.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "rtl/io/LaTeXDoc.h"
#include "rtl/io/LaTeXTikz2D.h"
#include "../../wasm/src/scan_drawing.h"
#include "pdflatex_run.h"

namespace fs = std::filesystem;
using rtl::Drawing2D;
using rtl::LaTeXTikz2D;
using rtl::Vector2f;

namespace
{
    std::string tikz(const Drawing2D &d)
    {
        std::ostringstream os;
        rtl::writeTikzPicture(d, os);
        return os.str();
    }
    size_t count(const std::string &s, const std::string &what)
    {
        size_t n = 0;
        for (size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1))
            ++n;
        return n;
    }
    //! Mark calls, one a line: \MarkA{x}{y}{deg} ... (a scan has one mark per cluster colour: A..J, BA).
    size_t marks(const std::string &t) { return count(t, "\n\\Mark"); }
    const std::string note = "Thinned for pdflatex's memory";

    //! A scan of n points in a map frame (x around 1500, y around 800, in metres of a large map), clusters of 60
    //! points (every 7th cluster unlabelled) and one segment per cluster, drawn as the package draws it.
    void scan(Drawing2D &d, size_t n)
    {
        std::vector<double> xy;
        std::vector<int> labels;
        std::vector<double> segments;
        for (size_t i = 0; i < n; ++i)
        {
            double a = 6.283185307179586 * static_cast<double>(i) / static_cast<double>(n);
            double r = 20 + 5 * std::sin(7 * a);
            xy.push_back(1500 + r * std::cos(a));
            xy.push_back(800 + r * std::sin(a));
            size_t c = i / 60;
            labels.push_back(c % 7 == 6 ? -1 : static_cast<int>(c));
            if (i % 60 == 59)
                segments.insert(segments.end(), {xy[2 * (i - 59)], xy[2 * (i - 59) + 1], xy[2 * i], xy[2 * i + 1]});
        }
        rtl_ops::drawScan(d, xy.data(), n, labels.data(), segments.data(), segments.size() / 4,
                      "scan of " + std::to_string(n) + " points");
    }
    std::vector<Vector2f> spiral(size_t n)
    {
        std::vector<Vector2f> v;
        for (size_t i = 0; i < n; ++i)
        {
            float t = static_cast<float>(i) / static_cast<float>(n);
            v.emplace_back(10 * std::cos(6.28f * t) * (1 + t), 10 * std::sin(6.28f * t) * (1 + t));
        }
        return v;
    }
}

TEST(Tikz2DBudget, DrawingsWithinTheLimitAreWrittenAsBefore)
{
    // 7,000 marks and segments: below the limit the output does not depend on it (golden tests pin the bytes).
    LaTeXTikz2D d;
    scan(d, 7000);
    EXPECT_EQ(d.texMarkLimit(), Drawing2D::pdflatex_mark_limit);
    std::string limited = tikz(d);
    d.setTexMarkLimit(0);
    EXPECT_EQ(tikz(d), limited);
    EXPECT_EQ(marks(limited), 7000u);
    EXPECT_EQ(limited.find(note), std::string::npos);
    d.clearAll();   // clearAll restores the default limit
    EXPECT_EQ(d.texMarkLimit(), Drawing2D::pdflatex_mark_limit);
}

TEST(Tikz2DBudget, MarksBeyondTheLimitAreThinnedEvenlyWithANote)
{
    struct Case
    {
        size_t n, stride;
    };
    // 8,000 marks fit exactly; 15,000 need 1 in 2; 27,000 (3x the measured limit) 1 in 4 (27,000 / 8,000 = 3.4).
    for (Case c : {Case{8000, 1}, Case{8001, 2}, Case{15000, 2}, Case{27000, 4}})
    {
        LaTeXTikz2D d;
        d.addPlot(spiral(c.n), "", "draw=red", LaTeXTikz2D::latex_mark_cross);
        std::string t = tikz(d);
        size_t kept = (c.n + c.stride - 1) / c.stride;
        EXPECT_EQ(count(t, "\\MarkA{"), kept) << c.n;
        if (c.stride == 1)
        {
            EXPECT_EQ(t.find(note), std::string::npos) << c.n;
            continue;
        }
        std::string expected = note + ": 1 in " + std::to_string(c.stride) + " marks and line points drawn (" +
                               std::to_string(kept) + " of " + std::to_string(c.n) + " marks).";
        EXPECT_NE(t.find("yshift=-0.1cm] at (\\MinX,\\MinY) {" + expected + "};\n\\end{tikzpicture}"),
                  std::string::npos) << c.n;
        // The marks kept are every stride-th one: the first is the spiral's first point, the second its stride-th.
        std::ostringstream second;
        second << "\\MarkA{" << rtl::detail::number(spiral(c.n)[c.stride].x()) << "}";
        size_t first_mark = t.find("\\MarkA{10}{0}");
        EXPECT_NE(first_mark, std::string::npos);
        EXPECT_EQ(t.find("\\MarkA{", first_mark + 1), t.find(second.str(), first_mark + 1)) << c.n;
    }
}

TEST(Tikz2DBudget, ScanClustersAreThinnedAcrossTheirOneMarkPlots)
{
    // drawScan makes one plot per point: the count runs over the whole drawing, so 1 in 2 of 15,000 is 7,500 and
    // every cluster keeps about half of its points; segments and the title are kept.
    LaTeXTikz2D d;
    scan(d, 15000);
    std::string t = tikz(d);
    EXPECT_EQ(marks(t), 7500u);
    EXPECT_NE(t.find(note + ": 1 in 2 marks and line points drawn (7500 of 15000 marks)."), std::string::npos);
    EXPECT_NE(t.find("{scan of 15000 points}"), std::string::npos);
    size_t edges = count(t, ") -- (");
    EXPECT_EQ(edges, 250u);   // one per cluster of 60
}

TEST(Tikz2DBudget, LongPolylinesAreThinnedKeepingTheirEnds)
{
    // 100,000 points count 12,500 marks: 1 in 2 points, and the last one is kept.
    LaTeXTikz2D d;
    std::vector<Vector2f> v = spiral(100001);
    d.addPlot(v, "draw=black");
    std::string t = tikz(d);
    EXPECT_EQ(count(t, " -- ("), 50000u);   // 50,001 points (paths of 500 share their joints: one " -- " each)
    std::string last = rtl::detail::tikzPoint(v.back().x(), v.back().y());
    EXPECT_NE(t.find("(" + last + ");\n"), std::string::npos);
    EXPECT_NE(t.find(note + ": 1 in 2 marks and line points drawn (0 of 0 marks)."), std::string::npos);
}

TEST(Tikz2DBudget, TooManyFixedPrimitivesThrowLengthErrorBeforeWriting)
{
    // 17,000 edges count 8,500 marks and cannot be thinned; with the limit off they are written.
    LaTeXTikz2D d;
    for (int i = 0; i < 17000; ++i)
        d.addLine(Vector2f(0, static_cast<float>(i)), Vector2f(1, static_cast<float>(i)), "draw=black");
    std::ostringstream os;
    EXPECT_THROW(rtl::writeTikz(d, os), std::length_error);
    EXPECT_TRUE(os.str().empty());
    try
    {
        d.writeTEX(os);
        ADD_FAILURE() << "no std::length_error";
    }
    catch (const std::length_error &e)
    {
        EXPECT_NE(std::string(e.what()).find("17000 primitives"), std::string::npos) << e.what();
    }
    d.setTexMarkLimit(0);
    EXPECT_EQ(count(tikz(d), "\\draw[StyleA]"), 17000u);
    // 15,000 edges fit (7,500) and leave room for 500 marks: 3,000 marks are thinned 1 in 6.
    LaTeXTikz2D e;
    for (int i = 0; i < 15000; ++i)
        e.addLine(Vector2f(0, static_cast<float>(i)), Vector2f(1, static_cast<float>(i)), "draw=black");
    e.addPlot(spiral(3000), "", "draw=red", LaTeXTikz2D::latex_mark_dot);
    std::string t = tikz(e);
    EXPECT_EQ(count(t, "\\MarkA{"), 500u);
    EXPECT_EQ(count(t, "\\draw[StyleA]"), 15000u);
}

//! One pdflatex run, one page each: a one-point scan, 15,000 points and 27,000 points (about 3x the measured limit)
//! with clusters and segments. Each must compile, and the thinned ones must carry the note.
TEST(Tikz2DBudget, ThinnedScansCompileWithPdflatex)
{
    ASSERT_TRUE(rtl::LaTeXDoc::pdflatexAvailable()) << "pdflatex is not on PATH (./run test installs TeX Live)";
    std::vector<std::string> pictures;
    for (size_t n : {1u, 15000u, 27000u})
    {
        LaTeXTikz2D d;
        scan(d, n);
        pictures.push_back(tikz(d));
    }
    EXPECT_EQ(pictures[0].find(note), std::string::npos);
    EXPECT_NE(pictures[1].find(note + ": 1 in 2 marks and line points drawn (7500 of 15000 marks)."),
              std::string::npos);
    EXPECT_NE(pictures[2].find(note + ": 1 in 4 marks and line points drawn (6750 of 27000 marks)."),
              std::string::npos);

    fs::path dir = fs::path(RTL_TEST_OUTPUT_DIR) / "latex" / "budget2d";
    fs::remove_all(dir);
    fs::create_directories(dir);
    pdflatex_test::writePreviewDocument(dir, "budget", pictures);
    const auto run = pdflatex_test::compile(dir, "budget");
    ASSERT_EQ(run.rc, 0) << run.failure();
    EXPECT_NE(run.log.find("Output written on budget.pdf (3 pages"), std::string::npos);
    // The note is text on pages 2 and 3, not on page 1.
    ASSERT_EQ(pdflatex_test::extractText(dir, "budget"), 0) << "pdftotext (poppler-utils) is needed to read the PDF";
    const std::string text = pdflatex_test::readFile(dir / "budget.txt");
    EXPECT_EQ(count(text, "Thinned for pdflatex"), 2u) << text;
    EXPECT_NE(text.find("(7500 of 15000 marks)"), std::string::npos) << text;
    EXPECT_NE(text.find("(6750 of 27000 marks)"), std::string::npos) << text;
    EXPECT_LT(text.find("scan of 1 points"), text.find("Thinned for pdflatex"));
}
