// A LaTeX report of figures and tables, compiled with pdflatex when it is installed
// (docs/reference.md, "LaTeXDoc").
//
// Every external step (create directories, compile, move the PDF, remove the temporary directory) is a replaceable
// callable, and a failing step never throws or stops the program: a report is a by-product, not a result.
#pragma once

#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "rtl/io/LaTeXTable.h"
#include "rtl/io/LaTeXTikz2D.h"
#include "rtl/io/LaTeXTikz3D.h"
#include "rtl/io/LaTeXUtility.h"

namespace rtl
{
    //! Gathers figures (anything with writeTEX(file), e.g. LaTeXTikz2D/3D) and tables into `<out_dir>/<out_name>.pdf`.
    //!
    //! Work happens in the temporary directory `<out_dir>_tmp_<out_name>`: every figure is written there as
    //! `<out_name>_<k>.tex` and compiled on its own (the main document includes the PDFs), and the destructor (or
    //! finish()) writes the `article` document, compiles it, moves the PDF to out_dir and removes the temporary
    //! directory. With setInlineFigures(true) the figures are `\input` into the main document instead (standalone
    //! package), so the whole report costs a single pdflatex run.
    //!
    //! External steps never throw or abort: if pdflatex is not on PATH the document says so once on std::cerr and
    //! produces no PDF; a failed step is reported on std::cerr and in problems(). Every step can be replaced
    //! (setMakeTmpDir, setCompileTex, ...); a replacement returns true on success. The final compile, move and
    //! removal always all run (RTL: the temporary directory is removed even when no PDF was made), unless
    //! setStopOnFailure(true), which keeps the LaTeX sources of a failed document for a later run. Captions are LaTeX, written as given (RTL), unless setEscapeCaptions(true).
    class LaTeXDoc
    {
    public:
        LaTeXDoc(std::string out_dir, std::string out_name)
                : output_dir(stripSlashes(std::move(out_dir))), name(std::move(out_name))
        {
            tmp_dir = output_dir + "_tmp_" + name;
            make_tmp_dir = defaultMakeDir;
            make_output_dir = defaultMakeDir;
            remove_tmp_dir = [](const std::string &dir) { return defaultRemove(dir); };
            move_final_doc = defaultMove;
            compile_tex = [this](const std::string &tex, const std::string &dir) { return defaultCompile(tex, dir); };
            if (!make_tmp_dir(tmp_dir))
                problem("cannot create the temporary directory '" + tmp_dir + "'");
            if (!make_output_dir(output_dir))
                problem("cannot create the output directory '" + output_dir + "'");
        }
        LaTeXDoc(const LaTeXDoc &) = delete;
        LaTeXDoc &operator=(const LaTeXDoc &) = delete;

        ~LaTeXDoc()
        {
            try
            {
                finish();
            }
            catch (...)
            {
                // A destructor must not throw; finish() already reported what went wrong.
            }
        }

        template<typename T> void setMakeTmpDir(T func) { make_tmp_dir = func; }
        template<typename T> void setMakeOutputDir(T func) { make_output_dir = func; }
        template<typename T> void setRemoveTmpDir(T func) { remove_tmp_dir = func; }
        template<typename T> void setMoveFinalDoc(T func) { move_final_doc = func; }
        template<typename T> void setCompileTex(T func) { compile_tex = func; }

        //! true: figures are `\input` into the main document and compiled with it (one pdflatex run in total).
        void setInlineFigures(bool inline_figures) { inline_mode = inline_figures; }

        //! Writes `le` as the next figure (full text width) with an optional caption.
        template<class LE>
        void addLE(LE &le, const std::string &desc = "")
        {
            std::string file = figure(le);
            body += "\\begin{figure}[t]\n\\centering\n" + include(file, "\\textwidth") + "\n";
            if (!desc.empty())
                body += "\\caption{" + caption(desc) + "}\n";
            body += "\\end{figure}\n\n";
        }

        //! A figure with a grid of `figs` exporters in `cols` columns; func(figs, i) returns the i-th exporter (it is
        //! written before the next call, so func may reuse one object).
        template<class T>
        void addGridLE(T &func, size_t cols, size_t figs, const std::string &desc = "")
        {
            if (cols == 0 || figs == 0)
                return;
            std::string width = detail::number(1.0 / static_cast<double>(cols)) + "\\textwidth";
            body += "\\begin{figure}[t]\n\\centering\n{\\setlength{\\tabcolsep}{0pt}\n\\begin{tabular}{" +
                    std::string(cols, 'c') + "}\n";
            for (size_t i = 0; i < figs; ++i)
            {
                auto &le = func(static_cast<int>(figs), static_cast<int>(i));
                std::string file = figure(le);
                body += include(file, width);
                if (i + 1 == figs)
                    body += "\n";
                else
                    body += (i + 1) % cols == 0 ? " \\\\\n" : " &\n";
            }
            body += "\\end{tabular}}\n";
            if (!desc.empty())
                body += "\\caption{" + caption(desc) + "}\n";
            body += "\\end{figure}\n\n";
        }

        void addTable(const LaTeXTable &tab, const std::string &desc)
        {
            std::ostringstream os;
            tab.writeTable(os, caption(desc));
            body += os.str();
        }

        //! Writes and compiles the document, moves the PDF to the output directory and removes the temporary
        //! directory. As in RTL these steps are best-effort and always all run, in that order, even after a failed
        //! compile; with setStopOnFailure(true) a failed write or compile skips the move and the removal (so the
        //! LaTeX sources stay in the temporary directory). Returns true if
        //! `<out_dir>/<out_name>.pdf` was produced. Called by the destructor; later calls do nothing and return the
        //! first result.
        bool finish()
        {
            if (finished)
                return result;
            finished = true;
            std::string tex = tmp_dir + "/" + name + ".tex";
            bool written = false;
            {
                std::ofstream ofs(tex);
                // Inline figures bring their colours (e.g. hsb) into this document: convert them to rgb as the
                // figures' own preamble would.
                ofs << "\\documentclass{article}\n\\usepackage{graphicx}\n\\usepackage["
                    << (inline_mode ? "rgb,table" : "table") << "]{xcolor}\n";
                if (inline_mode)
                    ofs << "\\usepackage{tikz}\n\\usepackage{standalone}\n";
                ofs << "\\graphicspath{{./}}\n\n\\begin{document}\n\n" << body << "\\end{document}\n";
                written = static_cast<bool>(ofs);
            }
            if (!written)
                problem("cannot write '" + tex + "'");
            bool compiled = compile_tex(tex, tmp_dir);
            std::string pdf = tmp_dir + "/" + name + ".pdf";
            std::error_code ec;
            pdf_made = compiled && std::filesystem::exists(pdf, ec);
            if (!pdf_made)
            {
                if (written && !missing_reported)   // (a missing pdflatex was already reported)
                    problem("compiling '" + tex + "' failed; see " + tmp_dir + "/" + name + ".log");
                problem("no PDF produced from the LaTeX sources in '" + tmp_dir + "'");
                if (stop_on_failure)
                    return result = false;
            }
            bool moved = move_final_doc(pdf, output_dir);
            if (!moved && pdf_made)
                problem("cannot move '" + pdf + "' to '" + output_dir + "'");
            if (!remove_tmp_dir(tmp_dir))
                problem("cannot remove the temporary directory '" + tmp_dir + "'");
            return result = pdf_made && moved;
        }

        //! true: a failed write or compile in finish() skips moving the PDF and removing the temporary directory
        //! (default false: every step runs, as in RTL).
        void setStopOnFailure(bool stop) { stop_on_failure = stop; }

        //! true: captions (addLE, addGridLE, addTable) are plain text and escaped with LaTeX::escapeLaTeXCharacters;
        //! default false: they are LaTeX and written as given, as in RTL.
        void setEscapeCaptions(bool escape) { escape_captions = escape; }

        //! Path of the final PDF (exists after a successful finish()).
        std::string pdfPath() const { return output_dir + "/" + name + ".pdf"; }
        std::string tmpDir() const { return tmp_dir; }
        //! Messages about steps that failed (also printed on std::cerr).
        const std::vector<std::string> &problems() const { return problem_list; }

        //! Whether `pdflatex` can be run (looked up on PATH once per process).
        static bool pdflatexAvailable()
        {
            static const bool available = std::system("command -v pdflatex > /dev/null 2>&1") == 0;
            return available;
        }

    private:
        LaTeXDoc() = default;

        std::string caption(const std::string &desc) const
        {
            return escape_captions ? LaTeX::escapeLaTeXCharacters(desc) : desc;
        }

        static std::string stripSlashes(std::string s)
        {
            while (s.size() > 1 && s.back() == '/')
                s.pop_back();
            return s.empty() ? "." : s;
        }

        void problem(const std::string &msg)
        {
            problem_list.push_back(msg);
            std::cerr << "rtl::LaTeXDoc: " << msg << "\n";
        }

        template<class LE>
        std::string figure(LE &le)
        {
            std::string base = name + "_" + std::to_string(figure_counter++);
            std::string tex = tmp_dir + "/" + base + ".tex";
            std::error_code ec;
            std::filesystem::remove(tex, ec);   // (a stale file of an earlier run must not pass for this figure)
            try
            {
                le.writeTEX(tex);
            }
            catch (const std::exception &e)
            {
                problem(std::string("writing a figure failed: ") + e.what());
                return "";
            }
            if (!std::filesystem::exists(tex, ec))
                return empty_figure;   // nothing to draw (e.g. an empty LaTeXTikz3D writes no file)
            if (inline_mode)
                return base + ".tex";
            if (!compile_tex(tex, tmp_dir))
            {
                if (!missing_reported)
                    problem("compiling figure '" + tex + "' failed; see " + tmp_dir + "/" + base + ".log");
                if (pdflatexAvailable() && !std::filesystem::exists(tmp_dir + "/" + base + ".pdf", ec))
                    return "";
            }
            return base + ".pdf";
        }

        std::string include(const std::string &file, const std::string &width) const
        {
            if (file.empty())
                return "\\fbox{(figure missing)}";
            if (file == empty_figure)
                return "\\fbox{(empty figure)}";
            if (inline_mode)
                return "\\resizebox{" + width + "}{!}{\\input{" + file + "}}";
            return "\\includegraphics[width=" + width + "]{" + file + "}";
        }

        static bool defaultMakeDir(const std::string &dir)
        {
            std::error_code ec;
            std::filesystem::create_directories(dir, ec);
            return std::filesystem::is_directory(dir, ec);
        }

        //! Removes the directory and everything in it (RTL's `rm -r`).
        static bool defaultRemove(const std::string &dir)
        {
            std::error_code ec;
            std::filesystem::remove_all(dir, ec);
            return !ec;
        }

        static bool defaultMove(const std::string &file, const std::string &dir)
        {
            namespace fs = std::filesystem;
            std::error_code ec;
            fs::path target = fs::path(dir) / fs::path(file).filename();
            fs::rename(file, target, ec);
            if (!ec)
                return true;
            // rename cannot cross file systems: copy and delete instead.
            ec.clear();
            fs::copy_file(file, target, fs::copy_options::overwrite_existing, ec);
            if (ec)
                return false;
            fs::remove(file, ec);
            return true;
        }

        //! pdflatex in the temporary directory, non-interactive; success means a clean exit and a PDF.
        bool defaultCompile(const std::string &tex_file, const std::string &dir)
        {
            if (!pdflatexAvailable())
            {
                if (!missing_reported)
                    problem("pdflatex was not found on PATH, so no PDF is produced (install TeX Live, e.g. "
                            "texlive-latex-base texlive-pictures texlive-latex-extra); the LaTeX sources are kept in '" +
                            tmp_dir + "'");
                missing_reported = true;
                return false;
            }
            namespace fs = std::filesystem;
            std::error_code ec;
            fs::path tex = fs::absolute(tex_file, ec);
            std::string cmd = "cd " + detail::shellQuote(dir) +
                              " && pdflatex -interaction=nonstopmode -halt-on-error " +
                              detail::shellQuote(tex.string()) + " > /dev/null 2>&1";
            int rc = std::system(cmd.c_str());
            fs::path pdf = fs::path(dir) / tex.filename().replace_extension(".pdf");
            return rc == 0 && fs::exists(pdf, ec);
        }

        static constexpr const char *empty_figure = "<empty figure>";
        std::string output_dir, name, tmp_dir;
        std::string body;
        size_t figure_counter = 0;
        bool inline_mode = false, finished = false, result = false, missing_reported = false, pdf_made = false;
        bool stop_on_failure = false, escape_captions = false;
        std::vector<std::string> problem_list;
        std::function<bool(const std::string &)> make_tmp_dir, make_output_dir, remove_tmp_dir;
        std::function<bool(const std::string &, const std::string &)> move_final_doc, compile_tex;
    };
}
