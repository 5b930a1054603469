#include "evaluation/results/session_matrix_tables.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "evaluation/results/csv_file.hpp"
#include "evaluation/results/summary_table.hpp"
#include "evaluation/text_escaping.hpp"

namespace radarpr {
namespace {

std::string csv_number(const std::optional<double>& value) {
  return value ? fmt::format("{}", *value) : "";
}

std::string session_of(const SessionMatrixConfig& matrix, std::size_t pair, bool query) {
  const auto& [q, d] = matrix.pairs[pair];
  return matrix.sessions[query ? q : d].name;
}

MetricAggregate reduce(const std::string& metric, std::vector<double> values,
                       std::size_t undefined) {
  MetricAggregate aggregate;
  aggregate.metric = metric;
  aggregate.pairs = values.size();
  aggregate.undefined = undefined;
  if (values.empty()) return aggregate;
  std::sort(values.begin(), values.end());
  double sum = 0.0;
  for (double value : values) sum += value;  // ascending order: the same sum on every run
  aggregate.mean = sum / static_cast<double>(values.size());
  const std::size_t middle = values.size() / 2;
  aggregate.median =
      values.size() % 2 == 1 ? values[middle] : (values[middle - 1] + values[middle]) / 2.0;
  aggregate.min = values.front();
  aggregate.max = values.back();
  return aggregate;
}

}  // namespace

std::vector<std::string> matrix_metric_names(const Protocol& protocol) {
  // Recall@K under the protocol's denominator, named by it when it is not the revisit queries.
  const std::string suffix =
      protocol.recall_denominator == RecallDenominator::revisit_queries
          ? ""
          : (protocol.recall_denominator == RecallDenominator::all_queries ? "_all_queries"
                                                                           : "_with_positive");
  std::vector<std::string> names = {"roc_auc", "f1_max", "pr_auc_trapezoid", "average_precision",
                                    "recall_at_1" + suffix};
  for (int k : protocol.recall_at_k) {
    if (k != 1) names.push_back(fmt::format("recall_at_{}{}", k, suffix));
  }
  names.push_back("recall_at_100_precision");
  names.push_back("extended_precision");
  return names;
}

std::optional<double> matrix_metric_value(const Metrics& metrics, const std::string& metric) {
  if (metric == "roc_auc") return metrics.roc_auc;
  if (metric == "f1_max") return metrics.f1_max;
  if (metric == "pr_auc_trapezoid") return metrics.pr_auc;
  if (metric == "average_precision") return metrics.average_precision;
  if (metric == "recall_at_100_precision") return metrics.recall_at_100_precision;
  if (metric == "extended_precision") return metrics.extended_precision;
  if (metric.starts_with("recall_at_")) {
    std::size_t digits = 0;
    const int k = std::stoi(metric.substr(10), &digits);
    const std::string suffix = metric.substr(10 + digits);
    const RecallDenominator denominator = suffix == "_all_queries" ? RecallDenominator::all_queries
                                          : suffix == "_with_positive"
                                              ? RecallDenominator::queries_with_positive
                                              : RecallDenominator::revisit_queries;
    if (!suffix.empty() && denominator == RecallDenominator::revisit_queries) {
      throw std::logic_error("unknown matrix metric " + metric);
    }
    return recall_at(metrics, k, denominator);
  }
  throw std::logic_error("unknown matrix metric " + metric);
}

std::vector<const DatasetRun*> matrix_pair_runs(const ExperimentConfig& config,
                                                const SessionMatrixConfig& matrix,
                                                const ExperimentRun& run) {
  std::vector<const DatasetRun*> pairs;
  for (std::size_t p = 0; p < matrix.pairs.size(); ++p) {
    const std::string& name = config.datasets.at(matrix.first_dataset + p).name;
    const auto it = std::find_if(run.datasets.begin(), run.datasets.end(),
                                 [&](const DatasetRun& dataset) { return dataset.name == name; });
    if (it == run.datasets.end()) {
      throw std::logic_error(fmt::format("the run has no results of pair {}", name));
    }
    pairs.push_back(&*it);
  }
  return pairs;
}

std::vector<DescriptorAggregate> aggregate_matrix(const ExperimentConfig& config,
                                                  const SessionMatrixConfig& matrix,
                                                  const ExperimentRun& run) {
  const auto pairs = matrix_pair_runs(config, matrix, run);
  std::vector<DescriptorAggregate> aggregates;
  for (std::size_t d = 0; d < config.descriptors.size(); ++d) {
    DescriptorAggregate aggregate;
    aggregate.id = config.descriptors[d].id;
    aggregate.label = config.descriptors[d].display_name();
    aggregate.pairs = pairs.size();
    for (const DatasetRun* pair : pairs) {
      if (pair->descriptors.at(d).evaluation.metrics.revisits == 0) {
        ++aggregate.pairs_without_revisit;
      }
    }
    for (const std::string& metric : matrix_metric_names(config.protocol)) {
      std::vector<double> values;
      std::size_t undefined = 0;
      for (const DatasetRun* pair : pairs) {
        const auto value = matrix_metric_value(pair->descriptors.at(d).evaluation.metrics, metric);
        if (value) {
          values.push_back(*value);
        } else {
          ++undefined;
        }
      }
      aggregate.metrics.push_back(reduce(metric, std::move(values), undefined));
    }
    aggregates.push_back(std::move(aggregate));
  }
  return aggregates;
}

std::string matrix_pairs_csv(const ExperimentConfig& config, const SessionMatrixConfig& matrix,
                             const ExperimentRun& run) {
  const auto names = matrix_metric_names(config.protocol);
  std::vector<std::string> header{"query_session", "database_session", "dataset", "descriptor",
                                  "label",         "queries",          "revisits"};
  header.insert(header.end(), names.begin(), names.end());
  std::string csv = csv_line(header);
  const auto pairs = matrix_pair_runs(config, matrix, run);
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    for (const DescriptorRun& descriptor : pairs[p]->descriptors) {
      const Metrics& m = descriptor.evaluation.metrics;
      std::vector<std::string> row{session_of(matrix, p, true),
                                   session_of(matrix, p, false),
                                   pairs[p]->name,
                                   descriptor.id,
                                   descriptor.label,
                                   std::to_string(m.queries),
                                   std::to_string(m.revisits)};
      for (const auto& name : names) row.push_back(csv_number(matrix_metric_value(m, name)));
      csv += csv_line(row);
    }
  }
  return csv;
}

std::string matrix_aggregate_csv(const ExperimentConfig& config, const SessionMatrixConfig& matrix,
                                 const ExperimentRun& run) {
  std::string csv = csv_line({"descriptor", "label", "metric", "pairs", "pairs_without_revisit",
                              "pairs_defined", "pairs_undefined", "mean", "median", "min", "max"});
  for (const auto& aggregate : aggregate_matrix(config, matrix, run)) {
    for (const auto& metric : aggregate.metrics) {
      csv +=
          csv_line({aggregate.id, aggregate.label, metric.metric, std::to_string(aggregate.pairs),
                    std::to_string(aggregate.pairs_without_revisit), std::to_string(metric.pairs),
                    std::to_string(metric.undefined), csv_number(metric.mean),
                    csv_number(metric.median), csv_number(metric.min), csv_number(metric.max)});
    }
  }
  return csv;
}

std::string matrix_summary_markdown(const ExperimentConfig& config,
                                    const SessionMatrixConfig& matrix, const ExperimentRun& run) {
  std::vector<std::string> session_names;
  for (const auto& session : matrix.sessions) session_names.push_back(session.name);
  std::string md = fmt::format(
      "## Session matrix {}\n\n{} sessions ({}), {} ordered pairs (query session searched against "
      "database session). Per descriptor, each metric over the pairs where it is defined: mean, "
      "median, min and max (n = pairs with a defined value); per pair in {}/pairs.csv, and as "
      "CSV in {}/aggregate.csv.\n\n",
      matrix.name, matrix.sessions.size(), fmt::join(session_names, ", "), matrix.pairs.size(),
      matrix.name, matrix.name);
  // A replayed evaluator names the aggregate it reports (radarpr's own summaries stay as they
  // were).
  const Protocol& protocol = config.protocol;
  if (protocol.preset != ProtocolPreset::radarpr) {
    md += fmt::format(
        "Protocol preset `{}`: the figure it reports over session pairs is the {} column; "
        "Recall@K is over `{}`.\n\n",
        to_string(protocol.preset), to_string(protocol.pair_aggregation),
        to_string(protocol.recall_denominator));
  }
  for (const auto& aggregate : aggregate_matrix(config, matrix, run)) {
    md += fmt::format("### {}\n\n{} pairs, {} without a revisit\n\n", aggregate.label,
                      aggregate.pairs, aggregate.pairs_without_revisit);
    md += "| metric | n | mean | median | min | max |\n|---|---:|---:|---:|---:|---:|\n";
    for (const auto& metric : aggregate.metrics) {
      md += fmt::format("| {} | {} | {} | {} | {} | {} |\n", metric.metric, metric.pairs,
                        format_metric(metric.mean), format_metric(metric.median),
                        format_metric(metric.min), format_metric(metric.max));
    }
    md += "\n";
  }
  // Per pair: the two headline metrics of each descriptor.
  md += "### Per pair: Recall@1 / ROC AUC\n\n| query | database |";
  std::string rule = "|---|---|";
  for (const auto& instance : config.descriptors) {
    md += fmt::format(" {} |", instance.display_name());
    rule += "---:|";
  }
  md += "\n";
  md += rule;
  md += "\n";
  const auto pairs = matrix_pair_runs(config, matrix, run);
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    md += fmt::format("| {} | {} |", session_of(matrix, p, true), session_of(matrix, p, false));
    for (const DescriptorRun& descriptor : pairs[p]->descriptors) {
      const Metrics& m = descriptor.evaluation.metrics;
      md += fmt::format(" {} / {} |", format_metric(recall_at(m, 1, protocol.recall_denominator)),
                        format_metric(m.roc_auc));
    }
    md += "\n";
  }
  return md + "\n";
}

}  // namespace radarpr
