// Helpers shared by the LaTeX exporters: escaping of user text and locale-independent number output
// (docs/reference.md, "LaTeX text").
#pragma once

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cmath>
#include <string>
#include <string_view>
#include <limits>
#include <type_traits>

namespace rtl::LaTeX
{
    //! Returns `str` as valid UTF-8 without control characters: every byte that does not start a well-formed UTF-8
    //! sequence (overlong forms, surrogates and code points above U+10FFFF included) becomes U+FFFD; tab, newline
    //! and carriage return become a space; other C0 controls, DEL and C1 controls (U+0080-U+009F) are dropped, and so
    //! are U+FFFE/U+FFFF (not characters in XML).
    inline std::string sanitizeUtf8(const std::string &str)
    {
        std::string out;
        out.reserve(str.size());
        const auto *s = reinterpret_cast<const unsigned char *>(str.data());
        size_t n = str.size();
        for (size_t i = 0; i < n;)
        {
            unsigned char c = s[i];
            if (c < 0x80)
            {
                if (c == '\t' || c == '\n' || c == '\r')
                    out += ' ';
                else if (c >= 0x20 && c != 0x7f)
                    out += static_cast<char>(c);
                ++i;
                continue;
            }
            size_t len = c >= 0xc2 && c <= 0xdf ? 2 : c >= 0xe0 && c <= 0xef ? 3 : c >= 0xf0 && c <= 0xf4 ? 4 : 0;
            unsigned long cp = len == 2 ? c & 0x1fu : len == 3 ? c & 0x0fu : c & 0x07u;
            bool ok = len > 0 && i + len <= n;
            for (size_t k = 1; ok && k < len; ++k)
            {
                ok = (s[i + k] & 0xc0) == 0x80;
                cp = (cp << 6) | (s[i + k] & 0x3fu);
            }
            ok = ok && !(len == 3 && cp < 0x800) && !(len == 4 && (cp < 0x10000 || cp > 0x10ffff)) &&
                 !(cp >= 0xd800 && cp <= 0xdfff);
            if (!ok)
            {
                out += "\xef\xbf\xbd";
                ++i;
                continue;
            }
            if (!(cp >= 0x80 && cp <= 0x9f) && cp != 0xfffe && cp != 0xffff)
                out.append(str, i, len);
            i += len;
        }
        return out;
    }

    //! ASCII LaTeX for one non-ASCII code point: Latin-1 letters as accent commands, Greek letters and common
    //! symbols in math, typographic punctuation as TeX ligatures; "?" for everything else (so that pdflatex compiles
    //! it with any input encoding and the default OT1 fonts).
    inline std::string unicodeToLaTeX(unsigned long cp)
    {
        static const char *latin1[64] = {
                "\\`{A}", "\\'{A}", "\\^{A}", "\\~{A}", "\\\"{A}", "\\AA{}", "\\AE{}", "\\c{C}",
                "\\`{E}", "\\'{E}", "\\^{E}", "\\\"{E}", "\\`{I}", "\\'{I}", "\\^{I}", "\\\"{I}",
                "D", "\\~{N}", "\\`{O}", "\\'{O}", "\\^{O}", "\\~{O}", "\\\"{O}", "$\\times$",
                "\\O{}", "\\`{U}", "\\'{U}", "\\^{U}", "\\\"{U}", "\\'{Y}", "Th", "\\ss{}",
                "\\`{a}", "\\'{a}", "\\^{a}", "\\~{a}", "\\\"{a}", "\\aa{}", "\\ae{}", "\\c{c}",
                "\\`{e}", "\\'{e}", "\\^{e}", "\\\"{e}", "\\`{\\i}", "\\'{\\i}", "\\^{\\i}", "\\\"{\\i}",
                "d", "\\~{n}", "\\`{o}", "\\'{o}", "\\^{o}", "\\~{o}", "\\\"{o}", "$\\div$",
                "\\o{}", "\\`{u}", "\\'{u}", "\\^{u}", "\\\"{u}", "\\'{y}", "th", "\\\"{y}"};
        static const char *greek_lower[25] = {"alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta", "theta",
                                              "iota", "kappa", "lambda", "mu", "nu", "xi", "o", "pi", "rho",
                                              "varsigma", "sigma", "tau", "upsilon", "phi", "chi", "psi", "omega"};
        static const char *greek_upper[25] = {"A", "B", "Gamma", "Delta", "E", "Z", "H", "Theta", "I", "K",
                                              "Lambda", "M", "N", "Xi", "O", "Pi", "P", "", "Sigma", "T",
                                              "Upsilon", "Phi", "X", "Psi", "Omega"};
        if (cp >= 0xc0 && cp <= 0xff)
            return latin1[cp - 0xc0];
        if (cp >= 0x3b1 && cp <= 0x3c9)
        {
            std::string g = greek_lower[cp - 0x3b1];
            return g == "o" ? g : "$\\" + g + "$";
        }
        if (cp >= 0x391 && cp <= 0x3a9 && cp != 0x3a2)
        {
            std::string g = greek_upper[cp - 0x391];
            return g.size() == 1 ? g : "$\\" + g + "$";
        }
        switch (cp)
        {
            case 0xa0: return "~";
            case 0xa3: return "\\pounds{}";
            case 0xa7: return "\\S{}";
            case 0xa9: return "\\copyright{}";
            case 0xb0: return "$^\\circ$";
            case 0xb1: return "$\\pm$";
            case 0xb2: return "$^2$";
            case 0xb3: return "$^3$";
            case 0xb5: return "$\\mu$";
            case 0xb6: return "\\P{}";
            case 0xb7: return "$\\cdot$";
            case 0x2013: return "--";
            case 0x2014: return "---";
            case 0x2018: return "`";
            case 0x2019: return "'";
            case 0x201c: return "``";
            case 0x201d: return "''";
            case 0x2026: return "\\ldots{}";
            case 0x2190: return "$\\leftarrow$";
            case 0x2192: return "$\\rightarrow$";
            case 0x2212: return "$-$";
            case 0x221e: return "$\\infty$";
            case 0x2248: return "$\\approx$";
            case 0x2260: return "$\\neq$";
            case 0x2264: return "$\\leq$";
            case 0x2265: return "$\\geq$";
            default: return "?";
        }
    }

    //! Returns `str` as ASCII LaTeX that compiles in text mode whatever the user wrote: & % $ # _ { } get a
    //! backslash; ~ ^ \ become `\textasciitilde`, `\textasciicircum` and `\textbackslash` (each followed by a space so
    //! that a following letter does not extend the command name); < > become $<$ / $>$ (the OT1 text font has no
    //! such glyphs). The text is first made valid UTF-8 without control characters (sanitizeUtf8: invalid bytes
    //! become U+FFFD, tab/newline a space, other controls and DEL are dropped); non-ASCII characters are then
    //! written by unicodeToLaTeX (accent commands, math symbols, or "?" - U+FFFD included).
    inline std::string escapeLaTeXCharacters(const std::string &str)
    {
        std::string clean = sanitizeUtf8(str), out;
        out.reserve(clean.size() + clean.size() / 4);
        // "$<$$>$" would read as display math: separate adjacent math shifts by a space.
        auto math = [&out](const std::string &m) {
            if (!out.empty() && out.back() == '$')
                out += ' ';
            out += m;
        };
        const auto *s = reinterpret_cast<const unsigned char *>(clean.data());
        for (size_t i = 0; i < clean.size(); ++i)
        {
            char c = clean[i];
            if (s[i] >= 0x80)
            {
                // sanitizeUtf8 guarantees a complete, valid sequence here.
                size_t len = s[i] >= 0xf0 ? 4 : s[i] >= 0xe0 ? 3 : 2;
                unsigned long cp = len == 2 ? s[i] & 0x1fu : len == 3 ? s[i] & 0x0fu : s[i] & 0x07u;
                for (size_t k = 1; k < len; ++k)
                    cp = (cp << 6) | (s[i + k] & 0x3fu);
                i += len - 1;
                std::string t = unicodeToLaTeX(cp);
                if (t.front() == '$')
                    math(t);
                else
                    out += t;
                continue;
            }
            switch (c)
            {
                case '&': case '%': case '$': case '#': case '_': case '{': case '}':
                    out += '\\';
                    out += c;
                    break;
                case '~': out += "\\textasciitilde "; break;
                case '^': out += "\\textasciicircum "; break;
                case '\\': out += "\\textbackslash "; break;
                case '<': case '>': math(c == '<' ? "$<$" : "$>$"); break;
                default: out += c;
            }
        }
        return out;
    }
}

namespace rtl::detail
{
    inline constexpr double pi = 3.14159265358979323846;

    //! Appends a finite coordinate with 6 significant digits in the C locale (TikZ does not accept "1,5"); fast enough
    //! for figures of millions of points. Non-finite values are written as 0 (callers filter them out first).
    inline void appendNumber(std::string &out, double value)
    {
        if (!std::isfinite(value))
            value = 0.0;
        if (std::abs(value) < 1e-30)
            value = 0.0;
        char buf[32];
#if defined(__cpp_lib_to_chars)
        char *end = std::to_chars(buf, buf + sizeof(buf), value, std::chars_format::general, 6).ptr;
#else
        // Standard libraries without floating-point to_chars (libc++ before 14, e.g. Emscripten 3.1's): the
        // standard defines chars_format::general with a precision as printf's %.*g in the C locale, which programs
        // have unless they call setlocale; the package's tests compare this path's output with the native one.
        const int n = std::snprintf(buf, sizeof(buf), "%.6g", value);
        char *end = buf + (n > 0 && n < static_cast<int>(sizeof(buf)) ? n : 0);
#endif
        // TikZ's parser reads "1e-05" fine, but not "1e+05": drop the plus sign.
        std::string_view sv(buf, static_cast<size_t>(end - buf));
        auto plus = sv.find('+');
        if (plus == std::string_view::npos)
            out.append(buf, end);
        else
        {
            out.append(buf, plus);
            out.append(buf + plus + 1, end);
        }
    }

    inline std::string number(double value)
    {
        std::string s;
        appendNumber(s, value);
        return s;
    }

    //! Name suffix of the i-th registered style/colour/mark: decimal digits mapped to letters (0 -> A, ..., 9 -> J),
    //! because TeX control sequence names cannot contain digits.
    inline std::string indexToLetters(size_t index)
    {
        std::string digits = std::to_string(index);
        for (char &c : digits)
            c = static_cast<char>('A' + (c - '0'));
        return digits;
    }

    //! Style strings are full TikZ key/value text starting with "style=" (e.g. "style={draw=red}"); anything else is
    //! wrapped so that "<Name>/.<text>" is always a valid style definition.
    inline std::string normalizeStyle(const std::string &style)
    {
        if (style.rfind("style=", 0) == 0 || style.rfind("style =", 0) == 0)
            return style;
        return "style={" + style + "}";
    }

    //! Single-quotes a path for /bin/sh.
    inline std::string shellQuote(const std::string &s)
    {
        std::string out = "'";
        for (char c : s)
        {
            if (c == '\'')
                out += "'\\''";
            else
                out += c;
        }
        out += '\'';
        return out;
    }

    //! True if `num` converts to the integer type I without undefined behaviour (finite and within range after
    //! truncation toward zero).
    template<typename I, typename T>
    bool fitsInteger(T num)
    {
        if constexpr (std::is_integral_v<T>)
            return true;   // integral conversions are defined (modular for unsigned targets)
        else
        {
            long double v = static_cast<long double>(num);
            if (!std::isfinite(v))
                return false;
            v = std::trunc(v);
            return v >= static_cast<long double>(std::numeric_limits<I>::min()) &&
                   v < static_cast<long double>(std::numeric_limits<I>::max()) + 1.0L;
        }
    }

    //! Literal text of a label format (before its conversion) for math mode: % # & $ escaped; braces kept if they
    //! balance, escaped otherwise.
    inline std::string latexFormatLiteral(const std::string &text)
    {
        int depth = 0;
        bool balanced = true;
        for (char c : text)
        {
            depth += c == '{' ? 1 : c == '}' ? -1 : 0;
            balanced = balanced && depth >= 0;
        }
        balanced = balanced && depth == 0;
        std::string out;
        for (size_t i = 0; i < text.size(); ++i)
        {
            char c = text[i];
            if (c == '%' && i + 1 < text.size() && text[i + 1] == '%')
                ++i;   // "%%" is one literal percent sign
            if (c == '%' || c == '#' || c == '&' || c == '$' || (!balanced && (c == '{' || c == '}')))
                out += '\\';
            out += c;
        }
        return out;
    }

    //! See LaTeXTikz2D::numberToLatexString. Defined for every value of T and every format: a value that the integer
    //! conversion of d i (long long) or u o x X (unsigned long long) cannot represent - NaN, +-inf, out of range, or
    //! negative (<= -1) for u o x X - is printed as with %g instead (e.g. "$-5$", "$10^{19}$", "$nan$", "$-inf$").
    //! A format without exactly one conversion at its end gives "". Literal text before the conversion is kept
    //! (math mode; % # & $ escaped, unbalanced braces escaped).
    template<typename T>
    std::string numberToLatexString(T num, const std::string &format)
    {
        if (format.empty())
            return "";
        // Exactly one conversion, at the end ("%%" is a literal percent): anything else would be undefined for
        // snprintf with a single argument.
        size_t spec = std::string::npos;
        for (size_t i = 0; i < format.size(); ++i)
        {
            if (format[i] != '%')
                continue;
            if (i + 1 < format.size() && format[i + 1] == '%')
            {
                ++i;
                continue;
            }
            if (spec != std::string::npos)
                return "";
            spec = i;
        }
        if (spec == std::string::npos ||
            format.find_first_not_of("-+ #0123456789.hlLjzt", spec + 1) != format.size() - 1)
            return "";
        char conv = format.back();
        if (std::string("diuoxXfFeEgGaA").find(conv) == std::string::npos)
            return "";
        bool signed_int = conv == 'd' || conv == 'i', unsigned_int = std::string("uoxX").find(conv) != std::string::npos;
        if ((signed_int && !fitsInteger<long long>(num)) || (unsigned_int && !fitsInteger<unsigned long long>(num)))
        {
            std::string fallback = format.substr(0, spec) + "%g";
            return numberToLatexString(static_cast<double>(num), fallback);
        }
        // Normalise the length modifier to the type actually passed (long long / unsigned long long / double).
        std::string fmt = "%";
        for (size_t i = spec + 1; i + 1 < format.size(); ++i)
            if (std::string("hlLjzt").find(format[i]) == std::string::npos)
                fmt += format[i];
        if (signed_int || unsigned_int)
            fmt += "ll";
        fmt += conv;
        char buf[128];
        int n;
        if (signed_int)
            n = std::snprintf(buf, sizeof(buf), fmt.c_str(), static_cast<long long>(num));
        else if (unsigned_int)
            n = std::snprintf(buf, sizeof(buf), fmt.c_str(), static_cast<unsigned long long>(num));
        else
            n = std::snprintf(buf, sizeof(buf), fmt.c_str(), static_cast<double>(num));
        if (n < 0)
            return "";
        std::string s(buf, static_cast<size_t>(std::min<int>(n, static_cast<int>(sizeof(buf)) - 1)));
        bool is_float = !(signed_int || unsigned_int || conv == 'a' || conv == 'A');
        size_t e = is_float ? s.find_first_of("eE") : std::string::npos;
        if (e != std::string::npos && e + 1 < s.size())
        {
            std::string mantissa = s.substr(0, e), exponent = s.substr(e + 1);
            bool negative = false;
            if (!exponent.empty() && (exponent[0] == '+' || exponent[0] == '-'))
            {
                negative = exponent[0] == '-';
                exponent.erase(0, 1);
            }
            size_t nz = exponent.find_first_not_of('0');
            exponent = nz == std::string::npos ? "0" : exponent.substr(nz);
            if (negative)
                exponent = "-" + exponent;
            std::string trimmed = mantissa;
            trimmed.erase(0, trimmed.find_first_not_of(' '));
            if (trimmed == "1")
                s = "10^{" + exponent + "}";
            else
                s = mantissa + " \\cdot 10^{" + exponent + "}";
        }
        // '#' (alternate form) can put nothing special in the number; the literal prefix is escaped.
        return "$" + latexFormatLiteral(format.substr(0, spec)) + s + "$";
    }
}
