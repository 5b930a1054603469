#pragma once

#include <optional>
#include <string>
#include <vector>

#include "evaluation/config/report_config.hpp"
#include "evaluation/results/auc_size.hpp"
#include "evaluation/results/results_reader.hpp"

namespace radarpr {

// One figure as files: <name>.csv (its data) and <name>.gp (a gnuplot script that, run in the
// figure folder, reads the csv by relative path and writes <name>.svg, <name>.png and
// <name>.pdf; figure_style.hpp). Every figure function draws in the given FigureStyle.
struct FigureFiles {
  std::string name;  // file stem, [A-Za-z0-9_.=-] only
  std::string caption;
  std::string csv;
  std::string script;
};

// One line of a PR or ROC figure: a descriptor's sweep, F1-max point marked.
struct CurveSeries {
  std::string title;
  const std::vector<SweepPoint>* curve = nullptr;
  std::optional<double> f1_max_threshold;
  std::optional<double> f1_max;
  std::optional<double> roc_auc;
  std::size_t colour = 0;  // index into figure_palette()
  int dash = 1;            // gnuplot dash type: 1 solid; a comparison gives each run its own
};

// Where a curve figure's key goes in the screen style: outside the plot, never over the data
// (the paper style puts it inside, in a corner the curves leave empty).
enum class KeyPlace { right, below };

// The series colours: 12 distinct ones, colour-blind-safe first (Okabe-Ito, then Tol), as
// '#rrggbb'. Black is kept for the F1-max marker, green and red for the matching graphs.
const std::vector<std::string>& figure_palette();

FigureFiles pr_figure(const std::string& name, const std::string& title,
                      const std::vector<CurveSeries>& series, KeyPlace key = KeyPlace::right,
                      FigureStyle style = FigureStyle::screen);
FigureFiles roc_figure(const std::string& name, const std::string& title,
                       const std::vector<CurveSeries>& series, KeyPlace key = KeyPlace::right,
                       FigureStyle style = FigureStyle::screen);
// How a matching graph is drawn, and what it needs from the run's protocol.
struct MatchingGraphContext {
  bool include_missed = false;  // the missed revisits (FN), each to its nearest loop frame
  FigureStyle style = FigureStyle::screen;
  bool top_view = false;  // x-y only (a 2-D plan), instead of frame index as height
  // The key's title, "F1-max threshold: d ≤ 0.0012"; none when F1-max is undefined.
  std::optional<std::string> threshold_text;
  double revisit_radius_m = 20.0;
  // A single session's recency exclusion in frames; unset when it is in seconds.
  std::optional<std::size_t> exclude_recent_frames = 50;
};

// The ReFeree paper's matching graph: trajectory in x-y at one scale, frame index as height (in a
// multi session the query session sits above the database session; none in the top view); TP
// edges thin, green and translucent, FP red over them; each missed revisit (FN) joined to the
// eligible frame within the revisit radius nearest to it when `include_missed`.
FigureFiles matching_graph_figure(const std::string& name, const std::string& title,
                                  const ResultRow& row, const DatasetTrajectory& trajectory,
                                  const MatchingGraphContext& context);
// The ReFeree paper's Figure 1 (bottom): ROC AUC against payload bytes (log x), one point per
// descriptor configuration and session kind (mean over the datasets of that kind, auc_size_points);
// each descriptor its colour, named in the key (no labels on the plot to overlap), the session kind
// its marker.
FigureFiles auc_size_figure(const std::string& name, const std::vector<AucSizePoint>& points,
                            FigureStyle style = FigureStyle::screen);

// A file-name-safe stem: characters outside [A-Za-z0-9_.=-] become '_'.
std::string figure_stem(const std::string& text);

}  // namespace radarpr
