// Helpers shared by the LaTeX exporters: escaping of user text and locale-independent number output (rtl-api §4.2).
#pragma once

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cmath>
#include <string>
#include <string_view>

namespace rtl::LaTeX
{
    //! Returns `str` with every character that is special to LaTeX made printable, so that labels, table cells and
    //! captions compile whatever the user wrote: & % $ # _ { } get a backslash, ~ ^ \ become \textasciitilde,
    //! \textasciicircum and \textbackslash (each followed by a space so that a following letter does not extend the
    //! command name), and < > become $<$ / $>$ (the OT1 text font has no such glyphs).
    inline std::string escapeLaTeXCharacters(const std::string &str)
    {
        std::string out;
        out.reserve(str.size() + str.size() / 4);
        for (char c : str)
        {
            switch (c)
            {
                case '&': case '%': case '$': case '#': case '_': case '{': case '}':
                    out += '\\';
                    out += c;
                    break;
                case '~': out += "\\textasciitilde "; break;
                case '^': out += "\\textasciicircum "; break;
                case '\\': out += "\\textbackslash "; break;
                case '<': case '>':
                    // "$<$$>$" would read as display math: separate adjacent math shifts by a space.
                    if (!out.empty() && out.back() == '$')
                        out += ' ';
                    out += c == '<' ? "$<$" : "$>$";
                    break;
                default: out += c;
            }
        }
        return out;
    }
}

namespace rtl::latex_detail
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
        auto res = std::to_chars(buf, buf + sizeof(buf), value, std::chars_format::general, 6);
        char *end = res.ptr;
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
        // Normalise the length modifier to the type actually passed (long long / unsigned long long / double).
        std::string fmt = format.substr(0, spec + 1);
        for (size_t i = spec + 1; i + 1 < format.size(); ++i)
            if (std::string("hlLjzt").find(format[i]) == std::string::npos)
                fmt += format[i];
        if (std::string("diuoxX").find(conv) != std::string::npos)
            fmt += "ll";
        fmt += conv;
        char buf[128];
        int n;
        switch (conv)
        {
            case 'd': case 'i':
                n = std::snprintf(buf, sizeof(buf), fmt.c_str(), static_cast<long long>(num));
                break;
            case 'u': case 'o': case 'x': case 'X':
                n = std::snprintf(buf, sizeof(buf), fmt.c_str(), static_cast<unsigned long long>(num));
                break;
            case 'f': case 'F': case 'e': case 'E': case 'g': case 'G': case 'a': case 'A':
                n = std::snprintf(buf, sizeof(buf), fmt.c_str(), static_cast<double>(num));
                break;
            default:
                return "";
        }
        if (n < 0)
            return "";
        std::string s(buf, static_cast<size_t>(std::min<int>(n, static_cast<int>(sizeof(buf)) - 1)));
        bool is_float = !(conv == 'd' || conv == 'i' || conv == 'u' || conv == 'o' || conv == 'x' || conv == 'X' ||
                          conv == 'a' || conv == 'A');
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
        return "$" + s + "$";
    }
}
