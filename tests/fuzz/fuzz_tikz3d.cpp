// libFuzzer harness for the 3D TikZ renderer (rtl/io/LaTeXTikz3D.h): marks, lines, faces, axes, regions and views
// decoded from the bytes (values often huge, tiny or non-finite), then writeTEX to a stream. The output must be safe
// LaTeX (ASCII, balanced braces, no bare %), of bounded size, without non-finite numbers. A scene beyond TeX's
// dimensions (std::length_error, detail::refuseBeyondTex) is a valid outcome if nothing was written.
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <string>

#include "fuzz_tikz_drawings.h"
#include "fuzz_tikz_input.h"
#include "rtl/io/LaTeXTikz3D.h"

using fuzz_tikz::require;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    rtl::LaTeXTikz3D d = fuzz_tikz::decodeScene3D(data, size);
    std::ostringstream os;
    try
    {
        d.writeTEX(os);
    }
    catch (const std::length_error &e)
    {
        require(os.str().empty() && fuzz_tikz::beyondTex(e));   // the documented refusal writes nothing
        return 0;
    }
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
