#include "evaluation/results/table.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "evaluation/results/csv_file.hpp"

namespace radarpr {
namespace {

// Markdown table cells end at '|' (escaped in code spans too: GitHub splits the row first). A
// backtick in plain text is escaped; a code span holding backticks takes a longer fence.
std::string markdown_cell(const TableCell& cell) {
  std::string text;
  std::size_t run = 0, longest = 0;  // the longest backtick run, for the fence
  for (char c : cell.text) {
    run = c == '`' ? run + 1 : 0;
    longest = std::max(longest, run);
    if (c == '|') {
      text += "\\|";
    } else if (c == '`' && !cell.code) {
      text += "\\`";
    } else {
      text += c;
    }
  }
  if (cell.code) {
    const std::string fence(longest + 1, '`');
    const bool pad = longest > 0;  // "`` `a ``": a space keeps the fence off the content
    text = fence + (pad ? " " : "") + text + (pad ? " " : "") + fence;
  }
  return cell.bold ? fmt::format("**{}**", text) : text;
}

std::string latex_escape(const std::string& text) {
  std::string escaped;
  for (char c : text) {
    switch (c) {
      case '&':
      case '%':
      case '$':
      case '#':
      case '_':
      case '{':
      case '}':
        escaped += '\\';
        escaped += c;
        break;
      case '~':
        escaped += "\\textasciitilde{}";
        break;
      case '^':
        escaped += "\\textasciicircum{}";
        break;
      case '\\':
        escaped += "\\textbackslash{}";
        break;
      case '<':
        escaped += "\\textless{}";
        break;
      case '>':
        escaped += "\\textgreater{}";
        break;
      case '"':
        escaped += "\\textquotedbl{}";
        break;
      default:
        escaped += c;
    }
  }
  return escaped;
}

}  // namespace

std::string html_escape(const std::string& text) {
  std::string escaped;
  for (char c : text) {
    switch (c) {
      case '&':
        escaped += "&amp;";
        break;
      case '<':
        escaped += "&lt;";
        break;
      case '>':
        escaped += "&gt;";
        break;
      case '"':
        escaped += "&quot;";
        break;
      case '\'':
        escaped += "&#39;";
        break;
      default:
        escaped += c;
    }
  }
  return escaped;
}

std::string to_markdown(const Table& table) {
  std::string md = "|";
  std::string rule = "|";
  for (std::size_t c = 0; c < table.header.size(); ++c) {
    md += fmt::format(" {} |", markdown_cell({table.header[c]}));
    rule += table.numeric[c] ? "---:|" : "---|";
  }
  md += fmt::format("\n{}\n", rule);
  for (const auto& row : table.rows) {
    md += "|";
    for (const auto& cell : row) md += fmt::format(" {} |", markdown_cell(cell));
    md += "\n";
  }
  return md;
}

std::string to_csv(const Table& table) {
  std::string csv = csv_line(table.header);
  for (const auto& row : table.rows) {
    std::vector<std::string> fields;
    for (const auto& cell : row) fields.push_back(cell.text);
    csv += csv_line(fields);
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
  for (std::size_t c = 0; c < table.header.size(); ++c) {
    if (c) tex += " & ";
    tex += latex_escape(table.header[c]);
  }
  tex += " \\\\\n\\midrule\n";
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
  for (std::size_t c = 0; c < table.header.size(); ++c) {
    html += fmt::format("<th{}>{}</th>", table.numeric[c] ? " class=\"num\"" : "",
                        html_escape(table.header[c]));
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
