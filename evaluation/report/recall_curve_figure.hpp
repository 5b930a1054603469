#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "evaluation/config/report_config.hpp"
#include "evaluation/report/figure_files.hpp"
#include "evaluation/results/results_reader.hpp"

namespace radarpr {

// Recall@N for N = 1 .. `last`: the share of revisit queries whose first correct frame is among
// their N nearest (matches.csv's first_correct_rank in [1, N]). `last` is the smaller of the
// asked `max_n` and the frames the row's rankings cover (ResultRow::ranked_frames, else
// `recorded_k`, the run's largest Recall@K: results written before the depth was recorded).
// Empty without revisit queries (Recall@N undefined).
struct RecallCurve {
  std::vector<double> recall;  // recall[N - 1]
  std::size_t ranked_frames = 0;
  bool stops_early = false;  // the rankings end before max_n
};
RecallCurve recall_at_n(const ResultRow& row, std::size_t max_n, std::size_t recorded_k);

struct RecallSeries {
  std::string title;
  RecallCurve curve;
  std::size_t colour = 0;  // index into figure_palette(), as the PR and ROC curves
  int dash = 1;
};

// The Recall@N curves of one dataset, every descriptor: N (1 .. max_n) across, Recall@N up; a
// curve whose rankings end early stops there.
FigureFiles recall_at_n_figure(const std::string& name, const std::string& title,
                               const std::vector<RecallSeries>& series, std::size_t max_n,
                               FigureStyle style);

}  // namespace radarpr
