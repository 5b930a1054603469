#include "evaluation/report/auc_per_kb_figure.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "evaluation/report/figure_style.hpp"
#include "evaluation/text_escaping.hpp"

namespace radarpr {
namespace {

// Three significant digits: 4.52, 0.0151.
std::string three_digits(double value) {
  const int decimals = std::max(0, 2 - static_cast<int>(std::floor(std::log10(value))));
  return fmt::format("{:.{}f}", value, decimals);
}

}  // namespace

FigureFiles auc_per_kb_figure(const std::string& name, const std::vector<AucSizePoint>& points,
                              FigureStyle style) {
  const bool paper = style == FigureStyle::paper;
  FigureFiles figure{
      name, "ROC AUC per KB of payload: per session kind, the mean over its datasets", "", ""};
  figure.csv = "bar,auc_per_kb,mean_roc_auc,payload_bytes,session,descriptor\n";
  bool kinds[2] = {false, false};
  for (const AucSizePoint& p : points) {
    if (p.mean_auc) kinds[p.multi_session ? 1 : 0] = true;
  }
  const bool both_kinds = kinds[0] && kinds[1];
  std::string plots, labels;
  double low = 0.0, high = 0.0;
  int bar = 0;
  std::size_t longest = 0;  // the longest bar name, for the margin under the plot
  for (const AucSizePoint& p : points) {
    if (!p.mean_auc || p.payload_bytes <= 0.0) continue;
    const double density = *p.mean_auc / (p.payload_bytes / 1024.0);
    if (density <= 0.0) continue;  // an AUC of 0 has no place on a log axis
    const std::string tick =
        both_kinds ? fmt::format("{} ({})", p.label, p.multi_session ? "multi" : "single")
                   : p.label;
    figure.csv += fmt::format("{}{},{},{},{},{},{}\n", bar ? "\n\n" : "", bar, density, *p.mean_auc,
                              p.payload_bytes, p.multi_session ? "multi" : "single",
                              csv_field(tick, CsvQuoting::always));
    const auto& palette = figure_palette();
    plots += fmt::format(
        "{}'{}.csv' skip 1 index {} using 1:2:xticlabels(6) with boxes lc rgb '{}' notitle",
        plots.empty() ? "plot " : ", \\\n     ", name, bar,
        palette[p.descriptor_index % palette.size()]);
    // The paper column's bars are narrower than their values: written upwards from the bar's top.
    labels += fmt::format(
        "set label {} '{}' at {}, {} {} front\n", 10 + bar, three_digits(density), bar, density,
        paper ? "left rotate by 90 offset 0,0.3 font ',6'" : "center offset 0,0.6 font ',10'");
    longest = std::max(longest, tick.size());
    low = bar == 0 ? density : std::min(low, density);
    high = std::max(high, density);
    ++bar;
  }
  std::string range;
  if (plots.empty()) {
    plots = "set label 1 'no defined ROC AUC' at graph 0.5, graph 0.5 center\nplot NaN notitle";
    range = "set xrange [0:1]\nset yrange [0.1:10]\n";
  } else {
    // Whole decades around the bars, with room above the tallest for its value.
    range = fmt::format("set xrange [-0.6:{}]\nset yrange [{}:{}]\n", bar - 0.4,
                        std::pow(10.0, std::floor(std::log10(low)) - (low == high ? 1 : 0)),
                        std::pow(10.0, std::ceil(std::log10(high * (paper ? 20.0 : 1.6)))));
  }
  // Long names under narrow bars: slanted on the screen, upright in the paper column (6 pt), with
  // the margin under the plot sized for the longest (a 6 pt character is about a third of a
  // margin line).
  const FigureCanvas canvas{std::max(900, 90 * bar + 200), 640, 3.2};
  const std::string settings = fmt::format(
      "set logscale y\n{}set style fill solid 0.85 border lc rgb 'black'\nset boxwidth 0.7\n"
      "set xtics {} nomirror scale 0\nset ylabel '{}'\nset grid ytics\nunset key\n"
      "set bmargin {}\n{}",
      range, paper ? "rotate by 90 right font ',6'" : "rotate by 35 right",
      paper ? "ROC AUC per KB" : "mean ROC AUC per KB of payload (1 KB = 1,024 bytes; log scale)",
      paper ? static_cast<int>(std::ceil(0.36 * static_cast<double>(longest))) + 1 : 10, labels);
  figure.script = figure_script(name, "ROC AUC per kilobyte of payload", figure.caption, settings,
                                plots, style, canvas);
  return figure;
}

}  // namespace radarpr
