// 3D scenes beyond pdflatex's memory: LaTeXTikz3D writes every k-th mark with a note above
// texMarkLimit(), scenes within it byte for byte as before, and throws std::length_error before writing anything when
// the lines, axes and faces alone exceed it; a scene of 12,000 dot marks (10,000 compiled, 11,000 failed with "TeX
// capacity exceeded" before) compiles with the real pdflatex and the note is in the PDF.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "rtl/io/LaTeXDoc.h"
#include "rtl/io/LaTeXTikz3D.h"
#include "pdflatex_run.h"

namespace fs = std::filesystem;
using rtl::LaTeXTikz3D;
using rtl::Vector3f;

namespace
{
    const std::string note = "Thinned for pdflatex's memory";

    size_t count(const std::string &s, const std::string &what)
    {
        size_t n = 0;
        for (size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1))
            ++n;
        return n;
    }
    std::string tikz(LaTeXTikz3D &t)
    {
        std::ostringstream os;
        t.writeTikz(os);
        return os.str();
    }
    //! Mark i of n on a rising helix inside the min region [-12, 12]^2 x [-1, 12], so that the rendered region (and
    //! the camera) does not depend on which marks are present.
    Vector3f helix(size_t i, size_t n)
    {
        float a = 6.2831853f * static_cast<float>(i) / static_cast<float>(n);
        return {10 * std::cos(3 * a), 10 * std::sin(3 * a), 10 * static_cast<float>(i) / static_cast<float>(n)};
    }
    //! The scene: marks i < n with i % keep_every == 0, and `lines` lines along x.
    void scene(LaTeXTikz3D &t, size_t n, size_t keep_every = 1, size_t lines = 0)
    {
        t.setView(60, Vector3f(-1, -0.7f, -0.5f));
        t.setMinPlotRegion(Vector3f(-12, -12, -1), Vector3f(12, 12, 12));
        for (size_t i = 0; i < n; i += keep_every)
            t.addMark(helix(i, n), "fill=red", LaTeXTikz3D::latex_mark_dot, 0.0f, 0.5f);
        for (size_t i = 0; i < lines; ++i)
        {
            float y = -10 + 20 * static_cast<float>(i) / static_cast<float>(lines);
            t.addLine(rtl::LineSegment3f(Vector3f(-10, y, 0), Vector3f(10, y, 0)), "draw=black");
        }
    }
}

TEST(Tikz3DBudget, ScenesWithinTheLimitAreWrittenAsBefore)
{
    // 7,998 marks and 4 lines are exactly 8,000 mark equivalents: the output does not depend on the limit.
    LaTeXTikz3D t;
    scene(t, 7998, 1, 4);
    EXPECT_EQ(t.texMarkLimit(), rtl::Drawing2D::pdflatex_mark_limit);
    std::string limited = tikz(t);
    EXPECT_EQ(t.tikzString(), limited);   // the string forms (no stream; the package uses them)
    std::ostringstream doc;
    t.writeTEX(doc);
    EXPECT_EQ(t.texString(), doc.str());
    t.setTexMarkLimit(0);
    EXPECT_EQ(tikz(t), limited);
    EXPECT_EQ(count(limited, "\\MarkA{"), 7998u);
    EXPECT_EQ(limited.find(note), std::string::npos);
    t.clearAll();   // clearAll restores the default limit
    EXPECT_EQ(t.texMarkLimit(), rtl::Drawing2D::pdflatex_mark_limit);
}

TEST(Tikz3DBudget, MarksBeyondTheLimitAreThinnedEvenlyWithANote)
{
    struct Case
    {
        size_t n, lines, stride;
    };
    // 7,999 marks + 4 lines need 1 in 2; 27,000 marks 1 in 4 (27,000 / 8,000 = 3.4); 15,000 marks beside 4,000
    // lines (2,000) 1 in 3 (15,000 / 6,000 = 2.5).
    for (Case c : {Case{7999, 4, 2}, Case{27000, 0, 4}, Case{15000, 4000, 3}})
    {
        LaTeXTikz3D t;
        scene(t, c.n, 1, c.lines);
        std::string thinned = tikz(t);
        size_t kept = (c.n + c.stride - 1) / c.stride;
        std::string expected = "\\node[anchor=north west, yshift=-0.1cm] at (-5,-5) {" + note + ": 1 in " +
                               std::to_string(c.stride) + " marks drawn (" + std::to_string(kept) + " of " +
                               std::to_string(c.n) + " marks).};\n";
        // Byte for byte the scene of only every stride-th mark, written without a limit, plus the note.
        LaTeXTikz3D sub;
        scene(sub, c.n, c.stride, c.lines);
        sub.setTexMarkLimit(0);
        std::string reference = tikz(sub);
        size_t end = reference.rfind("\\end{tikzpicture}");
        ASSERT_NE(end, std::string::npos);
        EXPECT_EQ(thinned, reference.substr(0, end) + expected + "\\end{tikzpicture}\n") << c.n;
        EXPECT_EQ(count(thinned, "\\MarkA{"), kept) << c.n;
        EXPECT_EQ(count(thinned, "\\draw[StyleB]"), c.lines) << c.n;   // lines are never thinned
    }
}

TEST(Tikz3DBudget, TooManyLinesThrowLengthErrorBeforeWriting)
{
    // 16,002 lines count 8,001 marks and cannot be thinned; with the limit off they are written.
    LaTeXTikz3D t;
    scene(t, 10, 1, 16002);
    std::ostringstream os;
    EXPECT_THROW(t.writeTikz(os), std::length_error);
    EXPECT_TRUE(os.str().empty());
    try
    {
        t.writeTEX(os);
        ADD_FAILURE() << "no std::length_error";
    }
    catch (const std::length_error &e)
    {
        EXPECT_NE(std::string(e.what()).find("16002 lines, axes and face paths"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(os.str().empty());
    fs::path file = fs::path(RTL_TEST_OUTPUT_DIR) / "tikz3d_budget_throw.tex";
    fs::remove(file);
    EXPECT_THROW(t.writeTEX(file.string()), std::length_error);
    EXPECT_FALSE(fs::exists(file));   // not even created
    t.setTexMarkLimit(0);
    EXPECT_EQ(count(tikz(t), "\\draw[StyleB]"), 16002u);
}

//! One pdflatex run: 12,000 dot marks and 40 lines (11,000 marks failed before) are thinned 1 in 2, compile, and the
//! note is text in the PDF.
TEST(Tikz3DBudget, ThinnedSceneCompilesWithPdflatex)
{
    ASSERT_TRUE(rtl::LaTeXDoc::pdflatexAvailable()) << "pdflatex is not on PATH (./run test installs TeX Live)";
    LaTeXTikz3D t;
    scene(t, 12000, 1, 40);
    fs::path dir = fs::path(RTL_TEST_OUTPUT_DIR) / "latex" / "budget3d";
    fs::remove_all(dir);
    fs::create_directories(dir);
    t.writeTEX((dir / "budget.tex").string());
    const auto run = pdflatex_test::compile(dir, "budget");
    ASSERT_EQ(run.rc, 0) << run.failure();
    EXPECT_NE(run.log.find("Output written on budget.pdf (1 page"), std::string::npos);
    ASSERT_EQ(pdflatex_test::extractText(dir, "budget"), 0) << "pdftotext (poppler-utils) is needed to read the PDF";
    const std::string text = pdflatex_test::readFile(dir / "budget.txt");
    EXPECT_NE(text.find("Thinned for pdflatex"), std::string::npos) << text;
    EXPECT_NE(text.find("(6000 of 12000 marks)"), std::string::npos) << text;
}
