// Issue 15: what the TikZ fuzz harnesses decode compiles with pdflatex. Every seed of tests/fuzz/seeds/tikz2d and
// tikz3d plus 200 deterministic pseudo-random inputs per harness are decoded with the harnesses' own decoders
// (tests/fuzz/fuzz_tikz_drawings.h); each picture the writers accept (a std::length_error is the documented refusal)
// is written as the standalone document would have it (its \PreviewBorder and the tikzpicture) into one preview
// document, and one pdflatex run must compile them all. A failure names every picture whose page raised an error.
// On the old headers this found "! Dimension too large" in most random pictures (extents, mark sizes, rotations).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "../fuzz/fuzz_tikz_drawings.h"
#include "pdflatex_run.h"

namespace fs = std::filesystem;

namespace
{
    struct Input
    {
        std::string name;
        std::vector<uint8_t> bytes;
    };

    //! The harness's seeds (sorted by name), then 200 inputs of 1..400 random bytes from a fixed generator.
    std::vector<Input> inputs(const std::string &harness, unsigned seed)
    {
        std::vector<Input> v;
        const fs::path dir = fs::path(RTL_TEST_DATA_DIR) / ".." / "fuzz" / "seeds" / harness;
        std::vector<fs::path> files;
        for (const auto &e : fs::directory_iterator(dir))
            files.push_back(e.path());
        std::sort(files.begin(), files.end());
        for (const auto &f : files)
        {
            std::ifstream in(f, std::ios::binary);
            v.push_back({harness + " seed " + f.filename().string(),
                         std::vector<uint8_t>((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>())});
        }
        std::mt19937 rng(seed);
        for (int i = 0; i < 200; ++i)
        {
            Input in{harness + " random " + std::to_string(i), std::vector<uint8_t>(1 + rng() % 400)};
            for (auto &b : in.bytes)
                b = static_cast<uint8_t>(rng() & 0xff);
            v.push_back(std::move(in));
        }
        return v;
    }

    struct Sample
    {
        std::vector<std::string> names, pages;   // accepted pictures: name, document body
        size_t refused = 0, empty = 0;
        std::map<std::string, size_t> reasons;   // refusals by what was beyond TeX's dimensions
        void refuse(const std::exception &e)
        {
            ++refused;
            std::string what = e.what();
            size_t a = what.find(": "), b = what.find(" of ");
            ++reasons[a != std::string::npos && b != std::string::npos && a < b ? what.substr(a + 2, b - a - 2) : what];
        }
    };

    //! The standalone document's \PreviewBorder line and its picture, checked to start with the preview preamble.
    std::string page(const std::string &name, const std::string &doc)
    {
        const std::string border = "\\setlength\\PreviewBorder{", begin = "\\begin{document}\n", end = "\\end{document}\n";
        size_t b = doc.find(border), p = doc.find(begin), e = doc.rfind(end);
        EXPECT_EQ(doc.rfind(pdflatex_test::preamble, 0), 0u) << name;
        EXPECT_TRUE(b != std::string::npos && p != std::string::npos && e != std::string::npos && b < p && p < e) << name;
        if (b == std::string::npos || p == std::string::npos || e == std::string::npos || !(b < p && p < e))
            return "";
        return "\\typeout{RTL-PICTURE " + name + "}\n" + doc.substr(b, doc.find('\n', b) + 1 - b) +
               doc.substr(p + begin.size(), e - p - begin.size());
    }

    void add(Sample &s, const std::string &name, const std::string &doc)
    {
        if (doc.empty())
            ++s.empty;
        else
        {
            s.names.push_back(name);
            s.pages.push_back(page(name, doc));
        }
    }

    Sample sample2D()
    {
        Sample s;
        for (const auto &in : inputs("tikz2d", 15))
        {
            fuzz_tikz::Drawing2DCase c = fuzz_tikz::decodeDrawing2D(in.bytes.data(), in.bytes.size());
            std::ostringstream os;
            try
            {
                rtl::writeTikz(c.d, os);
            }
            catch (const std::length_error &e)
            {
                // The harness's tiny mark budgets refuse drawings the default budget thins: write those as a user would.
                os.str("");
                try
                {
                    if (fuzz_tikz::beyondTex(e))
                        throw;
                    c.d.setTexMarkLimit(rtl::Drawing2D::pdflatex_mark_limit);
                    rtl::writeTikz(c.d, os);
                }
                catch (const std::length_error &e2)
                {
                    s.refuse(e2);
                    continue;
                }
            }
            add(s, in.name, os.str());
        }
        return s;
    }

    Sample sample3D()
    {
        Sample s;
        for (const auto &in : inputs("tikz3d", 16))
        {
            rtl::LaTeXTikz3D d = fuzz_tikz::decodeScene3D(in.bytes.data(), in.bytes.size());
            std::ostringstream os;
            try
            {
                d.writeTEX(os);
            }
            catch (const std::length_error &e)
            {
                s.refuse(e);
                continue;
            }
            add(s, in.name, os.str());
        }
        return s;
    }
}

TEST(TikzFuzzSample, EveryAcceptedPictureCompiles)
{
    const Sample s2 = sample2D(), s3 = sample3D();
    std::printf("tikz2d: %zu pictures written, %zu refused, %zu empty; tikz3d: %zu written, %zu refused, %zu empty\n",
                s2.names.size(), s2.refused, s2.empty, s3.names.size(), s3.refused, s3.empty);
    for (const Sample *s : {&s2, &s3})
        for (const auto &r : s->reasons)
            std::printf("  %s refused: %s (%zu)\n", s == &s2 ? "tikz2d" : "tikz3d", r.first.c_str(), r.second);
    // The sample is meant to exercise the writers: many inputs give a picture.
    EXPECT_GT(s2.names.size(), 50u);
    EXPECT_GT(s3.names.size(), 25u);

    std::vector<std::string> pages = s2.pages;
    pages.insert(pages.end(), s3.pages.begin(), s3.pages.end());
    const fs::path dir = fs::path(RTL_TEST_OUTPUT_DIR) / "tikz_fuzz_sample";
    fs::create_directories(dir);
    // The harnesses' styles name ColorA, which is defined only in pictures that saveColor: elsewhere it is the
    // user's own colour, which the document defines.
    pdflatex_test::writePreviewDocument(dir, "sample", pages, "\\definecolor{ColorA}{gray}{0.5}\n");
    const auto run = pdflatex_test::compile(dir, "sample", false);

    // Every error of the log, by the picture whose \typeout came last before it.
    std::set<std::string> failed;
    std::string first_errors;
    const std::string marker = "RTL-PICTURE ";
    for (size_t p = run.log.find("\n!"); p != std::string::npos; p = run.log.find("\n!", p + 1))
    {
        size_t m = run.log.rfind(marker, p);
        std::string name = m == std::string::npos ? "(before the first picture)"
                                                  : run.log.substr(m + marker.size(), run.log.find('\n', m) - m - marker.size());
        if (failed.insert(name).second && failed.size() <= 10)
            first_errors += name + ": " + run.log.substr(p + 1, run.log.find('\n', p + 1) - p - 1) + "\n";
    }
    EXPECT_EQ(run.rc, 0) << failed.size() << " of " << pages.size() << " pictures failed, e.g.\n"
                         << first_errors << (failed.empty() ? run.failure() : "") << "\nsee " << (dir / "sample.log");
    EXPECT_TRUE(failed.empty()) << first_errors;
}
