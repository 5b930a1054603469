#pragma once

#include <optional>
#include <string_view>

#include "evaluation/config/config_reader.hpp"

namespace radarpr {

// How the report draws its figures. `screen` (the default) suits the HTML page: large, titled,
// keys beside the plot. `paper` suits a two-column IEEE paper: one column (3.5 in) wide, 8 pt
// text, the key inside the plot, no title in the image (the caption carries it), lines thick
// enough to survive printing. Both write SVG, PNG and PDF.
enum class FigureStyle { screen, paper };

std::optional<FigureStyle> parse_figure_style(std::string_view text);
const char* to_string(FigureStyle style);

// A config's "report" object: how `run` (and a later `report` of its folder) draws the figures.
struct ReportConfig {
  FigureStyle style = FigureStyle::screen;
  // The Recall@N curves run from N = 1 to this.
  int recall_curve_n = 25;
  // Also draw auc_per_kb: each point of auc_vs_size as its AUC per kilobyte of payload.
  bool auc_per_kb = false;
};

constexpr int kMaxRecallCurveN = 1000;

// Parses a "report" object (ConfigError naming the key path for a bad value or unknown key).
ReportConfig parse_report_config(ConfigReader reader);

}  // namespace radarpr
