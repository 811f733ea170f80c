// Shared by the LaTeX/TikZ/SVG harnesses: a reader that decodes fuzz bytes into values, and the invariants every
// LaTeX output must keep (ASCII only, balanced unescaped braces, no bare %, paired math shifts).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace fuzz_tikz
{
    //! Aborts (a libFuzzer finding) naming the source line of the broken invariant.
    inline void require(bool ok, const char *file = __builtin_FILE(), int line = __builtin_LINE())
    {
        if (ok)
            return;
        std::fprintf(stderr, "invariant broken at %s:%d\n", file, line);
        std::abort();
    }

    class Reader
    {
    public:
        Reader(const uint8_t *data, size_t size) : d(data), n(size) {}
        bool empty() const { return i >= n; }
        uint8_t byte() { return i < n ? d[i++] : 0; }
        float raw() { float f = 0; std::memcpy(&f, take(4).data(), 4); return f; }
        //! Mostly "interesting" values (small, huge, tiny, non-finite), sometimes raw bit patterns.
        float value()
        {
            static const float table[] = {0.0f, 1.0f, -1.0f, 0.5f, 2.0f, 10.0f, -10.0f, 1e-3f, -1e-3f, 1e3f, 1e6f, -1e6f,
                                          1500.0f, 800.0f, 1e16f, 7.7e31f, 3e38f, -3e38f, 1e-30f, 1e-45f,
                                          __builtin_nanf(""), __builtin_inff(), -__builtin_inff(), 0.1f, 1e19f};
            uint8_t b = byte();
            if (b < 200)
                return table[b % (sizeof(table) / sizeof(table[0]))] * (b >= 100 ? 1.37f : 1.0f);
            return raw();
        }
        std::string text(size_t max_len = 48)
        {
            size_t len = byte() % (max_len + 1);
            return take(len);
        }
        template<size_t N>
        const char *pick(const char *const (&options)[N]) { return options[byte() % N]; }

    private:
        std::string take(size_t len)
        {
            std::string s(len, '\0');
            for (size_t k = 0; k < len; ++k)
                s[k] = static_cast<char>(byte());
            return s;
        }
        const uint8_t *d;
        size_t n, i = 0;
    };

    //! Styles as a user writes them (style text is TikZ code the writers copy, so it is not fuzzed byte-wise).
    inline const char *const styles[] = {"draw=black", "style={draw=red,thick}", "fill=blue!20", "", "draw=gray,dotted",
                                         "style={fill=ColorA,draw=black,line width=0.8pt,opacity=0.5}", "->",
                                         "anchor=west", "style={draw=none,fill=green!30!black}"};
    inline const char *const formats[] = {"%d", "%u", "%x", "%g", "%.2f", "%.0e", "%5.1E", "%a", "%ld", "", "%q",
                                          "100%% %d", "x=%i", "%o", "%+08.3f", "%#X", "%d %d", "%"};
    inline const char *const colors[] = {"{rgb}{1,0,0}", "{RGB}{0,128,255}", "{hsb}{0.3,0.8,0.5}", "{HTML}{1F77B4}",
                                         "{gray}{0.5}"};

    //! LaTeX text that pdflatex can read: printable ASCII (and newlines/tabs), braces balanced when the escaped
    //! ones (\{ \}) are not counted, no bare '%' (a comment), an even number of bare '$'.
    inline void requireSafeLaTeX(const std::string &s)
    {
        long depth = 0, math = 0;
        for (size_t i = 0; i < s.size(); ++i)
        {
            unsigned char c = static_cast<unsigned char>(s[i]);
            require((c >= 0x20 && c < 0x7f) || c == '\n' || c == '\t');
            if (c == '\\')
            {
                require(i + 1 < s.size());
                ++i;   // the escaped character (or the first letter of a command name)
                continue;
            }
            require(c != '%');
            if (c == '{')
                ++depth;
            if (c == '}')
                require(--depth >= 0);
            if (c == '$')
                ++math;
        }
        require(depth == 0);
        require(math % 2 == 0);
    }
}
