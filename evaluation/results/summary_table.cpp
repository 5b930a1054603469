#include "evaluation/results/summary_table.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "evaluation/text_escaping.hpp"

namespace radarpr {

std::string format_metric(const std::optional<double>& value) {
  return value ? fmt::format("{:.3f}", *value) : "n/a";
}

std::string describe_session(const DatasetRun& dataset, const Protocol& protocol) {
  if (dataset.multi_session) {
    return fmt::format("multi session: {} against {}", dataset.query_sequence,
                       dataset.database_sequence);
  }
  const std::string exclusion =
      protocol.exclude_recent_seconds
          ? fmt::format("the last {} s excluded", *protocol.exclude_recent_seconds)
          : fmt::format("the {} most recent frames excluded", protocol.exclude_recent_frames);
  return fmt::format("single session: {}, {} scans, {}", dataset.query_sequence,
                     dataset.query_records.size(), exclusion);
}

std::string summary_table(const DatasetRun& dataset, const Protocol& protocol) {
  std::string header =
      "| descriptor | shape | element type | payload bytes | paper bytes | ROC AUC | F1-max | "
      "Recall@1 |";
  std::string rule = "|---|---|---|---:|---:|---:|---:|---:|";
  for (int k : protocol.recall_at_k) {
    if (k == 1) continue;
    header += fmt::format(" Recall@{} |", k);
    rule += "---:|";
  }
  header += " queries | revisits |\n";
  rule += "---:|---:|\n";
  std::string table = header + rule;
  for (const auto& run : dataset.descriptors) {
    const Metrics& m = run.evaluation.metrics;
    table += fmt::format("| {} | {}x{} | {} | {} | {} | {} | {} | {} |", markdown_cell(run.id),
                         run.rows, run.cols, kDescriptorElementType, run.payload_bytes,
                         run.paper_bytes, format_metric(m.roc_auc), format_metric(m.f1_max),
                         format_metric(m.recall_at_1));
    for (int k : protocol.recall_at_k) {
      if (k == 1) continue;
      const auto it = m.recall_at_k.find(k);
      table += fmt::format(" {} |",
                           format_metric(it == m.recall_at_k.end() ? std::nullopt : it->second));
    }
    table += fmt::format(" {} | {} |\n", m.queries, m.revisits);
  }
  return table;
}

std::string paper_metrics_table(const ExperimentRun& run) {
  if (run.datasets.empty()) return "";
  std::string header = "| descriptor |";
  std::string rule = "|---|";
  for (const auto& dataset : run.datasets) {
    header += fmt::format(" {} AUC | {} F1-max |", markdown_cell(dataset.name),
                          markdown_cell(dataset.name));
    rule += "---:|---:|";
  }
  std::string table = header + "\n" + rule + "\n";
  // Every dataset runs the experiment's descriptors in the same order.
  for (std::size_t d = 0; d < run.datasets.front().descriptors.size(); ++d) {
    table += fmt::format("| {} |", markdown_cell(run.datasets.front().descriptors[d].label));
    for (const auto& dataset : run.datasets) {
      const Metrics& m = dataset.descriptors[d].evaluation.metrics;
      table += fmt::format(" {} | {} |", format_metric(m.roc_auc), format_metric(m.f1_max));
    }
    table += "\n";
  }
  return table;
}

std::string paper_size_table(const ExperimentRun& run) {
  if (run.datasets.empty()) return "";
  std::string table =
      "| descriptor | id | shape | element type | payload bytes | paper bytes | rotation-invariant "
      "|\n|---|---|---|---|---:|---:|---|\n";
  for (std::size_t d = 0; d < run.datasets.front().descriptors.size(); ++d) {
    // A shape can follow the scan geometry (R-ReFeree's chunks follow R): list each one seen.
    std::vector<std::string> shapes, payloads, papers;
    for (const auto& dataset : run.datasets) {
      const DescriptorRun& r = dataset.descriptors[d];
      const std::string shape = fmt::format("{}x{}", r.rows, r.cols);
      if (std::find(shapes.begin(), shapes.end(), shape) != shapes.end()) continue;
      shapes.push_back(shape);
      payloads.push_back(fmt::format("{}", r.payload_bytes));
      papers.push_back(fmt::format("{}", r.paper_bytes));
    }
    const DescriptorRun& first = run.datasets.front().descriptors[d];
    table += fmt::format("| {} | {} | {} | {} | {} | {} | {} |\n", markdown_cell(first.label),
                         markdown_code_cell(first.id), fmt::join(shapes, " / "),
                         kDescriptorElementType, fmt::join(payloads, " / "),
                         fmt::join(papers, " / "), first.rotation_invariant ? "yes" : "no");
  }
  return table;
}

}  // namespace radarpr
