// libFuzzer harness for the 2D drawing model and both back-ends (Drawing2D.h, Tikz2DWriter.h, Svg2D.h): drawing
// calls decoded from the bytes (values often huge, tiny or non-finite; texts raw bytes), then the same drawing written
// as TikZ and as SVG. The TikZ must be safe LaTeX (ASCII, balanced braces, no bare %), the SVG well-formed XML, both
// of bounded size, and neither may contain a non-finite number.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "../io/xml_check.h"
#include "fuzz_tikz_input.h"
#include "rtl/io/LaTeXTikz2D.h"
#include "rtl/io/Svg2D.h"

using fuzz_tikz::require;
using rtl::Vector2f;

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
    fuzz_tikz::Reader in(data, size);
    uint8_t axes = in.byte();
    rtl::Svg2D d(axes & 1, (axes >> 1) & 1);
    if (axes & 4)
        d.setTexMarkLimit(1 + (axes >> 3));   // tiny budgets (1..32 marks): the thinning path and its note
    std::string tex_texts, xml_texts;   // one line per user text (words must not join across texts); what it contributes ("nan" in a label is a finding, in a text not)
    size_t grids = 0, ops = 0;
    auto v2 = [&]() { float x = in.value(); return Vector2f(x, in.value()); };
    while (!in.empty() && ops++ < 64)
    {
        switch (in.byte() % 24)
        {
            case 0: d.setSize(in.value(), in.value()); break;
            case 1: d.setBorder(in.value()); break;
            case 2: d.setMarkRadius(in.value()); break;
            case 3: d.setGridAxisOverrun(in.byte() & 1, in.value()); break;
            case 4: d.setScaleX(in.value()); break;
            case 5: d.setScaleY(in.value()); break;
            case 6: { float a = in.value(), b = in.value(), c = in.value(); d.setClipRegion(a, b, c, in.value()); break; }
            case 7: { float a = in.value(), b = in.value(), c = in.value(); d.setMinPlotRegion(a, b, c, in.value()); break; }
            case 8:
                if (grids++ < 6)
                    (in.byte() & 1) ? d.addGridH(in.pick(fuzz_tikz::styles), in.value()) : d.addGridV(in.pick(fuzz_tikz::styles), in.value());
                break;
            case 9:
                if (grids++ < 6)
                {
                    bool x = in.byte() & 1;
                    std::string st = in.pick(fuzz_tikz::styles), fmt = in.pick(fuzz_tikz::formats);
                    unsigned pos = in.byte() & 15;
                    float tick = in.value();
                    x ? d.addAxisX(st, fmt, pos, tick, in.value()) : d.addAxisY(st, fmt, pos, tick, in.value());
                }
                break;
            case 10: { std::string t = in.text(); tex_texts += rtl::LaTeX::escapeLaTeXCharacters(t) + "\n"; xml_texts += rtl::svg_detail::xmlEscape(t) + "\n"; (in.byte() & 1) ? d.addDescriptionX(t) : d.addDescriptionY(t); break; }
            case 11:
            {
                std::vector<Vector2f> v(in.byte() % 40);
                for (auto &p : v)
                    p = v2();
                std::string line = in.pick(fuzz_tikz::styles), mark_style = in.pick(fuzz_tikz::styles);
                const char *const marks[] = {rtl::Drawing2D::latex_mark_cross, rtl::Drawing2D::latex_mark_dot,
                                             rtl::Drawing2D::latex_mark_mark, rtl::Drawing2D::latex_mark_robot,
                                             rtl::Drawing2D::latex_mark_blank};
                d.addPlot(v, line, mark_style, in.pick(marks), in.value());
                break;
            }
            case 12:
            {
                std::vector<float> x(in.byte() % 20), y(in.byte() % 2 ? x.size() : x.size() + 1);
                for (auto &a : x)
                    a = in.value();
                for (auto &a : y)
                    a = in.value();
                d.addPlot(x, y, in.pick(fuzz_tikz::styles), in.pick(fuzz_tikz::styles), rtl::Drawing2D::latex_mark_cross);
                break;
            }
            case 13: { Vector2f a = v2(); d.addEdge(rtl::LineSegment2f(a, v2()), in.pick(fuzz_tikz::styles), in.byte() & 3); break; }
            case 14: { Vector2f a = v2(); d.addLine(a, v2(), in.pick(fuzz_tikz::styles)); break; }
            case 15: { Vector2f a = v2(), b = v2(); d.addTriangle(a, b, v2(), in.pick(fuzz_tikz::styles)); break; }
            case 16: { Vector2f a = v2(); d.addRectangle(a, v2(), in.pick(fuzz_tikz::styles)); break; }
            case 17: { Vector2f a = v2(), b = v2(), c = v2(); d.addQuadrilateral(a, b, c, v2(), in.pick(fuzz_tikz::styles)); break; }
            case 18: { Vector2f a = v2(); d.addCircle(a, in.value(), in.pick(fuzz_tikz::styles)); break; }
            case 19: { Vector2f a = v2(); float rx = in.value(), ry = in.value(); d.addEllipse(a, rx, ry, in.value(), in.pick(fuzz_tikz::styles)); break; }
            case 20: { Vector2f a = v2(); float r = in.value(), b = in.value(); d.addPie(a, r, b, in.value(), in.pick(fuzz_tikz::styles)); break; }
            case 21: { std::string t = in.text(); tex_texts += rtl::LaTeX::escapeLaTeXCharacters(t) + "\n"; xml_texts += rtl::svg_detail::xmlEscape(t) + "\n"; d.addText(t, in.pick(fuzz_tikz::styles), v2()); break; }
            case 22: d.saveColor(in.pick(fuzz_tikz::colors)); break;
            case 23: (in.byte() & 1) ? d.clearData() : d.clearAll(); break;
        }
    }
    std::ostringstream tikz, svg;
    try
    {
        rtl::writeTikz(d, tikz);
    }
    catch (const std::length_error &)
    {
        // The documented refusal (more unthinnable primitives than the budget) writes nothing; without a budget
        // the same drawing is written.
        require(tikz.str().empty());
        d.setTexMarkLimit(0);
        rtl::writeTikz(d, tikz);
    }
    rtl::writeSvg(d, svg);
    const std::string t = tikz.str(), s = svg.str();
    fuzz_tikz::requireSafeLaTeX(t);
    xml_check::Result r = xml_check::check(s);
    require(r.ok);
    // Bounded: 6 grids/axes of at most max_ticks lines each, plus what the calls drew.
    require(t.size() < 8'000'000 && s.size() < 8'000'000);
    // A thinned picture says so; the budget's count of marks written matches the marks in the output.
    const rtl::latex_detail::TikzThinning thin = rtl::latex_detail::tikzThinning(d, d.frame());
    require((t.find("{Thinned for pdflatex's memory: 1 in ") != std::string::npos) == thin.thinned());
    size_t marks = 0;
    for (size_t p = t.find("\n\\Mark"); p != std::string::npos; p = t.find("\n\\Mark", p + 1))
        ++marks;
    require(marks == thin.kept);
    requireFinite(t, tex_texts);
    requireFinite(s, xml_texts);
    return 0;
}
