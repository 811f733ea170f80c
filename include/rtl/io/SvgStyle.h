// Translation of TikZ style text and xcolor colour specs into SVG presentation attributes (for Svg2D), and XML text
// escaping. One small translator, so that a drawing styled for TikZ looks alike in SVG.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "rtl/io/LaTeXUtility.h"

namespace rtl::detail
{
    struct Rgb
    {
        double r = 0, g = 0, b = 0;
    };

    inline std::string trim(const std::string &s)
    {
        size_t b = s.find_first_not_of(" \t\n\r"), e = s.find_last_not_of(" \t\n\r");
        return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
    }

    //! Splits at top-level commas (not inside braces).
    inline std::vector<std::string> splitTopLevel(const std::string &s, char sep = ',')
    {
        std::vector<std::string> parts;
        std::string cur;
        int depth = 0;
        for (char c : s)
        {
            if (c == '{')
                ++depth;
            else if (c == '}')
                depth = std::max(0, depth - 1);
            if (c == sep && depth == 0)
            {
                parts.push_back(trim(cur));
                cur.clear();
            }
            else
                cur += c;
        }
        parts.push_back(trim(cur));
        return parts;
    }

    inline double parseNumber(const std::string &s, double fallback)
    {
        std::string t = trim(s);
        if (t.empty())
            return fallback;
        char *end = nullptr;
        double v = std::strtod(t.c_str(), &end);
        return end == t.c_str() || !std::isfinite(v) ? fallback : v;
    }

    inline double clamp01(double v) { return std::isfinite(v) ? std::min(1.0, std::max(0.0, v)) : 0.0; }

    //! The xcolor base colours (and a few dvipsnames-free extras TikZ users write).
    inline bool namedColor(const std::string &name, Rgb &c)
    {
        static const std::map<std::string, Rgb> named = {
                {"red", {1, 0, 0}},          {"green", {0, 1, 0}},         {"blue", {0, 0, 1}},
                {"cyan", {0, 1, 1}},         {"magenta", {1, 0, 1}},       {"yellow", {1, 1, 0}},
                {"black", {0, 0, 0}},        {"white", {1, 1, 1}},         {"gray", {0.5, 0.5, 0.5}},
                {"darkgray", {0.25, 0.25, 0.25}}, {"lightgray", {0.75, 0.75, 0.75}}, {"brown", {0.75, 0.5, 0.25}},
                {"lime", {0.75, 1, 0}},      {"olive", {0.5, 0.5, 0}},     {"orange", {1, 0.5, 0}},
                {"pink", {1, 0.75, 0.75}},   {"purple", {0.75, 0, 0.25}},  {"teal", {0, 0.5, 0.5}},
                {"violet", {0.5, 0, 0.5}}};
        auto it = named.find(trim(name));
        if (it == named.end())
            return false;
        c = it->second;
        return true;
    }

    inline Rgb hsbToRgb(double h, double s, double v)
    {
        h = clamp01(h) * 6.0;
        s = clamp01(s);
        v = clamp01(v);
        int i = static_cast<int>(std::floor(h)) % 6;
        double f = h - std::floor(h), p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
        switch (i)
        {
            case 0: return {v, t, p};
            case 1: return {q, v, p};
            case 2: return {p, v, t};
            case 3: return {p, q, v};
            case 4: return {t, p, v};
            default: return {v, p, q};
        }
    }

    //! A saveColor spec "{model}{values}" (rgb, RGB, hsb, HTML, gray, cmyk, named); false if not understood.
    inline bool specColor(const std::string &spec, Rgb &c)
    {
        std::string s = trim(spec);
        if (s.size() < 4 || s[0] != '{')
            return false;
        size_t e = s.find('}');
        if (e == std::string::npos || e + 1 >= s.size() || s[e + 1] != '{' || s.back() != '}')
            return false;
        std::string model = s.substr(1, e - 1), values = s.substr(e + 2, s.size() - e - 3);
        std::vector<std::string> v = splitTopLevel(values);
        auto at = [&](size_t i) { return i < v.size() ? parseNumber(v[i], 0.0) : 0.0; };
        if (model == "rgb" && v.size() == 3)
            c = {clamp01(at(0)), clamp01(at(1)), clamp01(at(2))};
        else if (model == "RGB" && v.size() == 3)
            c = {clamp01(at(0) / 255), clamp01(at(1) / 255), clamp01(at(2) / 255)};
        else if (model == "hsb" && v.size() == 3)
            c = hsbToRgb(at(0), at(1), at(2));
        else if (model == "gray" && v.size() == 1)
            c = {clamp01(at(0)), clamp01(at(0)), clamp01(at(0))};
        else if (model == "cmyk" && v.size() == 4)
        {
            double k = clamp01(at(3));
            c = {(1 - clamp01(at(0))) * (1 - k), (1 - clamp01(at(1))) * (1 - k), (1 - clamp01(at(2))) * (1 - k)};
        }
        else if (model == "HTML" && values.size() == 6 &&
                 values.find_first_not_of("0123456789abcdefABCDEF") == std::string::npos)
        {
            long x = std::strtol(values.c_str(), nullptr, 16);
            c = {((x >> 16) & 255) / 255.0, ((x >> 8) & 255) / 255.0, (x & 255) / 255.0};
        }
        else if (model == "named")
            return namedColor(values, c);
        else
            return false;
        return true;
    }

    //! Colour expressions as TikZ/xcolor reads them: a name (base colour or registered ColorX) or a mix
    //! "c1!p1!c2!p2!c3..." (p % of the left, the rest of the right; a missing last colour is white).
    class ColorResolver
    {
    public:
        //! Registered colours (name, spec), e.g. from TikzNames::colorList().
        explicit ColorResolver(const std::vector<std::pair<std::string, std::string>> &registered)
        {
            for (const auto &r : registered)
            {
                Rgb c;
                if (specColor(r.second, c))
                    user[r.first] = c;
            }
        }

        bool resolve(const std::string &expr, Rgb &out) const
        {
            std::vector<std::string> parts = splitTopLevel(expr, '!');
            Rgb acc;
            if (!base(parts[0], acc))
                return false;
            for (size_t i = 1; i < parts.size(); i += 2)
            {
                double p = clamp01(parseNumber(parts[i], 100.0) / 100.0);
                Rgb other{1, 1, 1};
                if (i + 1 < parts.size() && !base(parts[i + 1], other))
                    return false;
                acc = {p * acc.r + (1 - p) * other.r, p * acc.g + (1 - p) * other.g, p * acc.b + (1 - p) * other.b};
            }
            out = acc;
            return true;
        }

        //! "#rrggbb", or "" if the expression is not a colour.
        std::string hex(const std::string &expr) const
        {
            Rgb c;
            if (!resolve(expr, c))
                return "";
            char buf[8];
            auto byte = [](double v) { return static_cast<int>(std::lround(clamp01(v) * 255.0)); };
            std::snprintf(buf, sizeof(buf), "#%02x%02x%02x", byte(c.r), byte(c.g), byte(c.b));
            return buf;
        }

    private:
        bool base(const std::string &name, Rgb &c) const
        {
            std::string n = trim(name);
            auto it = user.find(n);
            if (it != user.end())
            {
                c = it->second;
                return true;
            }
            return namedColor(n, c);
        }
        std::map<std::string, Rgb> user;
    };

    //! The SVG side of one TikZ style: colours, widths in cm, dashes, opacities, arrow tips and text anchor.
    struct SvgStyle
    {
        std::string stroke, fill, text_color;   // "#rrggbb" or "" (not set)
        bool draw_none = false, fill_none = false;
        double line_width_cm = 0.4 / 28.4527559;   // TikZ default: 0.4 pt
        std::string dash;                           // "dotted", "dashed", "densely dotted", ... or ""
        double opacity = 1, fill_opacity = 1, stroke_opacity = 1;
        bool arrow_end = false, arrow_beg = false;
        std::string anchor;                         // TikZ node anchor, e.g. "west", "north east"
    };

    inline double tikzWidthCm(const std::string &key)
    {
        static const std::map<std::string, double> widths = {
                {"ultra thin", 0.1}, {"very thin", 0.2}, {"thin", 0.4},  {"semithick", 0.6},
                {"thick", 0.8},      {"very thick", 1.2}, {"ultra thick", 1.6}};
        auto it = widths.find(key);
        return it == widths.end() ? -1.0 : it->second / 28.4527559;
    }

    //! A TeX length ("0.8pt", "1mm", "0.05cm", "2") in cm; `fallback` if it is not one.
    inline double texLengthCm(const std::string &text, double fallback)
    {
        std::string t = trim(text);
        char *end = nullptr;
        double v = std::strtod(t.c_str(), &end);
        if (end == t.c_str() || !std::isfinite(v) || v < 0)
            return fallback;
        std::string unit = trim(std::string(end));
        if (unit.empty() || unit == "pt")
            return v / 28.4527559;
        if (unit == "cm")
            return v;
        if (unit == "mm")
            return v / 10;
        if (unit == "in")
            return v * 2.54;
        if (unit == "bp")
            return v * 2.54 / 72;
        return fallback;
    }

    //! Parses a normalised style ("style={...}" or bare key/value text).
    inline SvgStyle parseTikzStyle(const std::string &style_text, const ColorResolver &colors)
    {
        std::string s = trim(style_text);
        if (s.rfind("style", 0) == 0)
        {
            size_t eq = s.find('=');
            s = eq == std::string::npos ? std::string() : trim(s.substr(eq + 1));
            if (s.size() >= 2 && s.front() == '{' && s.back() == '}')
                s = s.substr(1, s.size() - 2);
        }
        SvgStyle st;
        for (const std::string &item : splitTopLevel(s))
        {
            if (item.empty())
                continue;
            size_t eq = item.find('=');
            std::string key = trim(item.substr(0, eq)), value = eq == std::string::npos ? "" : trim(item.substr(eq + 1));
            if (!value.empty() && value.front() == '{' && value.back() == '}')
                value = trim(value.substr(1, value.size() - 2));
            auto color = [&](std::string &target, bool &none) {
                if (value == "none")
                    none = true;
                else if (value.empty())
                    target = target.empty() ? "#000000" : target;
                else
                {
                    std::string h = colors.hex(value);
                    if (!h.empty())
                        target = h;
                }
            };
            if (key == "draw")
                color(st.stroke, st.draw_none);
            else if (key == "fill")
                color(st.fill, st.fill_none);
            else if (key == "color")
            {
                std::string h = colors.hex(value);
                if (!h.empty())
                    st.stroke = st.text_color = h;
            }
            else if (key == "text")
                st.text_color = colors.hex(value);
            else if (key == "line width")
                st.line_width_cm = texLengthCm(value, st.line_width_cm);
            else if (tikzWidthCm(key) > 0 && eq == std::string::npos)
                st.line_width_cm = tikzWidthCm(key);
            else if (key == "opacity")
                st.opacity = clamp01(parseNumber(value, 1));
            else if (key == "fill opacity")
                st.fill_opacity = clamp01(parseNumber(value, 1));
            else if (key == "draw opacity")
                st.stroke_opacity = clamp01(parseNumber(value, 1));
            else if (key == "anchor")
                st.anchor = value;
            else if (key == "->" || key == "-latex" || key == "-stealth" || key == "-{>}")
                st.arrow_end = true;
            else if (key == "<-" || key == "latex-" || key == "stealth-")
                st.arrow_beg = true;
            else if (key == "<->" || key == "latex-latex")
                st.arrow_end = st.arrow_beg = true;
            else if (key.find("dotted") != std::string::npos || key.find("dashed") != std::string::npos ||
                     key == "dashdotted")
                st.dash = key;
            else if (key == "solid")
                st.dash.clear();
            else if (eq == std::string::npos)
            {
                // A bare colour sets the colour of lines and text (TikZ's "red").
                std::string h = colors.hex(key);
                if (!h.empty())
                    st.stroke = st.text_color = h;
            }
        }
        return st;
    }

    //! stroke-dasharray for a TikZ dash pattern (lengths in cm), "" for solid.
    inline std::string dashArray(const std::string &dash, double width_cm)
    {
        const double pt = 1 / 28.4527559;
        auto pair = [&](double on, double off) {
            return detail::number(std::max(on, width_cm * 0.5)) + " " + detail::number(off);
        };
        if (dash.empty())
            return "";
        if (dash.find("dashdotted") != std::string::npos)
            return pair(3 * pt, 2 * pt) + " " + pair(0.1 * pt, 2 * pt);
        bool dense = dash.find("densely") != std::string::npos, loose = dash.find("loosely") != std::string::npos;
        if (dash.find("dotted") != std::string::npos)
            return pair(0.1 * pt, (dense ? 1 : loose ? 4 : 2) * pt);
        return pair(3 * pt, (dense ? 2 : loose ? 6 : 3) * pt);
    }

    //! Text fit for XML character data and attribute values: & < > " ' escaped; control characters (other than tab
    //! and newline, which become spaces) dropped; invalid UTF-8 replaced by U+FFFD.
    inline std::string xmlEscape(const std::string &text)
    {
        std::string clean = LaTeX::sanitizeUtf8(text), out;
        out.reserve(clean.size());
        for (char c : clean)
        {
            switch (c)
            {
                case '&': out += "&amp;"; break;
                case '<': out += "&lt;"; break;
                case '>': out += "&gt;"; break;
                case '"': out += "&quot;"; break;
                case '\'': out += "&apos;"; break;
                default: out += c;
            }
        }
        return out;
    }
}
