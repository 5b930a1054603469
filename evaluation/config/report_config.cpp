#include "evaluation/config/report_config.hpp"

#include <fmt/format.h>

namespace radarpr {

std::optional<FigureStyle> parse_figure_style(std::string_view text) {
  if (text == "screen") return FigureStyle::screen;
  if (text == "paper") return FigureStyle::paper;
  return std::nullopt;
}

const char* to_string(FigureStyle style) {
  return style == FigureStyle::paper ? "paper" : "screen";
}

ReportConfig parse_report_config(ConfigReader reader) {
  ReportConfig config;
  const std::string style = reader.string_or("style", "screen");
  const auto parsed = parse_figure_style(style);
  if (!parsed) reader.fail("style", "must be \"screen\" or \"paper\"");
  config.style = *parsed;
  const auto n = reader.integer_or("recall_curve_n", config.recall_curve_n);
  if (n < 1 || n > kMaxRecallCurveN) {
    reader.fail("recall_curve_n", fmt::format("must be in [1, {}]", kMaxRecallCurveN));
  }
  config.recall_curve_n = static_cast<int>(n);
  config.auc_per_kb = reader.boolean_or("auc_per_kb", config.auc_per_kb);
  reader.finish();
  return config;
}

}  // namespace radarpr
