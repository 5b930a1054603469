#include "evaluation/report/matrix_figures.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "evaluation/report/figure_style.hpp"
#include "evaluation/results/results_error.hpp"
#include "evaluation/results/results_writer.hpp"
#include "evaluation/text_escaping.hpp"

namespace radarpr {
namespace {

struct MatrixPairs {
  std::string name;
  std::vector<std::string> sessions;
  struct Pair {
    std::size_t query = 0;
    std::size_t database = 0;
    std::string dataset;
  };
  std::vector<Pair> pairs;
};

struct Metric {
  const char* key;    // summary.json row key
  const char* title;  // as figures name it
  const char* stem;
};
constexpr Metric kMetrics[] = {{"recall_at_1", "Recall@1", "recall_at_1"},
                               {"roc_auc", "ROC AUC", "roc_auc"}};

std::vector<MatrixPairs> read_matrices(const RunResults& run) {
  std::vector<MatrixPairs> matrices;
  const nlohmann::json& summary = run.summary;
  if (!summary.contains("matrices")) return matrices;
  const std::string where = (run.folder / "summary.json").string();
  try {
    for (const auto& entry : summary.at("matrices")) {
      MatrixPairs matrix;
      matrix.name = entry.at("name").get<std::string>();
      matrix.sessions = entry.at("sessions").get<std::vector<std::string>>();
      for (const auto& pair : entry.at("pairs")) {
        MatrixPairs::Pair p{pair.at("query").get<std::size_t>(),
                            pair.at("database").get<std::size_t>(),
                            pair.at("dataset").get<std::string>()};
        if (p.query >= matrix.sessions.size() || p.database >= matrix.sessions.size()) {
          throw ResultsError(fmt::format("{}: matrix {}: pair {} names no session", where,
                                         matrix.name, p.dataset));
        }
        matrix.pairs.push_back(std::move(p));
      }
      matrices.push_back(std::move(matrix));
    }
  } catch (const nlohmann::json::exception& error) {
    throw ResultsError(fmt::format("{}: \"matrices\" is malformed ({})", where, error.what()));
  }
  return matrices;
}

// The summary.json row of (dataset, descriptor).
const nlohmann::json& summary_row(const RunResults& run, const std::string& dataset,
                                  const std::string& descriptor) {
  for (const auto& row : run.summary.at("rows")) {
    if (row.value("dataset", "") == dataset && row.value("descriptor", "") == descriptor) {
      return row;
    }
  }
  throw ResultsError(fmt::format("{}: no row of {} on {}", (run.folder / "summary.json").string(),
                                 descriptor, dataset));
}

std::optional<double> metric_of(const nlohmann::json& row, const char* key) {
  if (!row.contains(key) || !row[key].is_number()) return std::nullopt;
  return row[key].get<double>();
}

std::string tics(const std::vector<std::string>& labels) {
  std::string text = "(";
  for (std::size_t i = 0; i < labels.size(); ++i) {
    text += fmt::format("{}{} {}", i ? ", " : "", gnuplot_string(labels[i]), i);
  }
  return text + ")";
}

// A descriptor label as a gnuplot string expression on several lines, one parameter a line
// ("open_radvlad:" "bin_dim=128," ...), so that the box plot's labels neither overlap nor run off
// the figure. Sets `lines` to the number of lines.
std::string wrapped_label(const std::string& label, std::size_t& lines) {
  std::string expression;
  std::string line;
  lines = 0;
  const auto flush = [&] {
    if (line.empty()) return;
    expression += (expression.empty() ? "" : ".\"\\n\".") + gnuplot_string(line);
    line.clear();
    ++lines;
  };
  for (const char c : label) {
    line += c;
    if (c == ':' || c == ',') flush();
  }
  flush();
  return expression.empty() ? gnuplot_string("") : expression;
}

FigureFiles heat_map(const RunResults& run, const MatrixPairs& matrix, const std::string& id,
                     const std::string& label, const Metric& metric, FigureStyle style) {
  const std::size_t n = matrix.sessions.size();
  std::vector<std::optional<double>> cells(n * n);
  for (const auto& pair : matrix.pairs) {
    cells[pair.query * n + pair.database] =
        metric_of(summary_row(run, pair.dataset, id), metric.key);
  }
  FigureFiles figure;
  figure.name = fmt::format("matrix_{}__{}__{}", figure_stem(matrix.name),
                            descriptor_folder_name(id), metric.stem);
  figure.caption = fmt::format(
      "{}, {}: {} per pair (query session down, database session "
      "across; blank: not evaluated or undefined)",
      matrix.name, label, metric.title);
  figure.csv = "database,query,value\n";
  for (std::size_t q = 0; q < n; ++q) {
    for (std::size_t d = 0; d < n; ++d) {
      const auto& value = cells[q * n + d];
      figure.csv += fmt::format("{},{},{}\n", d, q, value ? fmt::format("{}", *value) : "NaN");
    }
  }
  const std::string body = fmt::format(
      "set datafile missing 'NaN'\n"
      "set xlabel 'database session'\n"
      "set ylabel 'query session'\n"
      "set xrange [-0.5:{}]\n"
      "set yrange [{}:-0.5]\n"
      "set xtics {} rotate by 30 right\n"
      "set ytics {}\n"
      "set cbrange [0:1]\n"
      "set cblabel {}\n"
      "set palette defined (0 '#440154', 0.25 '#3b528b', 0.5 '#21918c', 0.75 '#5ec962', "
      "1 '#fde725')\n"
      "set size ratio -1\n"
      "set tics out\n"
      // One filled box per cell: a missing cell stays blank without shifting the others (an
      // image plot infers its grid from the points present). Values in black on the light half
      // of the palette, in white on the dark half.
      "plot '{name}.csv' using 1:2:(0.5):(0.5):3 skip 1 with boxxyerror fill solid 1.0 "
      "noborder lc palette notitle, \\\n"
      "     '' using 1:2:($3 >= 0.6 ? sprintf('%.2f', $3) : '') skip 1 with labels "
      "textcolor rgb 'black' notitle, \\\n"
      "     '' using 1:2:($3 < 0.6 ? sprintf('%.2f', $3) : '') skip 1 with labels "
      "textcolor rgb 'white' notitle",
      static_cast<double>(n) - 0.5, static_cast<double>(n) - 0.5, tics(matrix.sessions),
      tics(matrix.sessions), gnuplot_string(metric.title), fmt::arg("name", figure.name));
  const int size = 240 + 70 * static_cast<int>(n);
  figure.script = figure_script(figure.name, figure.caption,
                                fmt::format("{}: {}, {}", matrix.name, label, metric.title), "",
                                body, style, FigureCanvas{size + 120, size, 3.0});
  return figure;
}

FigureFiles box_plot(const RunResults& run, const MatrixPairs& matrix, const Metric& metric,
                     FigureStyle style) {
  FigureFiles figure;
  figure.name = fmt::format("matrix_{}__box__{}", figure_stem(matrix.name), metric.stem);
  figure.caption = fmt::format(
      "{}: {} over the {} pairs, one box per descriptor (median, quartiles, whiskers to 1.5 IQR; "
      "undefined values left out)",
      matrix.name, metric.title, matrix.pairs.size());
  figure.csv = "descriptor,value\n";
  std::vector<std::string> labels;
  for (std::size_t d = 0; d < run.descriptors.size(); ++d) {
    const std::string& id = run.descriptors[d];
    std::string label = id;
    for (const auto& pair : matrix.pairs) {
      const nlohmann::json& row = summary_row(run, pair.dataset, id);
      label = row.value("label", id);
      if (const auto value = metric_of(row, metric.key)) {
        figure.csv += fmt::format("{},{}\n", d, *value);
      }
    }
    labels.push_back(label);
  }
  std::string xtics = "(";
  std::size_t label_lines = 1;
  for (std::size_t d = 0; d < labels.size(); ++d) {
    std::size_t lines = 0;
    xtics += fmt::format("{}{} {}", d ? ", " : "", wrapped_label(labels[d], lines), d);
    label_lines = std::max(label_lines, lines);
  }
  xtics += ")";
  // One box per descriptor, each from its own rows: the x position and the tick label are the
  // descriptor's index, whatever descriptors have no defined value.
  const std::string body = fmt::format(
      "set ylabel {}\n"
      "set yrange [0:1]\n"
      "set xrange [-0.6:{}]\n"
      "set xtics {}\n"
      "set bmargin {}\n"
      "set style fill solid 0.35 border -1\n"
      "set style boxplot outliers pointtype 7\n"
      "set boxwidth 0.5\n"
      "set grid ytics\n"
      "plot for [i=0:{}] '{}.csv' using (i):($1 == i ? $2 : NaN):(0.5) skip 1 with boxplot "
      "lc rgb '#0072b2' notitle",
      gnuplot_string(metric.title), static_cast<double>(labels.size()) - 0.4, xtics,
      label_lines + 2, std::max<std::size_t>(labels.size(), 1) - 1, figure.name);
  figure.script =
      figure_script(figure.name, figure.caption,
                    fmt::format("{}: {} per pair", matrix.name, metric.title), "", body, style,
                    FigureCanvas{360 + 130 * static_cast<int>(labels.size()),
                                 500 + 16 * static_cast<int>(label_lines),
                                 2.2 + 0.12 * static_cast<double>(label_lines)});
  return figure;
}

}  // namespace

std::vector<FigureFiles> matrix_figures(const RunResults& run, FigureStyle style) {
  std::vector<FigureFiles> figures;
  for (const auto& matrix : read_matrices(run)) {
    for (const auto& metric : kMetrics) figures.push_back(box_plot(run, matrix, metric, style));
    for (const auto& id : run.descriptors) {
      const std::string label =
          matrix.pairs.empty()
              ? id
              : summary_row(run, matrix.pairs.front().dataset, id).value("label", id);
      for (const auto& metric : kMetrics) {
        figures.push_back(heat_map(run, matrix, id, label, metric, style));
      }
    }
  }
  return figures;
}

std::string matrix_section_html(const RunResults& run, const std::vector<PageFigure>& figures) {
  std::string html;
  for (const auto& matrix : read_matrices(run)) {
    const std::string prefix = "matrix_" + figure_stem(matrix.name) + "__";
    html += fmt::format(
        "<h3>{}</h3>\n<p>{} sessions, {} ordered pairs. The aggregate over the pairs (mean, "
        "median, min, max of every metric) is in <code>summary.md</code> and "
        "<code>{}/aggregate.csv</code>, every pair in <code>{}/pairs.csv</code>.</p>\n",
        html_escape(matrix.name), matrix.sessions.size(), matrix.pairs.size(),
        html_escape(matrix.name), html_escape(matrix.name));
    for (const auto& figure : figures) {
      if (figure.name.starts_with(prefix)) html += figure_html(figure);
    }
  }
  return html;
}

}  // namespace radarpr
