// libFuzzer harness for the 3D TikZ renderer (rtl/io/LaTeXTikz3D.h): marks, lines, faces, axes, regions and views
// decoded from the bytes (values often huge, tiny or non-finite), then writeTEX to a stream. The output must be safe
// LaTeX (ASCII, balanced braces, no bare %), of bounded size, without non-finite numbers.
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "fuzz_tikz_input.h"
#include "rtl/io/LaTeXTikz3D.h"

using fuzz_tikz::require;
using rtl::Vector3f;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_tikz::Reader in(data, size);
    rtl::LaTeXTikz3D d;
    size_t faces = 0, axes = 0, ops = 0;
    auto v3 = [&]() { float x = in.value(), y = in.value(); return Vector3f(x, y, in.value()); };
    const char *const marks[] = {rtl::LaTeXTikz3D::latex_mark_cross, rtl::LaTeXTikz3D::latex_mark_dot,
                                 rtl::LaTeXTikz3D::latex_mark_robot, rtl::LaTeXTikz3D::latex_mark_blank};
    while (!in.empty() && ops++ < 48)
    {
        switch (in.byte() % 14)
        {
            case 0: d.setExportSize(in.value(), in.value()); break;
            case 1: { float a = in.value(), b = in.value(), c = in.value(); d.setExportClipping(a, b, c, in.value()); break; }
            case 2: { float fov = in.value(); d.setView(fov, v3()); break; }
            case 3: d.setBorder(in.value()); break;
            case 4: d.setGridAxisOverrun(in.byte() & 1, in.value()); break;
            case 5: { Vector3f a = v3(); d.setMaxPlotRegion(a, v3()); break; }
            case 6: { Vector3f a = v3(); d.setMinPlotRegion(a, v3()); break; }
            case 7: { Vector3f p = v3(); float rot = in.value(); d.addMark(p, in.pick(fuzz_tikz::styles), in.pick(marks), rot, in.value()); break; }
            case 8: { Vector3f a = v3(); d.addLine(rtl::LineSegment3f(a, v3()), in.pick(fuzz_tikz::styles)); break; }
            case 9:
                if (faces++ < 12)
                {
                    Vector3f n = v3();
                    rtl::Polygon3Df f(n, in.value());
                    size_t k = 3 + in.byte() % 4;
                    for (size_t i = 0; i < k; ++i)
                        f.addPoint(v3());
                    d.addFace(f, in.pick(fuzz_tikz::styles), in.pick(fuzz_tikz::styles), in.pick(fuzz_tikz::styles));
                }
                break;
            case 10:
                if (axes++ < 4)
                {
                    std::string st = in.pick(fuzz_tikz::styles), fmt = in.pick(fuzz_tikz::formats);
                    unsigned pos = in.byte() & 15;
                    float tick = in.value();
                    Vector3f a = v3();
                    d.addAxis(st, fmt, pos, tick, a, v3());
                }
                break;
            case 11: d.setFrameStyle(in.pick(fuzz_tikz::styles)); break;
            case 12: d.saveColor(in.pick(fuzz_tikz::colors)); break;
            case 13: (in.byte() & 1) ? d.clearData() : d.clearAll(); break;
        }
    }
    std::ostringstream os;
    d.writeTEX(os);
    const std::string t = os.str();
    fuzz_tikz::requireSafeLaTeX(t);
    require(t.size() < 8'000'000);
    for (const char *w : {"nan", "inf"})
        for (size_t p = t.find(w); p != std::string::npos; p = t.find(w, p + 1))
            if (!(p > 0 && std::isalpha(static_cast<unsigned char>(t[p - 1]))))   // only inside words
            {
                std::fprintf(stderr, "'%s' in the output: ...%s...\n", w, t.substr(p < 80 ? 0 : p - 80, 160).c_str());
                require(false);
            }
    return 0;
}
