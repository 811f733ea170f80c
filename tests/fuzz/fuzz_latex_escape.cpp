// libFuzzer harness for the LaTeX escaper (rtl/io/LaTeXUtility.h): any bytes become ASCII LaTeX with balanced braces,
// no unescaped special character outside math, paired math shifts; sanitizeUtf8 gives valid UTF-8 and is idempotent.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_tikz_input.h"
#include "rtl/io/LaTeXUtility.h"

using fuzz_tikz::require;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    std::string in(reinterpret_cast<const char *>(data), size);
    std::string clean = rtl::LaTeX::sanitizeUtf8(in);
    require(rtl::LaTeX::sanitizeUtf8(clean) == clean);
    require(clean.size() <= 3 * in.size());
    std::string out = rtl::LaTeX::escapeLaTeXCharacters(in);
    fuzz_tikz::requireSafeLaTeX(out);
    require(out.size() <= 20 * in.size() + 1);
    // Outside math, the characters TeX treats specially appear only escaped.
    bool in_math = false;
    for (size_t i = 0; i < out.size(); ++i)
    {
        char c = out[i];
        if (c == '\\')
        {
            ++i;
            continue;
        }
        if (c == '$')
            in_math = !in_math;
        else if (!in_math)
            require(c != '&' && c != '#' && c != '_' && c != '^');   // '~' only comes from U+00A0 (a tie)
        else
            require(c != '&' && c != '#' && c != '%');
    }
    require(!in_math);
    // ASCII text without specials is left alone.
    bool plain = true;
    for (unsigned char c : in)
        plain = plain && c >= 0x20 && c < 0x7f && std::string("&%$#_{}~^\\<>").find(static_cast<char>(c)) == std::string::npos;
    if (plain)
        require(out == in);
    return 0;
}
