// Internal pieces shared by LaTeXTikz2D and LaTeXTikz3D: the standalone document around a tikzpicture, the registry
// of generated style/colour/mark names, mark templates, coordinate text and label anchors.
#pragma once

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "rtl/io/LaTeXUtility.h"
#include "rtl/io/TextSink.h"

namespace rtl::detail
{
    //! Mark templates (TikZ code around the local origin, sized by \MarkRadius; "@style" becomes the style name),
    //! published by both exporters as latex_mark_* / latex_var_style.
    inline constexpr const char *tikz_mark_blank = "";
    inline constexpr const char *tikz_mark_cross =
            "\\draw[@style] (-\\MarkRadius,-\\MarkRadius) -- (\\MarkRadius,\\MarkRadius) "
            "(-\\MarkRadius,\\MarkRadius) -- (\\MarkRadius,-\\MarkRadius);";
    inline constexpr const char *tikz_mark_mark = "\\draw[@style] (0,-\\MarkRadius) -- (0,\\MarkRadius);";
    inline constexpr const char *tikz_mark_dot = "\\filldraw[@style] (0,0) circle (\\MarkRadius);";
    inline constexpr const char *tikz_mark_robot =
            "\\filldraw[@style] (0,0) circle (\\MarkRadius); \\draw[@style] (0,0) -- (2*\\MarkRadius,0);";
    inline constexpr const char *tikz_var_style = "@style";

    //! Label position bit flags, published by both exporters as position_*.
    inline constexpr unsigned int tikz_position_above = 0x01, tikz_position_below = 0x02,
                                  tikz_position_right = 0x04, tikz_position_left = 0x08;

    //! What a TikZ writer may put on paper, in cm: TeX's largest dimension is 16383.99998 pt (about 575 cm), and
    //! a picture extent, mark size, border or clip corner beyond it fails with "! Dimension too large". The margin
    //! leaves room for tick labels, descriptions and mark strokes around the checked extent.
    inline constexpr double tex_paper_limit_cm = 500.0;

    //! Throws std::length_error "<who>: <what> of <cm> cm is beyond TeX's dimensions (limit 500 cm)" unless
    //! |cm| <= tex_paper_limit_cm (NaN and infinities are refused too). The writers call it before writing anything.
    inline void refuseBeyondTex(double cm, const char *what, const std::string &who)
    {
        if (std::abs(cm) <= tex_paper_limit_cm)
            return;
        char value[32];
        std::snprintf(value, sizeof(value), "%g", cm);
        throw std::length_error(who + ": " + what + " of " + value + " cm is beyond TeX's dimensions (limit " +
                                number(tex_paper_limit_cm) + " cm)");
    }

    //! An angle in degrees as TikZ may read it: pgfmath numbers stay below 16384, so beyond +-3600 degrees (ten
    //! turns) it is reduced modulo 360, keeping its sign; smaller (and non-finite) angles are returned unchanged.
    inline double tikzAngle(double deg) { return std::abs(deg) > 3600.0 ? std::fmod(deg, 360.0) : deg; }

    //! An arc from begin to end degrees (counter-clockwise if end > begin): unchanged unless one of the angles or the
    //! sweep is beyond +-3600; then the start is reduced by tikzAngle and the sweep modulo 360 in its direction (a
    //! whole number of turns draws one full turn).
    inline void tikzArc(double &begin, double &end)
    {
        const double sweep = end - begin;
        if (!(std::abs(begin) > 3600.0 || std::abs(end) > 3600.0 || std::abs(sweep) > 3600.0) || !std::isfinite(sweep))
            return;
        double s = std::abs(sweep) > 3600.0 ? std::fmod(sweep, 360.0) : sweep;
        if (s == 0.0 && sweep != 0.0)
            s = std::copysign(360.0, sweep);
        begin = tikzAngle(begin);
        end = begin + s;
    }

    //! "x,y" with appendNumber formatting.
    inline std::string tikzPoint(double x, double y)
    {
        std::string s;
        appendNumber(s, x);
        s += ',';
        appendNumber(s, y);
        return s;
    }

    //! TikZ node anchor for the position flags: the label sits on the named side of its point.
    inline std::string tikzAnchor(unsigned int position)
    {
        std::string v, h;
        if (position & tikz_position_above)
            v = "south";
        else if (position & tikz_position_below)
            v = "north";
        if (position & tikz_position_right)
            h = "west";
        else if (position & tikz_position_left)
            h = "east";
        if (v.empty() && h.empty())
            return "center";
        return v.empty() ? h : h.empty() ? v : v + " " + h;
    }

    //! The `minimal` document cropped to the picture by preview; write_tikz(os) writes the tikzpicture. A border below
    //! 1e-4 cm is written as 0 (a TeX length cannot have an exponent, and it is below 0.1 pt anyway). Into a
    //! std::ostream or a std::string (TextSink.h).
    template<class Out, class WriteTikz>
    void writeTikzDocument(Out &target, float border_cm, WriteTikz &&write_tikz)
    {
        detail::TextOut<Out> os{target};
        os << "\\documentclass{minimal}\n\\usepackage[rgb]{xcolor}\n\\usepackage{tikz}\n"
              "\\usepackage[active,tightpage]{preview}\n\\PreviewEnvironment{tikzpicture}\n"
              "\\setlength\\PreviewBorder{" << number(border_cm < 1e-4f ? 0.0f : border_cm) << "cm}\n\n\\begin{document}\n";
        write_tikz(target);
        os << "\\end{document}\n";
    }

    //! Calls write(stream) on a buffer, then writes it to file_name; throws std::runtime_error (prefixed
    //! "<who>::writeTEX") if the file cannot be written. The document is made first, so a writer that refuses
    //! (std::length_error) leaves no file behind and an earlier file of that name untouched.
    template<class Write>
    void writeTexFile(const std::string &file_name, const char *who, Write &&write)
    {
        std::ostringstream document;
        write(document);
        std::ofstream ofs(file_name);
        if (!ofs)
            throw std::runtime_error(std::string(who) + "::writeTEX: cannot open '" + file_name + "' for writing");
        ofs << document.str();
        if (!ofs)
            throw std::runtime_error(std::string(who) + "::writeTEX: writing '" + file_name + "' failed");
    }

    //! Generated names StyleX, ColorX and \MarkX, each registered once, with their definitions in registration order.
    class TikzNames
    {
    public:
        void clear()
        {
            styles.clear();
            style_order.clear();
            colors.clear();
            color_order.clear();
            marks.clear();
            mark_order.clear();
        }

        //! Name of the (normalised) style text.
        std::string style(const std::string &style_text)
        {
            std::string norm = normalizeStyle(style_text);
            auto it = styles.find(norm);
            if (it != styles.end())
                return it->second;
            std::string name = "Style" + indexToLetters(style_order.size());
            styles.emplace(norm, name);
            style_order.emplace_back(name, norm);
            return name;
        }

        //! Name of a colour spec such as "{rgb}{1,0,0}".
        std::string color(const std::string &spec)
        {
            auto it = colors.find(spec);
            if (it != colors.end())
                return it->second;
            std::string name = "Color" + indexToLetters(color_order.size());
            colors.emplace(spec, name);
            color_order.emplace_back(name, spec);
            return name;
        }

        //! Name of the mark command for (style, template, key_suffix), defined on first use as
        //! \newcommand{\MarkX}<args>{\begin{scope}[<scope_options>] <template with the style name> \end{scope}}.
        std::string mark(const std::string &style_text, const std::string &templ, const std::string &key_suffix,
                         const std::string &args, const std::string &scope_options)
        {
            std::string style_name = style(style_text);
            std::string key = style_name + '\n' + templ + key_suffix;
            auto it = marks.find(key);
            if (it != marks.end())
                return it->second;
            std::string name = "\\Mark" + indexToLetters(marks.size());
            marks.emplace(key, name);
            std::string body = templ;
            const std::string var = tikz_var_style;
            for (size_t p = body.find(var); p != std::string::npos; p = body.find(var, p + style_name.size()))
                body.replace(p, var.size(), style_name);
            mark_order.push_back("\\newcommand{" + name + "}" + args + "{\\begin{scope}[" + scope_options + "] " +
                                 body + " \\end{scope}}\n");
            return name;
        }

        //! "<Name>/.<text>" entries for the tikzpicture options, separated by ",\n\t".
        std::string styleOptions() const
        {
            std::string out;
            for (size_t i = 0; i < style_order.size(); ++i)
                out += (i ? ",\n\t" : "") + style_order[i].first + "/." + style_order[i].second;
            return out;
        }
        std::string colorDefinitions() const
        {
            std::string out;
            for (const auto &c : color_order)
                out += "\\definecolor{" + c.first + "}" + c.second + "\n";
            return out;
        }
        std::string markDefinitions() const
        {
            std::string out;
            for (const auto &m : mark_order)
                out += m;
            return out;
        }

        //! The normalised text of a registered style name ("" if unknown), e.g. for a back-end other than TikZ.
        std::string styleText(const std::string &name) const
        {
            for (const auto &s : style_order)
                if (s.first == name)
                    return s.second;
            return "";
        }
        //! Registered colours as (name, spec) in registration order.
        const std::vector<std::pair<std::string, std::string>> &colorList() const { return color_order; }

    private:
        std::map<std::string, std::string> styles;                   // normalised style text -> name
        std::vector<std::pair<std::string, std::string>> style_order;  // (name, text) in registration order
        std::map<std::string, std::string> colors;
        std::vector<std::pair<std::string, std::string>> color_order;
        std::map<std::string, std::string> marks;                    // (style, template, suffix) -> \MarkX
        std::vector<std::string> mark_order;                         // \newcommand definitions
    };
}
