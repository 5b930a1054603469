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
// The ReFeree paper's matching graph: trajectory in x-y, frame index as height (in a multi session
// the query session sits above the database session); TP edges green, FP red; missed revisits
// (FN) as blue rings when `include_missed`.
FigureFiles matching_graph_figure(const std::string& name, const std::string& title,
                                  const ResultRow& row, const DatasetTrajectory& trajectory,
                                  bool include_missed, FigureStyle style = FigureStyle::screen);
// The ReFeree paper's Figure 1 (bottom): ROC AUC against payload bytes (log x), one point per
// descriptor configuration and session kind (mean over the datasets of that kind, auc_size_points);
// each descriptor its colour, named in the key (no labels on the plot to overlap), the session kind
// its marker.
FigureFiles auc_size_figure(const std::string& name, const std::vector<AucSizePoint>& points,
                            FigureStyle style = FigureStyle::screen);

// A file-name-safe stem: characters outside [A-Za-z0-9_.=-] become '_'.
std::string figure_stem(const std::string& text);

}  // namespace radarpr
