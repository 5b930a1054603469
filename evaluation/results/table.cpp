#include "evaluation/results/table.hpp"

#include <fmt/format.h>

namespace radarpr {
namespace {

std::string markdown_text(const TableCell& cell) {
  const std::string text = cell.code ? markdown_code_cell(cell.text) : markdown_cell(cell.text);
  return cell.bold ? fmt::format("**{}**", text) : text;
}

}  // namespace

std::string to_markdown(const Table& table) {
  std::string md = "|";
  std::string rule = "|";
  for (std::size_t c = 0; c < table.header.size(); ++c) {
    md += fmt::format(" {} |", markdown_text({table.header[c]}));
    rule += table.numeric[c] ? "---:|" : "---|";
  }
  md += fmt::format("\n{}\n", rule);
  for (const auto& row : table.rows) {
    md += "|";
    for (const auto& cell : row) md += fmt::format(" {} |", markdown_text(cell));
    md += "\n";
  }
  return md;
}

std::string to_csv(const Table& table) {
  std::string csv;
  for (std::size_t c = 0; c < table.header.size(); ++c) {
    if (c) csv += ',';
    csv += csv_field(table.header[c]);
  }
  csv += "\n";
  for (const auto& row : table.rows) {
    for (std::size_t c = 0; c < row.size(); ++c) {
      if (c) csv += ',';
      csv += csv_field(row[c].text);
    }
    csv += "\n";
  }
  return csv;
}

std::string to_latex(const Table& table) {
  std::string columns;
  for (bool numeric : table.numeric) columns += numeric ? 'r' : 'l';
  std::string tex = fmt::format(
      "% needs \\usepackage{{booktabs}} (and \\usepackage[T1]{{fontenc}} for "
      "\\textquotedbl)\n\\begin{{tabular}}{{{}}}\n\\toprule\n",
      columns);
  std::size_t grouped = 0;
  for (const auto& group : table.groups) grouped += group.columns;
  if (!table.groups.empty() && grouped == table.header.size()) {
    // Two levels: each group's title centred over its columns and ruled under, then the
    // columns' own names.
    std::string rules, names;
    std::size_t first = 1;
    for (std::size_t g = 0; g < table.groups.size(); ++g) {
      const ColumnGroup& group = table.groups[g];
      const std::string sep = g ? " & " : "";
      if (group.title.empty()) {
        // No heading: one empty cell per column.
        for (std::size_t c = 0; c < group.columns; ++c) tex += (g || c) ? " & " : "";
      } else {
        tex += sep + fmt::format("\\multicolumn{{{}}}{{c}}{{{}}}", group.columns,
                                 latex_escape(group.title));
      }
      if (!group.title.empty()) {
        rules += fmt::format("\\cmidrule(lr){{{}-{}}}", first, first + group.columns - 1);
      }
      for (std::size_t c = 0; c < group.columns; ++c) {
        const std::string name =
            c < group.subheaders.size() ? group.subheaders[c] : table.header[first - 1 + c];
        names += (names.empty() && g == 0 && c == 0 ? "" : " & ") + latex_escape(name);
      }
      first += group.columns;
    }
    tex += " \\\\\n" + (rules.empty() ? "" : rules + "\n") + names + " \\\\\n\\midrule\n";
  } else {
    for (std::size_t c = 0; c < table.header.size(); ++c) {
      if (c) tex += " & ";
      tex += latex_escape(table.header[c]);
    }
    tex += " \\\\\n\\midrule\n";
  }
  for (const auto& row : table.rows) {
    for (std::size_t c = 0; c < row.size(); ++c) {
      std::string text = latex_escape(row[c].text);
      if (row[c].code) text = fmt::format("\\texttt{{{}}}", text);
      if (row[c].bold) text = fmt::format("\\textbf{{{}}}", text);
      if (c) tex += " & ";
      tex += text;
    }
    tex += " \\\\\n";
  }
  return tex + "\\bottomrule\n\\end{tabular}\n";
}

std::string to_html(const Table& table) {
  std::string html = "<table>\n<thead><tr>";
  const auto num = [&table](std::size_t c) {
    return table.numeric[c] ? std::string(" class=\"num\"") : std::string();
  };
  std::size_t grouped = 0;
  for (const auto& group : table.groups) grouped += group.columns;
  if (!table.groups.empty() && grouped == table.header.size()) {
    // Two levels, as in LaTeX: each group's title over its columns, their short names below
    // ("AUC" under the dataset, not "campus AUC" in every column), so that a table of many
    // datasets stays narrow; a column without a group title spans both rows.
    std::string names;
    std::size_t first = 0;
    for (const auto& group : table.groups) {
      if (group.title.empty()) {
        for (std::size_t c = first; c < first + group.columns; ++c) {
          html += fmt::format("<th rowspan=\"2\"{}>{}</th>", num(c), html_escape(table.header[c]));
        }
      } else {
        html += fmt::format("<th colspan=\"{}\">{}</th>", group.columns, html_escape(group.title));
        for (std::size_t c = 0; c < group.columns; ++c) {
          const std::string& name =
              c < group.subheaders.size() ? group.subheaders[c] : table.header[first + c];
          names += fmt::format("<th{}>{}</th>", num(first + c), html_escape(name));
        }
      }
      first += group.columns;
    }
    html += "</tr>\n<tr>" + names;
  } else {
    for (std::size_t c = 0; c < table.header.size(); ++c) {
      html += fmt::format("<th{}>{}</th>", num(c), html_escape(table.header[c]));
    }
  }
  html += "</tr></thead>\n<tbody>\n";
  for (const auto& row : table.rows) {
    html += "<tr>";
    for (std::size_t c = 0; c < row.size(); ++c) {
      std::string text = html_escape(row[c].text);
      if (row[c].code) text = fmt::format("<code>{}</code>", text);
      if (row[c].bold) text = fmt::format("<strong>{}</strong>", text);
      html += fmt::format("<td{}>{}</td>", table.numeric[c] ? " class=\"num\"" : "", text);
    }
    html += "</tr>\n";
  }
  return html + "</tbody>\n</table>\n";
}

}  // namespace radarpr
