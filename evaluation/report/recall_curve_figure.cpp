#include "evaluation/report/recall_curve_figure.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "evaluation/report/figure_style.hpp"
#include "evaluation/text_escaping.hpp"

namespace radarpr {

RecallCurve recall_at_n(const ResultRow& row, std::size_t max_n, std::size_t recorded_k) {
  RecallCurve curve;
  curve.ranked_frames = row.ranked_frames.value_or(recorded_k);
  const std::size_t last = std::min(max_n, curve.ranked_frames);
  curve.stops_early = last < max_n;
  std::size_t revisits = 0;
  std::vector<std::size_t> found_at(last + 1, 0);  // revisit queries first correct at rank N
  for (const auto& [revisit, rank] : row.ranks) {
    if (!revisit) continue;
    ++revisits;
    if (rank >= 1 && rank <= last) ++found_at[rank];
  }
  if (revisits == 0) return curve;
  std::size_t found = 0;
  for (std::size_t n = 1; n <= last; ++n) {
    found += found_at[n];
    curve.recall.push_back(static_cast<double>(found) / static_cast<double>(revisits));
  }
  return curve;
}

FigureFiles recall_at_n_figure(const std::string& name, const std::string& title,
                               const std::vector<RecallSeries>& series, std::size_t max_n,
                               FigureStyle style) {
  const bool paper = style == FigureStyle::paper;
  const auto& palette = figure_palette();
  FigureFiles figure{name, title, "n,recall_at_n,series\n", ""};
  std::string plots;
  std::vector<std::string> key_titles;
  int block = 0;
  for (std::size_t s = 0; s < series.size(); ++s) {
    const RecallSeries& line = series[s];
    if (line.curve.recall.empty()) continue;
    std::string rows;
    for (std::size_t n = 1; n <= line.curve.recall.size(); ++n) {
      rows += fmt::format("{},{},{}\n", n, line.curve.recall[n - 1],
                          csv_field(line.title, CsvQuoting::always));
    }
    figure.csv += (block ? "\n\n" : "") + rows;
    const std::string key =
        line.curve.stops_early
            ? fmt::format("{} (ranks end at N = {})", line.title, line.curve.recall.size())
            : line.title;
    // The same colour and dash type as the descriptor's PR and ROC curves; a marker at every N
    // (a handful of points, and a curve that stops early ends on a visible point).
    static constexpr int kMarkers[] = {4, 6, 8, 12, 10, 14, 1, 2, 3};
    plots += fmt::format(
        "{}'{}.csv' skip 1 index {} using 1:2 with linespoints lw {} dt {} pt {} ps {} lc rgb "
        "'{}' title {}",
        plots.empty() ? "plot " : ", \\\n     ", name, block, paper ? "2.5" : "3", line.dash,
        kMarkers[line.colour % std::size(kMarkers)], paper ? "0.5" : "1.0",
        palette[line.colour % palette.size()], gnuplot_string(key));
    key_titles.push_back(key);
    ++block;
  }
  if (plots.empty()) {
    plots =
        "set label 1 'no revisit query: Recall@N undefined' at graph 0.5, graph 0.5 center\n"
        "plot NaN notitle";
  }
  FigureCanvas canvas{1200, 640, 2.6};
  const std::string key = styled_key(style, "right bottom", key_titles, canvas);
  const std::string settings = fmt::format(
      "set xlabel 'N (nearest frames retrieved)'\nset ylabel 'Recall@N'\n"
      "set xrange [0.5:{}]\nset yrange [0:1.02]\n{}"
      "set key {}\nset grid\n",
      static_cast<double>(max_n) + 0.5,
      // Every N up to 10, else every 5th (and 1): labels that never crowd.
      max_n <= 10 ? "set xtics 1\n"
                  : fmt::format("set xtics 0,{}\nset xtics add ('1' 1)\n", max_n <= 50 ? 5 : 10),
      key);
  figure.script = figure_script(name, "Recall@N curves", title, settings, plots, style, canvas);
  return figure;
}

}  // namespace radarpr
