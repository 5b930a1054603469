#pragma once

#include <string>
#include <vector>

#include "evaluation/text_escaping.hpp"

namespace radarpr {

// A table as the report writes it in four formats; the values are already formatted text, so
// every format shows exactly the same numbers.
struct TableCell {
  std::string text;
  bool bold = false;  // best of its column
  bool code = false;  // a descriptor id: `x` in Markdown, \texttt in LaTeX
};

// Columns under one heading (a dataset over its metrics): in LaTeX a two-level header.
struct ColumnGroup {
  std::string title;  // empty: no heading over these columns
  std::size_t columns = 1;
  std::vector<std::string> subheaders;  // the columns' own names under the heading
};

struct Table {
  std::vector<std::string> header;
  std::vector<bool> numeric;  // per column: right-aligned
  std::vector<std::vector<TableCell>> rows;
  // Empty, or covering every column in order: then LaTeX (\multicolumn, \cmidrule) and HTML
  // (colspan) write the group titles over their columns and the subheaders below. Markdown and
  // CSV keep `header`.
  std::vector<ColumnGroup> groups;
};

// **x** for bold; every cell through markdown_cell / markdown_code_cell (text_escaping.hpp).
std::string to_markdown(const Table& table);
// Plain values through csv_field (quoted when needed, formulas kept as text).
std::string to_csv(const Table& table);
// A tabular with \textbf{x} for bold and LaTeX specials escaped; booktabs rules; a two-level
// header when the table has column groups.
std::string to_latex(const Table& table);
// A <table> with <strong> for bold; text HTML-escaped; a two-level header when the table has
// column groups.
std::string to_html(const Table& table);

}  // namespace radarpr
