#pragma once

#include <optional>
#include <string>
#include <vector>

#include "evaluation/config/experiment_config.hpp"
#include "evaluation/experiment_runner.hpp"

namespace radarpr {

// One descriptor x published dataset of a paper's Table I beside this run (paper-table.md).
struct PublishedComparisonRow {
  std::string descriptor;                 // the label both tables use
  std::string published_dataset;          // the paper's column
  std::vector<std::string> run_datasets;  // the run's datasets standing for it (values averaged)
  std::optional<double> paper_auc, run_auc, paper_f1_max, run_f1_max;
  // run - paper; empty when either is unknown.
  std::optional<double> auc_difference() const;
  std::optional<double> f1_max_difference() const;
};

// The rows for every descriptor of the run whose label is a row of the published Table I, in
// config order, and every published dataset some run dataset stands for, in the paper's order.
// A run value is the mean of the defined values of the datasets standing for that column.
std::vector<PublishedComparisonRow> published_comparison(const ExperimentConfig& config,
                                                         const ExperimentRun& run);

// summary.md's section: Table I beside the paper's with the differences, then Table II beside
// the paper's sizes. Empty when the config names no published tables.
std::string published_comparison_markdown(const ExperimentConfig& config, const ExperimentRun& run);
// published_comparison.csv: the rows above, full precision, empty cells where unknown.
std::string published_comparison_csv(const ExperimentConfig& config, const ExperimentRun& run);

}  // namespace radarpr
