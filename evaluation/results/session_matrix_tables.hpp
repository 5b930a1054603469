#pragma once

#include <optional>
#include <string>
#include <vector>

#include "evaluation/config/experiment_config.hpp"
#include "evaluation/experiment_runner.hpp"

namespace radarpr {

// One metric of every pair of a matrix, for one descriptor, reduced to the figures a study over
// many session pairs reports. Undefined values (a pair without revisit has no Recall@1) are left
// out of the statistics and counted.
struct MetricAggregate {
  std::string metric;     // the metrics.json key: "roc_auc", "recall_at_5", ...
  std::size_t pairs = 0;  // pairs with a defined value
  std::size_t undefined = 0;
  std::optional<double> mean, median, min, max;
};

struct DescriptorAggregate {
  std::string id;
  std::string label;
  std::size_t pairs = 0;
  std::size_t pairs_without_revisit = 0;
  std::vector<MetricAggregate> metrics;  // in metric_names() order
};

// Every metric a pair reports, by metrics.json key, in table order.
std::vector<std::string> matrix_metric_names(const Protocol& protocol);
// The value of `metric` (a matrix_metric_names() key) in `metrics`.
std::optional<double> matrix_metric_value(const Metrics& metrics, const std::string& metric);

// The pairs of `matrix` in `run` (the datasets it expanded into), in pair order.
std::vector<const DatasetRun*> matrix_pair_runs(const ExperimentConfig& config,
                                                const SessionMatrixConfig& matrix,
                                                const ExperimentRun& run);

std::vector<DescriptorAggregate> aggregate_matrix(const ExperimentConfig& config,
                                                  const SessionMatrixConfig& matrix,
                                                  const ExperimentRun& run);

// <matrix>/pairs.csv: one row per pair x descriptor with every metric.
std::string matrix_pairs_csv(const ExperimentConfig& config, const SessionMatrixConfig& matrix,
                             const ExperimentRun& run);
// <matrix>/aggregate.csv: one row per descriptor x metric (mean, median, min, max, counts).
std::string matrix_aggregate_csv(const ExperimentConfig& config, const SessionMatrixConfig& matrix,
                                 const ExperimentRun& run);
// The matrix's section of summary.md: per descriptor the aggregate of every metric, then the
// per-pair Recall@1 and ROC AUC.
std::string matrix_summary_markdown(const ExperimentConfig& config,
                                    const SessionMatrixConfig& matrix, const ExperimentRun& run);

}  // namespace radarpr
