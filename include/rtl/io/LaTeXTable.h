// A LaTeX tabular inside a table float, written into a LaTeXDoc (docs/reference.md, "LaTeXTable").
#pragma once

#include <algorithm>
#include <fstream>
#include <ostream>
#include <string>
#include <vector>

#include "rtl/io/LaTeXUtility.h"
#include "rtl/io/TextSink.h"

namespace rtl
{
    //! Collects a heading, rows and horizontal rules. As in RTL, cells and the caption are LaTeX and are written as
    //! given (so "Item\_name" or "$10^{3}$" arrive unchanged). For plain user text, setHeadingEscaped / addRowEscaped
    //! escape every cell with LaTeX::escapeLaTeXCharacters, and a caption can be passed through the same function.
    class LaTeXTable
    {
    public:
        LaTeXTable() = default;
        ~LaTeXTable() = default;

        //! Tabular column specification, e.g. "c|c||c". If never set, every column is centred ("c" per cell).
        void setColumnStyle(const std::string &cs) { column_style = cs; }
        std::string columnsStyle() { return column_style; }

        //! Sets the heading row, cells as given; an empty vector is ignored.
        void setHeading(const std::vector<std::string> &heading_cells)
        {
            if (!heading_cells.empty())
                heading = heading_cells;
        }
        //! Sets the heading row from plain text (each cell escaped); an empty vector is ignored.
        void setHeadingEscaped(const std::vector<std::string> &heading_cells) { setHeading(escapeCells(heading_cells)); }

        //! Appends a row, cells as given; an empty vector is ignored.
        void addRow(const std::vector<std::string> &row_cells)
        {
            if (!row_cells.empty())
                rows.push_back({false, row_cells});
        }
        //! Appends a row of plain text (each cell escaped); an empty vector is ignored.
        void addRowEscaped(const std::vector<std::string> &row_cells) { addRow(escapeCells(row_cells)); }

        void addHLine() { rows.push_back({true, {}}); }

        //! The text writeTable writes, as a string (e.g. for a binding that returns strings); no stream involved.
        [[nodiscard]] std::string tableString(const std::string &desc) const
        {
            std::string out;
            writeTo(out, desc);
            return out;
        }

        //! Writes table/center/tabular, the heading and rows (cells joined by " & ", each line starting with a tab and
        //! ending with "\\"), and `\caption{desc}` (desc as given) only if `desc` is non-empty, then a blank line.
        void writeTable(std::ostream &ofs, const std::string &desc) const { writeTo(ofs, desc); }

    private:
        //! writeTable into a std::ostream or a std::string (TextSink.h).
        template<class Out>
        void writeTo(Out &ofs, const std::string &desc) const
        {
            using detail::textAppend;
            textAppend(ofs, "\\begin{table}\n\\begin{center}\n\\begin{tabular}{");
            textAppend(ofs, effectiveColumnStyle());
            textAppend(ofs, "}\n");
            bool first = true;
            auto line = [&](const std::string &text) {
                if (!first)
                    textAppend(ofs, "\n");
                first = false;
                textAppend(ofs, "\t");
                textAppend(ofs, text);
            };
            if (!heading.empty())
                line(joinCells(heading));
            for (const auto &r : rows)
                line(r.hline ? std::string("\\hline") : joinCells(r.cells));
            textAppend(ofs, "\n\\end{tabular}\n\\end{center}\n");
            if (!desc.empty())
            {
                textAppend(ofs, "\\caption{");
                textAppend(ofs, desc);
                textAppend(ofs, "}\n");
            }
            textAppend(ofs, "\\end{table}\n\n");
        }

        struct Row
        {
            bool hline;
            std::vector<std::string> cells;
        };

        static std::vector<std::string> escapeCells(const std::vector<std::string> &cells)
        {
            std::vector<std::string> out;
            out.reserve(cells.size());
            for (const auto &c : cells)
                out.push_back(LaTeX::escapeLaTeXCharacters(c));
            return out;
        }

        static std::string joinCells(const std::vector<std::string> &cells)
        {
            std::string s;
            for (size_t i = 0; i < cells.size(); ++i)
            {
                if (i > 0)
                    s += " & ";
                s += cells[i];
            }
            return s + "\\\\";
        }

        std::string effectiveColumnStyle() const
        {
            if (!column_style.empty())
                return column_style;
            size_t cols = heading.size();
            for (const auto &r : rows)
                cols = std::max(cols, r.cells.size());
            return std::string(std::max<size_t>(cols, 1), 'c');
        }

        std::string column_style;
        std::vector<std::string> heading;
        std::vector<Row> rows;
    };
}
