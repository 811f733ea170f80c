// Draws the speed report's figures and tables from the TSVs of speed_native and speed_wasm.mjs, with
// the library's own Drawing2D written by its TikZ and SVG back-ends: time per point against the number of points,
// log-log, one colour and mark per algorithm, native solid, wasm dashed, the floors in grey, a legend in the
// corner the curves leave free. Two figures: the paper's "Speed benchmark of vectorization algorithms" (FTLS,
// ITLS, DP, RW) and the segmenters (CAR, IA). The tables give every time as a ratio to the floor of the same run.
//
// Usage: speed_figure --out=DIR NATIVE.tsv [WASM.tsv]
// Writes DIR/speed_vectorizers.{tex,svg}, DIR/speed_segmenters.{tex,svg} and DIR/tables.md.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "rtl/io/Drawing2D.h"
#include "rtl/io/Svg2D.h"
#include "rtl/io/Tikz2DWriter.h"

namespace
{
    struct Row
    {
        double ns = NAN, wall_ns = NAN, library_ns = NAN;   // whole call in CPU and wall time, library part (CPU)
        long long output = -1;
    };
    //! impl -> case -> points -> row
    using Data = std::map<std::string, std::map<std::string, std::map<size_t, Row>>>;

    double number(const std::string &s)
    {
        char *end = nullptr;
        const double v = std::strtod(s.c_str(), &end);
        return end != s.c_str() && *end == '\0' ? v : NAN;
    }

    void readTsv(const std::string &file, Data &data)
    {
        std::ifstream f(file);
        if (!f) { std::fprintf(stderr, "speed_figure: cannot read %s\n", file.c_str()); std::exit(1); }
        std::string line;
        while (std::getline(f, line))
        {
            std::vector<std::string> c;
            std::stringstream ss(line);
            for (std::string cell; std::getline(ss, cell, '\t');) c.push_back(cell);
            if (c.size() != 9 || c[0] == "impl") continue;   // headers (one per appended run)
            Row r;
            r.ns = number(c[5]);
            r.wall_ns = number(c[6]);
            r.library_ns = number(c[7]);
            r.output = std::atoll(c[8].c_str());
            data[c[0]][c[1]][static_cast<size_t>(std::atoll(c[2].c_str()))] = r;
        }
    }

    struct Style
    {
        std::string name, color;
        const char *mark;
    };

    //! One figure: `cases` of every implementation in `data` plus the floors, the legend top right.
    rtl::Drawing2D figure(const Data &data, const std::vector<Style> &cases, const std::string &floor_label)
    {
        const float width = 13, height = 8.5, xlo = 0.8f, xhi = 6.2f;   // x in decades: 10^0.8 .. 10^6.2 points
        std::vector<Style> all = cases;
        all.push_back({"floor", "gray", rtl::Drawing2D::latex_mark_blank});
        // The y range: every drawn value, then room above the curves' right part for the legend.
        double ymin = INFINITY, ymax = -INFINITY, yright = -INFINITY;
        const float legend_w = 7.6f, row_h = 0.45f;
        const size_t rows = std::max<size_t>(all.size(), 3);
        const float legend_h = static_cast<float>(rows) * row_h + 0.3f;
        const double legend_x0 = xhi - legend_w / width * (xhi - xlo);
        for (const auto &impl : data)
            for (const auto &s : all)
            {
                auto it = impl.second.find(s.name);
                if (it == impl.second.end()) continue;
                for (const auto &p : it->second)
                {
                    if (!(p.second.ns > 0)) continue;
                    const double y = std::log10(p.second.ns);
                    ymin = std::min(ymin, y);
                    ymax = std::max(ymax, y);
                    if (std::log10(static_cast<double>(p.first)) >= legend_x0 - 0.3) yright = std::max(yright, y);
                }
            }
        if (!std::isfinite(ymin)) { ymin = 0; ymax = 1; yright = 1; }
        const double ylo = ymin - 0.15;   // a tight frame: the decade ticks inside it are labelled
        // The legend's bottom 0.2 decades over the highest curve under it: ytop - legend height in decades.
        const double k = legend_h / height;
        const double ytop = std::max(ymax + 0.1, (yright + 0.2 - k * ylo) / (1 - k));
        rtl::Drawing2D d(rtl::Drawing2D::axis_type_log10, rtl::Drawing2D::axis_type_log10);
        d.setSize(width, height);
        d.setMarkRadius(0.06f);
        d.setGridAxisOverrun(rtl::Drawing2D::overrun_absolute, 0);
        auto p10 = [](double e) { return static_cast<float>(std::pow(10.0, e)); };
        d.setMinPlotRegion(p10(xlo), p10(ylo), p10(xhi), p10(ytop));
        d.addGridH("draw=gray!30, very thin", 1);
        d.addGridV("draw=gray!30, very thin", 1);
        d.addAxisX("draw=black", "%.0e", rtl::Drawing2D::position_below, 1, p10(ylo));
        d.addAxisY("draw=black", "%g", rtl::Drawing2D::position_left, 1, p10(xlo));
        d.addDescriptionX("number of points n");
        d.addDescriptionY("CPU time per point [ns]");
        for (const auto &s : all)
            for (const auto &impl : data)
            {
                auto it = impl.second.find(s.name);
                if (it == impl.second.end()) continue;
                std::vector<float> x, y;
                for (const auto &p : it->second)
                {
                    x.push_back(static_cast<float>(p.first));
                    y.push_back(static_cast<float>(p.second.ns));
                }
                const std::string dash = impl.first == "native" ? "" : ", dashed";
                const std::string width_key = s.name == "floor" ? "" : ", thick";
                d.addPlot(x, y, "draw=" + s.color + width_key + dash, "draw=" + s.color + ", fill=" + s.color, s.mark);
            }
        // Legend: algorithms (colour, mark) on the left, implementations (line pattern) on the right.
        const double ly1 = ytop - 0.06 * (ytop - ylo), lx0 = legend_x0 + 0.04 * (xhi - xlo);
        const double dy = row_h / height * (ytop - ylo), dx = 1.0 / width * (xhi - xlo);   // one row, one cm
        d.addRectangle(rtl::Vector2f(p10(lx0 - 0.1 * dx), p10(ly1 + 0.3 * dy)),
                       rtl::Vector2f(p10(xhi - 0.1 * dx), p10(ly1 - (static_cast<double>(rows) + 0.1) * dy)),
                       "draw=gray, fill=white");
        auto entry = [&](double x, size_t row, const std::string &line, const std::string &mark_style, const char *mark,
                         const std::string &text) {
            const float y = p10(ly1 - (static_cast<double>(row) + 0.5) * dy);
            d.addPlot(std::vector<float>{p10(x), p10(x + 0.4 * dx), p10(x + 0.8 * dx)}, std::vector<float>{y, y, y}, line,
                      mark_style, mark);
            d.addText(text, "anchor=west", rtl::Vector2f(p10(x + dx), y));
        };
        for (size_t i = 0; i < all.size(); ++i)
        {
            const auto &s = all[i];
            const bool fl = s.name == "floor";
            entry(lx0, i, "draw=" + s.color + (fl ? "" : ", thick"), fl ? "" : "draw=" + s.color + ", fill=" + s.color,
                  s.mark, fl ? floor_label : s.name);
        }
        const double rx = lx0 + 3.9 * dx;
        entry(rx, 0, "draw=black, thick", "", rtl::Drawing2D::latex_mark_blank, "native (C++)");
        entry(rx, 1, "draw=black, thick, dashed", "", rtl::Drawing2D::latex_mark_blank, "wasm (Node)");
        return d;
    }

    void write(const rtl::Drawing2D &d, const std::string &stem)
    {
        std::ofstream tex(stem + ".tex"), svg(stem + ".svg");
        rtl::writeTikz(d, tex);
        rtl::writeSvg(d, svg);
        if (!tex || !svg) { std::fprintf(stderr, "speed_figure: cannot write %s.tex/.svg\n", stem.c_str()); std::exit(1); }
    }

    std::string fmt(const char *f, double v)
    {
        if (!std::isfinite(v)) return "-";
        char b[64];
        std::snprintf(b, sizeof b, f, v);
        return b;
    }

    //! "ns (ratio x)": a time per point and its ratio to the floor of the same implementation and size.
    std::string cell(double ns, double floor_ns)
    {
        if (!std::isfinite(ns)) return "-";
        return fmt(ns < 10 ? "%.2f" : ns < 100 ? "%.1f" : "%.0f", ns) + " (" + fmt("%.1f", ns / floor_ns) + "×)";
    }

    void tables(const Data &data, const std::vector<std::string> &cases, std::ostream &os)
    {
        std::set<size_t> sizes;
        for (const auto &impl : data)
            for (const auto &c : impl.second)
                for (const auto &p : c.second) sizes.insert(p.first);
        auto get = [&](const std::string &impl, const std::string &c, size_t n) -> const Row * {
            auto i = data.find(impl);
            if (i == data.end()) return nullptr;
            auto j = i->second.find(c);
            if (j == i->second.end()) return nullptr;
            auto k = j->second.find(n);
            return k == j->second.end() ? nullptr : &k->second;
        };
        auto header = [&](const std::vector<std::string> &lead) {
            os << "|";
            for (const auto &c : lead) os << " " << c << " |";
            for (const auto &c : cases) os << " " << c << " |";
            os << "\n|";
            for (size_t i = 0; i < lead.size() + cases.size(); ++i) os << "---:|";
            os << "\n";
        };
        for (const std::string impl : {"native", "wasm"})
        {
            if (data.find(impl) == data.end()) continue;
            os << "\n**" << (impl == "native" ? "Native (C++)" : "rtl-wasm in Node, whole call")
               << "**: CPU ns per point (× the floor at the same n";
            os << (impl == "native" ? ", measured in the same rounds)\n\n" : ": the same pass in JavaScript, same rounds)\n\n");
            header({"n", "floor ns/point"});
            for (size_t n : sizes)
            {
                const Row *f = get(impl, "floor", n);
                if (!f) continue;
                os << "| " << n << " | " << fmt("%.2f", f->ns) << " |";
                for (const auto &c : cases)
                {
                    const Row *r = get(impl, c, n);
                    os << " " << (r ? cell(r->ns, f->ns) : "-") << " |";
                }
                os << "\n";
            }
        }
        if (data.count("native") && data.count("wasm"))
        {
            os << "\n**wasm against native** in CPU time (two processes, the same size measured seconds apart): the "
                  "library's part of the wasm call / the native call, then the whole wasm call / the native call. The "
                  "library's part is estimated as the call's CPU time times the share of its wall time that "
                  "rtl.lastComputeMs reports.\n\n";
            header({"n"});
            bool same = true;
            std::string differ;
            for (size_t n : sizes)
            {
                if (!get("native", "floor", n) || !get("wasm", "floor", n)) continue;
                os << "| " << n << " |";
                for (const auto &c : cases)
                {
                    const Row *a = get("native", c, n), *w = get("wasm", c, n);
                    if (!a || !w) { os << " - |"; continue; }
                    os << " " << fmt("%.2f", w->library_ns / a->ns) << " / " << fmt("%.1f", w->ns / a->ns) << " |";
                    if (a->output != w->output)
                    {
                        same = false;
                        differ += " " + c + " at " + std::to_string(n) + " (" + std::to_string(a->output) + " vs " +
                                  std::to_string(w->output) + ");";
                    }
                }
                os << "\n";
            }
            os << "\nOutputs (segments, kept points, clusters) native against wasm: "
               << (same ? "identical at every size and case.\n" : "differ:" + differ + "\n");
        }
        os << "\nOutput sizes (native): FTLS and ITLS segments, DP and RW kept points, CAR and IA clusters\n\n";
        header({"n"});
        for (size_t n : sizes)
        {
            os << "| " << n << " |";
            for (const auto &c : cases)
            {
                const Row *r = get("native", c, n);
                os << " " << (r ? std::to_string(r->output) : "-") << " |";
            }
            os << "\n";
        }
    }
}

int main(int argc, char **argv)
{
    std::string out;
    Data data;
    for (int i = 1; i < argc; ++i)
    {
        if (std::strncmp(argv[i], "--out=", 6) == 0) out = argv[i] + 6;
        else readTsv(argv[i], data);
    }
    if (out.empty() || data.empty())
    {
        std::fprintf(stderr, "usage: speed_figure --out=DIR NATIVE.tsv [WASM.tsv]\n");
        return 2;
    }
    const char *dot = rtl::Drawing2D::latex_mark_dot, *cross = rtl::Drawing2D::latex_mark_cross,
               *robot = rtl::Drawing2D::latex_mark_robot, *bar = rtl::Drawing2D::latex_mark_mark;
    write(figure(data, {{"FTLS", "blue", dot}, {"ITLS", "red", cross}, {"DP", "green!60!black", robot}, {"RW", "orange", bar}},
                 "floor (chord distances)"),
          out + "/speed_vectorizers");
    write(figure(data, {{"CAR", "violet", dot}, {"IA", "teal", cross}}, "floor (chord distances)"), out + "/speed_segmenters");
    std::ofstream md(out + "/tables.md");
    tables(data, {"FTLS", "ITLS", "DP", "RW", "CAR", "IA"}, md);
    if (!md) { std::fprintf(stderr, "speed_figure: cannot write %s/tables.md\n", out.c_str()); return 1; }
    return 0;
}
