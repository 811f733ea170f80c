// libFuzzer harness for the 2D drawing model and both back-ends (Drawing2D.h, Tikz2DWriter.h, Svg2D.h): drawing
// calls decoded from the bytes (values often huge, tiny or non-finite; texts raw bytes), then the same drawing written
// as TikZ and as SVG. The TikZ must be safe LaTeX (ASCII, balanced braces, no bare %), the SVG well-formed XML, both
// of bounded size, and neither may contain a non-finite number. A drawing beyond TeX's dimensions (std::length_error,
// detail::refuseBeyondTex) is a valid outcome: nothing is written as TikZ, the SVG is checked as always.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <string>

#include "../io/xml_check.h"
#include "fuzz_tikz_drawings.h"
#include "fuzz_tikz_input.h"
#include "rtl/io/LaTeXTikz2D.h"
#include "rtl/io/Svg2D.h"

using fuzz_tikz::require;

namespace
{
    bool letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
    //! Occurrences of `what` as a word ("nan" in "-nan" counts, in "dominant" not).
    size_t count(const std::string &s, const std::string &what)
    {
        size_t n = 0;
        for (size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1))
            n += (p == 0 || !letter(s[p - 1])) && (p + what.size() >= s.size() || !letter(s[p + what.size()]));
        return n;
    }
    //! No more "nan"/"inf" in the output than the user's (escaped) texts brought in; prints the first one if so.
    void requireFinite(const std::string &out, const std::string &user, int line = __builtin_LINE())
    {
        for (const char *w : {"nan", "inf"})
            if (count(out, w) > count(user, w))
            {
                size_t p = out.find(w);
                while (p != std::string::npos && count(out.substr(p, 4), w) == 0)
                    p = out.find(w, p + 1);
                std::fprintf(stderr, "'%s' in the output: ...%s...\n", w, out.substr(p < 80 ? 0 : p - 80, 160).c_str());
                require(false, __FILE__, line);
            }
    }
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_tikz::Drawing2DCase c = fuzz_tikz::decodeDrawing2D(data, size);
    rtl::Svg2D &d = c.d;
    std::ostringstream tikz, svg;
    bool refused = false;   // beyond TeX's dimensions: the documented refusal, nothing written
    try
    {
        rtl::writeTikz(d, tikz);
    }
    catch (const std::length_error &e)
    {
        // The documented refusals write nothing. The budget's (more unthinnable primitives than texMarkLimit):
        // without a budget the same drawing is written, unless it is beyond TeX's dimensions too.
        require(tikz.str().empty());
        refused = fuzz_tikz::beyondTex(e);
        if (!refused)
        {
            d.setTexMarkLimit(0);
            try
            {
                rtl::writeTikz(d, tikz);
            }
            catch (const std::length_error &e2)
            {
                require(tikz.str().empty() && fuzz_tikz::beyondTex(e2));
                refused = true;
            }
        }
    }
    rtl::writeSvg(d, svg);
    const std::string t = tikz.str(), s = svg.str();
    xml_check::Result r = xml_check::check(s);
    require(r.ok);
    require(s.size() < 8'000'000);
    requireFinite(s, c.xml_texts);
    if (refused)
        return 0;
    fuzz_tikz::requireSafeLaTeX(t);
    // Bounded: 6 grids/axes of at most max_ticks lines each, plus what the calls drew.
    require(t.size() < 8'000'000);
    // A thinned picture says so; the budget's count of marks written matches the marks in the output.
    const rtl::detail::TikzThinning thin = rtl::detail::tikzThinning(d, d.frame());
    require((t.find("{Thinned for pdflatex's memory: 1 in ") != std::string::npos) == thin.thinned());
    size_t marks = 0;
    for (size_t p = t.find("\n\\Mark"); p != std::string::npos; p = t.find("\n\\Mark", p + 1))
        ++marks;
    require(marks == thin.kept);
    requireFinite(t, c.tex_texts);
    return 0;
}
