// Everything the LaTeX exporters write must compile with the real pdflatex: figures batched into one document, a
// document with separately compiled figures, tables, and a figure of a real scan (kept in RTL_TEST_OUTPUT_DIR/latex).
// pdflatex missing is a FAILURE here (CI installs TeX Live); LaTeXDoc itself only reports it, which is checked in a
// child process run with an empty PATH.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "rtl/io/LaTeXDoc.h"
#include "scan_figure.h"

namespace fs = std::filesystem;
using rtl::LaTeXDoc;
using rtl::LaTeXTable;
using rtl::LaTeXTikz2D;
using rtl::LaTeXTikz3D;
using rtl::Vector2f;
using rtl::Vector3f;

namespace
{
    const char *kMissing = "pdflatex is not on PATH: the LaTeX tests need it (install texlive-latex-base "
                           "texlive-pictures texlive-latex-extra poppler-utils; ./run test does)";

    //! A fresh output folder <RTL_TEST_OUTPUT_DIR>/latex/<sub>, without the temporary folder that a previous run's
    //! LaTeXDoc named `doc` left there.
    fs::path outDir(const std::string &sub, const std::string &doc)
    {
        fs::path p = fs::path(RTL_TEST_OUTPUT_DIR) / "latex" / sub;
        fs::remove_all(p);
        fs::remove_all(p.string() + "_tmp_" + doc);
        fs::create_directories(p);
        return p;
    }

    std::string readFile(const fs::path &p)
    {
        std::ifstream f(p, std::ios::binary);
        std::ostringstream os;
        os << f.rdbuf();
        return os.str();
    }

    //! The error lines ("! ...") of a pdflatex log with the two lines after each, or "" if there are none.
    std::string logErrors(const fs::path &log)
    {
        std::istringstream is(readFile(log));
        std::string out, line;
        int context = 0;
        while (std::getline(is, line))
        {
            if (!line.empty() && line[0] == '!')
                context = 3;
            if (context > 0)
            {
                out += line + "\n";
                --context;
            }
        }
        return out;
    }

    //! Fraction of dark pixels on page 1, rendered by pdftoppm at 30 dpi (-1 if rendering failed).
    double inkFraction(const fs::path &pdf)
    {
        fs::path prefix = pdf.parent_path() / (pdf.stem().string() + "-page1");
        std::string cmd = "pdftoppm -r 30 -gray -f 1 -l 1 -singlefile " + rtl::detail::shellQuote(pdf.string()) +
                          " " + rtl::detail::shellQuote(prefix.string());
        if (std::system(cmd.c_str()) != 0)
            return -1;
        std::string img = readFile(prefix.string() + ".pgm");
        std::istringstream is(img);
        std::string magic;
        size_t w = 0, h = 0, maxval = 0;
        is >> magic >> w >> h >> maxval;
        is.get();
        if (magic != "P5" || w == 0 || h == 0 || maxval != 255)
            return -1;
        size_t start = static_cast<size_t>(is.tellg()), dark = 0;
        if (img.size() < start + w * h)
            return -1;
        for (size_t i = 0; i < w * h; ++i)
            dark += static_cast<unsigned char>(img[start + i]) < 128;
        return static_cast<double>(dark) / static_cast<double>(w * h);
    }

    //! A 2D figure with every primitive, mark and label kind, and user text full of special characters.
    LaTeXTikz2D figureAllPrimitives()
    {
        LaTeXTikz2D le;
        std::string c = le.saveColor("{hsb}{0.6,0.8,0.7}");
        le.addGridH("style={draw=gray!50,dotted}", 1);
        le.addGridV("style={draw=gray!50,dotted}", 1);
        le.addAxisX("style={draw=black,->}", "%.1f", LaTeXTikz2D::position_below, 1);
        le.addAxisY("style={draw=black,->}", "%.0e", LaTeXTikz2D::position_left | LaTeXTikz2D::position_below, 1);
        le.addDescriptionX("x_1 [m] & 100% {of} #2");
        le.addDescriptionY("y^2 ~ \\ $ <a>");
        std::vector<float> x, y;
        for (int i = 0; i < 25; ++i)
        {
            x.push_back(0.25f * static_cast<float>(i));
            y.push_back(2.0f * std::sin(0.25f * static_cast<float>(i)));
        }
        y[9] = NAN;   // a gap in the polyline
        le.addPlot(x, y, "style={draw=" + c + ",thick}", "style={draw=black,fill=white}", LaTeXTikz2D::latex_mark_robot);
        le.addPlot(x, y, "", "style={draw=red}", LaTeXTikz2D::latex_mark_cross, 0.7f);
        le.addPlot(x, y, "", "style={draw=blue}", LaTeXTikz2D::latex_mark_mark);
        std::vector<Vector2f> v = {{0.5f, -1.5f}, {1.5f, -1.0f}, {2.5f, -1.5f}};
        le.addPlot(v, "style={draw=green!50!black}", "style={fill=green}", LaTeXTikz2D::latex_mark_dot);
        le.addCircle(Vector2f(1, 1), 0.5f, "style={draw=red}");
        le.addEllipse(Vector2f(3, 1), 1, 0.3f, 0.5f, "style={draw=blue,fill=blue!20}");
        le.addPie(Vector2f(4, -1), 0.8f, 0.2f, 2.0f, "style={fill=orange}");
        le.addRectangle(Vector2f(0, -2), Vector2f(1, -1), "style={draw=black}");
        le.addTriangle(Vector2f(2, -2), Vector2f(3, -2), Vector2f(2.5f, -1), "style={fill=green}");
        le.addQuadrilateral(Vector2f(4, 2), Vector2f(5, 2), Vector2f(5.5f, 3), Vector2f(4, 3), "draw=purple");
        le.addLine(Vector2f(0, 0), Vector2f(5, 1e-7f), "style={draw=black,dashed}");
        le.addLines({rtl::LineSegment2f(0, 3, 1, 3), rtl::LineSegment2f(1, 3, 2, 2.5f)}, "style={draw=brown}");
        le.addEdges(std::vector<rtl::LineSegment2f>{{Vector2f(5, 0), Vector2f(6, 1)}}, "style={draw=red}",
                    LaTeXTikz2D::edge_arrow_end);
        le.addText("label_1 & 50% <x> {y} #3 ~ ^ \\ $", "style={anchor=west}", Vector2f(1, 2));
        return le;
    }

    LaTeXTikz2D figureLogAxes()
    {
        LaTeXTikz2D le(LaTeXTikz2D::axis_type_log10, LaTeXTikz2D::axis_type_log10);
        std::vector<float> a, b;
        for (int i = 1; i <= 100; ++i)
        {
            a.push_back(static_cast<float>(i));
            b.push_back(0.01f * static_cast<float>(i * i));
        }
        le.addPlot(a, b, "style={draw=blue}", "style={fill=blue}", LaTeXTikz2D::latex_mark_dot, 0.5f);
        le.addGridH("style={draw=gray!50}", 1);
        le.addGridV("style={draw=gray!50}", 1);
        le.addAxisX("style={draw=black}", "%.0e", LaTeXTikz2D::position_below, 1, 0.01f);
        le.addAxisY("style={draw=black}", "%.0e", LaTeXTikz2D::position_left, 1, 1);
        le.setClipRegion(0.5f, 0.005f, 200, 200);
        return le;
    }

    //! A cube, a plane cutting through it, a mark, a line and axes.
    void sceneCube(LaTeXTikz3D &le)
    {
        le.clearData();
        std::vector<rtl::Polygon3Df> faces;
        const float u[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (int ax = 0; ax < 3; ++ax)
            for (int s = -1; s <= 1; s += 2)
            {
                Vector3f n(ax == 0 ? s : 0, ax == 1 ? s : 0, ax == 2 ? s : 0);
                rtl::Polygon3Df p(n, 1);
                for (const auto &q : u)
                {
                    Vector3f v;
                    v[ax] = static_cast<float>(s);
                    v[(ax + 1) % 3] = q[0];
                    v[(ax + 2) % 3] = q[1];
                    p.addPoint(v);
                }
                faces.push_back(p);
            }
        le.addFace(faces, "style={fill=blue!30}", "style={fill=red!30}", "style={draw=black}");
        rtl::Polygon3Df cut(Vector3f(1, 1, 0), 0);
        for (const auto &q : u)
            cut.addPoint(Vector3f(1.5f * q[0], -1.5f * q[0], 1.5f * q[1]));
        le.addFace(cut, "style={fill=green!50,opacity=0.8}", "style={fill=yellow!50}", "style={draw=black,thick}");
        le.addMark(Vector3f(0, 0, 2), "style={fill=red}", LaTeXTikz3D::latex_mark_dot);
        le.addMarks({Vector3f(2, 0, 0), Vector3f(0, 2, 0)}, "style={draw=black}", LaTeXTikz3D::latex_mark_cross, 0, 1.5f);
        le.addLine(rtl::LineSegment3f(Vector3f(-2, -2, -2), Vector3f(2, 2, 2)), "style={draw=magenta,thick}");
        le.addLines({rtl::LineSegment3f(Vector3f(0, 0, 0), Vector3f(0, 0, 3))}, "style={draw=black,->}");
        le.addAxis("style={draw=black}", "%.0f", LaTeXTikz3D::position_left, 1, Vector3f(0, 0, 0), Vector3f(1, 0, 0));
        le.setMinPlotRegion(Vector3f(-2, -2, -2), Vector3f(2, 2, 2));
    }

    rtl::CarmenScan<float> intelScan()
    {
        auto scans = rtl::readCarmenLogFile<float>(std::string(RTL_TEST_DATA_DIR) + "/intel.log");
        if (scans.size() < 27)
            throw std::runtime_error("intel.log holds fewer than 27 scans");
        return scans[26];   // a scan with many walls and objects: 14 clusters
    }
}

TEST(LaTeXPdf, EveryFigureAndTableCompilesInOneBatchedDocument)
{
    ASSERT_TRUE(LaTeXDoc::pdflatexAvailable()) << kMissing;
    fs::path dir = outDir("batch dir 'quoted'", "batch");   // the shell commands must quote paths
    LaTeXTikz2D all = figureAllPrimitives(), log = figureLogAxes();
    LaTeXTikz3D cube;
    cube.setView(60, Vector3f(-1, -2, -1));
    cube.setFrameStyle("draw=black, thick");
    sceneCube(cube);
    LaTeXTikz3D persp;   // explicit view, export clipping, camera inside the scene's bounding box
    sceneCube(persp);
    persp.setView(100, rtl::RigidTf3f(0.3f, Vector3f(1, 0, 0), Vector3f(0, 0, -1.5f)));
    persp.setExportSize(8, 5);
    persp.setExportClipping(-3, -2, 3, 2);
    LaTeXTikz3D empty;
    LaTeXTable tab;
    tab.setColumnStyle("l|r|r");
    tab.setHeadingEscaped({"name_1", "50% & more", "{x}^2 ~ \\"});
    tab.addHLine();
    tab.addRowEscaped({"a#b", "$", "<>"});
    tab.addRow({"Item\\_name", LaTeXTikz2D::numberToLatexString(12345.0, "%.2e"), "$\\alpha$"});
    bool ok;
    std::string tmp;
    {
        LaTeXDoc doc(dir.string(), "batch");
        doc.setInlineFigures(true);
        doc.setEscapeCaptions(true);   // the captions below are plain text full of special characters
        doc.setRemoveTmpDir([](const std::string &) { return true; });   // keep the log for the check below
        doc.addLE(all, "All 2D primitives: x_1 & 100%");
        doc.addLE(log, "log10 axes");
        doc.addLE(cube, "cube {cut} by a plane #1");
        doc.addLE(persp);
        doc.addLE(empty, "empty 3D scene");
        auto grid = [&](int n, int i) -> LaTeXTikz3D & {
            float a = static_cast<float>(i) * 6.2831853f / static_cast<float>(n);
            cube.setView(40, Vector3f(std::cos(a), std::sin(a), -0.6f));
            return cube;
        };
        doc.addGridLE(grid, 3, 5, "grid of views ~ 5");
        doc.addTable(tab, "table of special characters: _ % $ & # { } ~ ^ \\");
        ok = doc.finish();
        tmp = doc.tmpDir();
        EXPECT_TRUE(doc.problems().empty()) << doc.problems().front();
    }
    EXPECT_TRUE(ok);
    EXPECT_EQ(logErrors(fs::path(tmp) / "batch.log"), "");
    ASSERT_TRUE(fs::exists(dir / "batch.pdf"));
    double ink = inkFraction(dir / "batch.pdf");
    EXPECT_GT(ink, 0.002) << "page 1 looks blank";
    EXPECT_LT(ink, 0.5) << "page 1 looks black";
    // The exact figure files LaTeXDoc \input: the standalone sources written by writeTEX.
    EXPECT_NE(readFile(fs::path(tmp) / "batch_0.tex").find("\\documentclass{minimal}"), std::string::npos);
}

TEST(LaTeXPdf, DocumentWithSeparatelyCompiledFiguresAndTheScanFigure)
{
    ASSERT_TRUE(LaTeXDoc::pdflatexAvailable()) << kMissing;
    fs::path dir = outDir("report", "report");
    auto r = rtl_test_latex::process(intelScan());
    ASSERT_GE(r.clusters.size(), 8u);
    ASSERT_GE(r.segments.size(), 15u);
    LaTeXTikz2D scan;
    rtl_test_latex::drawScan(scan, r);
    LaTeXTikz3D cube;
    sceneCube(cube);
    LaTeXTable tab;
    tab.setColumnStyle("r|r|r|r");
    tab.setHeading({"segment", "points", "length [m]", "rms [mm]"});
    tab.addHLine();
    for (size_t i = 0; i < r.segments.size() && i < 10; ++i)
    {
        const auto &s = r.segments[i];
        tab.addRow({std::to_string(i), std::to_string(s.points), std::to_string((s.end - s.beg).length()),
                    std::to_string(1000 * s.rms)});
    }
    bool ok;
    std::string tmp;
    {
        LaTeXDoc doc(dir.string(), "report");
        doc.setRemoveTmpDir([](const std::string &) { return true; });
        doc.addLE(scan, "intel.log, scan 27: clusters in colours, fitted segments in black");
        auto grid = [&](int, int i) -> LaTeXTikz3D & {
            cube.setView(50, Vector3f(i == 0 ? -1.0f : 1.0f, -1, -1));
            return cube;
        };
        doc.addGridLE(grid, 2, 2, "two views");
        doc.addTable(tab, "segment statistics");
        ok = doc.finish();
        tmp = doc.tmpDir();
        EXPECT_TRUE(doc.problems().empty()) << doc.problems().front();
    }
    EXPECT_TRUE(ok);
    for (const char *name : {"report_0", "report_1", "report_2", "report"})
    {
        fs::path log = fs::path(tmp) / (std::string(name) + ".log");
        ASSERT_TRUE(fs::exists(log)) << log;
        EXPECT_EQ(logErrors(log), "") << log;
    }
    ASSERT_TRUE(fs::exists(dir / "report.pdf"));
    EXPECT_GT(inkFraction(dir / "report.pdf"), 0.002);
    // The scan figure on its own, next to the report (the run keeps RTL_TEST_OUTPUT_DIR).
    fs::copy_file(fs::path(tmp) / "report_0.pdf", dir / "scan-intel.pdf", fs::copy_options::overwrite_existing);
    fs::copy_file(fs::path(tmp) / "report_0.tex", dir / "scan-intel.tex", fs::copy_options::overwrite_existing);
    double ink = inkFraction(dir / "scan-intel.pdf");
    EXPECT_GT(ink, 0.005);
    EXPECT_LT(ink, 0.5);
    // Every cluster colour and every segment is in the figure source.
    std::string src = readFile(dir / "scan-intel.tex");
    EXPECT_NE(src.find("\\definecolor{Color" + rtl::detail::indexToLetters(r.clusters.size() - 1) + "}{hsb}"),
              std::string::npos);
    size_t lines = 0;
    for (size_t p = src.find("line width=0.8pt"); p != std::string::npos; p = src.find("\\draw[Style", p + 1))
        ++lines;
    EXPECT_GE(lines, r.segments.size());
}

TEST(LaTeXPdf, MissingPdflatexIsReportedNotFatal)
{
    if (std::getenv("RTL_LATEX_CHILD") != nullptr)
    {
        // Child: PATH has no pdflatex.
        fs::path dir = fs::path(std::getenv("RTL_LATEX_CHILD"));
        EXPECT_FALSE(LaTeXDoc::pdflatexAvailable());
        LaTeXDoc doc(dir.string(), "nolatex");
        doc.setStopOnFailure(true);   // keep the sources of the failed document (RTL's default removes them)
        LaTeXTikz2D le;
        le.addLine(Vector2f(0, 0), Vector2f(1, 1), "style={draw=red}");
        doc.addLE(le, "a figure");
        LaTeXTable t;
        t.addRow({"1", "2"});
        doc.addTable(t, "a table");
        EXPECT_FALSE(doc.finish());
        ASSERT_FALSE(doc.problems().empty());
        EXPECT_NE(doc.problems().front().find("pdflatex was not found"), std::string::npos);
        EXPECT_FALSE(fs::exists(doc.pdfPath()));
        EXPECT_TRUE(fs::exists(fs::path(doc.tmpDir()) / "nolatex.tex"));     // sources kept for later
        EXPECT_TRUE(fs::exists(fs::path(doc.tmpDir()) / "nolatex_0.tex"));
        return;
    }
    fs::path dir = outDir("nolatex", "nolatex");
    fs::path self = fs::read_symlink("/proc/self/exe");
    fs::path err = dir / "stderr.txt";
    using rtl::detail::shellQuote;
    std::string cmd = "env PATH=/nonexistent RTL_LATEX_CHILD=" + shellQuote((dir / "out").string()) + " " +
                      shellQuote(self.string()) + " --gtest_filter=LaTeXPdf.MissingPdflatexIsReportedNotFatal > " +
                      shellQuote((dir / "stdout.txt").string()) + " 2> " + shellQuote(err.string());
    int rc = std::system(cmd.c_str());
    EXPECT_EQ(rc, 0) << readFile(dir / "stdout.txt");
    std::string msg = readFile(err);
    EXPECT_NE(msg.find("rtl::LaTeXDoc: pdflatex was not found on PATH, so no PDF is produced"), std::string::npos)
            << msg;
    // Said once, clearly, not once per figure.
    EXPECT_EQ(msg.find("pdflatex was not found", msg.find("pdflatex was not found") + 1), std::string::npos) << msg;
}
