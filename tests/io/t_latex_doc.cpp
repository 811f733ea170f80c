// LaTeXDoc's steps and captions, observed through its replaceable hooks (no pdflatex needed): RTL documents compile,
// move and remove as best-effort (docs/reference.md, "LaTeXDoc") and always all called, in that order; captions are
// written as given.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "rtl/io/LaTeXDoc.h"

namespace fs = std::filesystem;
using rtl::LaTeXDoc;

namespace
{
    //! A fresh output folder <RTL_TEST_OUTPUT_DIR>/latex/doc-<sub> and no temporary folder of an earlier run.
    std::string outDir(const std::string &sub, const std::string &name)
    {
        fs::path p = fs::path(RTL_TEST_OUTPUT_DIR) / "latex" / ("doc-" + sub);
        fs::remove_all(p);
        fs::remove_all(p.string() + "_tmp_" + name);
        return p.string();
    }

    std::string readFile(const fs::path &p)
    {
        std::ifstream f(p, std::ios::binary);
        return std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    }

    //! A figure whose writeTEX writes fixed text.
    struct TextFigure
    {
        std::string text = "figure";
        void writeTEX(const std::string &file) const { std::ofstream(file) << text; }
    };

    //! Installs hooks that log "<step> <argument>" and succeed as told.
    struct StepLog
    {
        std::vector<std::string> steps;
        void attach(LaTeXDoc &doc, bool compile_ok)
        {
            doc.setCompileTex([this, compile_ok](const std::string &tex, const std::string &) {
                steps.push_back("compile " + fs::path(tex).filename().string());
                return compile_ok;
            });
            doc.setMoveFinalDoc([this](const std::string &pdf, const std::string &) {
                steps.push_back("move " + fs::path(pdf).filename().string());
                return true;
            });
            doc.setRemoveTmpDir([this](const std::string &) {
                steps.push_back("remove");
                return true;
            });
        }
    };
}

TEST(LaTeXDoc, FailedCompileStillMovesAndRemoves)
{
    StepLog log;
    bool ok;
    {
        LaTeXDoc doc(outDir("failed", "failed"), "failed");
        log.attach(doc, false);
        TextFigure f;
        doc.addLE(f, "a figure");
        ok = doc.finish();
        EXPECT_FALSE(doc.problems().empty());
    }
    EXPECT_FALSE(ok);
    EXPECT_EQ(log.steps, (std::vector<std::string>{"compile failed_0.tex", "compile failed.tex", "move failed.pdf", "remove"}));
}

TEST(LaTeXDoc, DestructorRunsEveryStepOnceInOrder)
{
    StepLog log;
    {
        LaTeXDoc doc(outDir("dtor", "dtor"), "dtor");
        log.attach(doc, false);
    }
    EXPECT_EQ(log.steps, (std::vector<std::string>{"compile dtor.tex", "move dtor.pdf", "remove"}));

    StepLog twice;   // finish() then the destructor: the steps run once
    {
        LaTeXDoc doc(outDir("twice", "twice"), "twice");
        twice.attach(doc, true);
        EXPECT_FALSE(doc.finish());   // the hook "compiled" but made no PDF
        EXPECT_FALSE(doc.finish());
    }
    EXPECT_EQ(twice.steps, (std::vector<std::string>{"compile twice.tex", "move twice.pdf", "remove"}));
}

TEST(LaTeXDoc, SuccessfulStepsReturnTrue)
{
    std::string dir = outDir("ok", "ok");
    StepLog log;
    bool ok;
    {
        LaTeXDoc doc(dir, "ok");
        log.attach(doc, true);
        doc.setCompileTex([&](const std::string &tex, const std::string &) {   // a compile that makes the PDF
            log.steps.push_back("compile");
            fs::path pdf = fs::path(tex).replace_extension(".pdf");
            std::ofstream(pdf) << "%PDF";
            return true;
        });
        ok = doc.finish();
        EXPECT_TRUE(doc.problems().empty());
    }
    EXPECT_TRUE(ok);
    EXPECT_EQ(log.steps, (std::vector<std::string>{"compile", "move ok.pdf", "remove"}));
}

TEST(LaTeXDoc, StopOnFailureSkipsMoveAndRemove)
{
    StepLog log;
    {
        LaTeXDoc doc(outDir("stop", "stop"), "stop");
        log.attach(doc, false);
        doc.setStopOnFailure(true);
        EXPECT_FALSE(doc.finish());
    }
    EXPECT_EQ(log.steps, (std::vector<std::string>{"compile stop.tex"}));
}

TEST(LaTeXDoc, DefaultRemovalRemovesTheTemporaryDirectoryEvenWithoutPdfAsRtl)
{
    std::string dir = outDir("remove", "remove"), tmp;
    {
        LaTeXDoc doc(dir, "remove");
        doc.setCompileTex([](const std::string &, const std::string &) { return false; });
        tmp = doc.tmpDir();
        EXPECT_FALSE(doc.finish());
    }
    EXPECT_FALSE(fs::exists(fs::path(tmp)));
    EXPECT_FALSE(fs::exists(fs::path(dir) / "remove.pdf"));
}

TEST(LaTeXDoc, StopOnFailureKeepsTheSourcesWhenNoPdfWasMade)
{
    std::string dir = outDir("keep", "keep"), tmp;
    {
        LaTeXDoc doc(dir, "keep");
        doc.setStopOnFailure(true);
        doc.setCompileTex([](const std::string &, const std::string &) { return false; });
        tmp = doc.tmpDir();
        EXPECT_FALSE(doc.finish());
    }
    EXPECT_TRUE(fs::exists(fs::path(tmp) / "keep.tex"));
    EXPECT_FALSE(fs::exists(fs::path(dir) / "keep.pdf"));
}

TEST(LaTeXDoc, CaptionsAreWrittenAsGivenUnlessEscapingIsAsked)
{
    for (bool escape : {false, true})
    {
        std::string name = escape ? "escaped" : "given", tmp;
        {
            LaTeXDoc doc(outDir(name, name), name);
            doc.setCompileTex([](const std::string &, const std::string &) { return false; });
            doc.setRemoveTmpDir([](const std::string &) { return true; });
            doc.setEscapeCaptions(escape);
            TextFigure f;
            doc.addLE(f, "Item\\_name $\\sigma$");
            auto grid = [&](int, int) -> TextFigure & { return f; };
            doc.addGridLE(grid, 2, 2, "grid_1");
            rtl::LaTeXTable t;
            t.addRow({"a\\_b", "2"});
            doc.addTable(t, "table\\_1");
            tmp = doc.tmpDir();
        }
        std::string tex = readFile(fs::path(tmp) / (name + ".tex"));
        if (!escape)
        {
            EXPECT_NE(tex.find("\\caption{Item\\_name $\\sigma$}"), std::string::npos) << tex;
            EXPECT_NE(tex.find("\\caption{grid_1}"), std::string::npos) << tex;
            EXPECT_NE(tex.find("\\caption{table\\_1}"), std::string::npos) << tex;
        }
        else
        {
            EXPECT_NE(tex.find("\\caption{Item\\textbackslash \\_name \\$\\textbackslash sigma\\$}"), std::string::npos)
                    << tex;
            EXPECT_NE(tex.find("\\caption{grid\\_1}"), std::string::npos) << tex;
            EXPECT_NE(tex.find("\\caption{table\\textbackslash \\_1}"), std::string::npos) << tex;
        }
        EXPECT_NE(tex.find("\ta\\_b & 2\\\\\n"), std::string::npos) << tex;   // cells as given either way
    }
}

TEST(LaTeXDoc, AnEmptyTikz3DFigureIsAPlaceholderNotAProblem)
{
    std::string tmp;
    {
        LaTeXDoc doc(outDir("empty3d", "empty3d"), "empty3d");
        doc.setCompileTex([](const std::string &, const std::string &) { return true; });
        doc.setRemoveTmpDir([](const std::string &) { return true; });
        rtl::LaTeXTikz3D empty;
        doc.addLE(empty, "nothing");
        EXPECT_TRUE(doc.problems().empty());
        tmp = doc.tmpDir();
    }
    EXPECT_FALSE(fs::exists(fs::path(tmp) / "empty3d_0.tex"));
    std::string tex = readFile(fs::path(tmp) / "empty3d.tex");
    EXPECT_NE(tex.find("\\fbox{(empty figure)}"), std::string::npos) << tex;
}
