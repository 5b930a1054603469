#pragma once

#include <optional>
#include <string>
#include <vector>

#include "evaluation/report/results_reader.hpp"

namespace radarpr {

// One figure as files: <name>.csv (its data) and <name>.gp (a gnuplot script that, run in the
// figure folder, reads the csv by relative path and writes <name>.svg and <name>.png).
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
};

FigureFiles pr_figure(const std::string& name, const std::string& title,
                      const std::vector<CurveSeries>& series);
FigureFiles roc_figure(const std::string& name, const std::string& title,
                       const std::vector<CurveSeries>& series);
// The seed paper's matching graph: trajectory in x-y, frame index as height (in a multi session
// the query session sits above the database session); TP edges green, FP red; missed revisits
// (FN) as blue rings when `include_missed`.
FigureFiles matching_graph_figure(const std::string& name, const std::string& title,
                                  const ResultRow& row, const DatasetTrajectory& trajectory,
                                  bool include_missed);
// The seed's Figure 1 (bottom): ROC AUC against payload bytes (log x), one point per descriptor
// configuration and session kind (mean over the datasets of that kind), labelled.
FigureFiles auc_size_figure(const std::string& name, const RunResults& run);

// A file-name-safe stem: characters outside [A-Za-z0-9_.=-] become '_'.
std::string figure_stem(const std::string& text);

}  // namespace radarpr
