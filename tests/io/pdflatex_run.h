// The io tests' pdflatex step: write pictures into one preview document, compile <dir>/<base>.tex, keep the log for
// the failure message, and read the PDF's text back (pdftotext) to find what the pictures print.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "rtl/io/LaTeXUtility.h"

namespace pdflatex_test
{
    namespace fs = std::filesystem;

    inline std::string readFile(const fs::path &file)
    {
        std::ifstream in(file);
        return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    }

    //! The preview document's preamble, the one the TikZ writers' standalone documents start with.
    inline const char *const preamble = "\\documentclass{minimal}\n\\usepackage[rgb]{xcolor}\n\\usepackage{tikz}\n"
                                        "\\usepackage[active,tightpage]{preview}\n\\PreviewEnvironment{tikzpicture}\n";

    //! <dir>/<base>.tex: a minimal document with one preview page per picture; `extra` goes at the end of the preamble.
    inline void writePreviewDocument(const fs::path &dir, const std::string &base, const std::vector<std::string> &pictures,
                                     const std::string &extra = "")
    {
        std::ofstream doc(dir / (base + ".tex"));
        doc << preamble << extra << "\\begin{document}\n";
        for (const auto &p : pictures)
            doc << p;
        doc << "\\end{document}\n";
    }

    struct Run
    {
        int rc;
        std::string log;   //!< <base>.log
        //! The first error of the log (or its end when there is none), for the assertion message.
        std::string failure() const
        {
            size_t err = log.find("\n!");
            return err == std::string::npos ? log.substr(log.size() > 2000 ? log.size() - 2000 : 0) : log.substr(err, 600);
        }
    };

    inline std::string inDir(const fs::path &dir, const std::string &command)
    {
        return "cd " + rtl::detail::shellQuote(dir.string()) + " && " + command;
    }

    //! pdflatex, non-interactive, on <dir>/<base>.tex (its output in <dir>/pdflatex.out); with halt_on_error false
    //! it goes on after an error, so that the log lists every failing picture.
    inline Run compile(const fs::path &dir, const std::string &base, bool halt_on_error = true)
    {
        const std::string halt = halt_on_error ? "-halt-on-error " : "";
        int rc = std::system(inDir(dir, "pdflatex -interaction=nonstopmode " + halt + base + ".tex > pdflatex.out 2>&1").c_str());
        return {rc, readFile(dir / (base + ".log"))};
    }

    //! pdftotext's exit code; the text is left in <dir>/<base>.txt.
    inline int extractText(const fs::path &dir, const std::string &base)
    {
        return std::system(inDir(dir, "pdftotext " + base + ".pdf " + base + ".txt").c_str());
    }
}
