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

// Under a table where a Recall@K is n/a although Recall@1 is defined: the descriptor hands over
// only the candidates of its key pre-search (RetrievalMethod::key_then_rerank), so a K beyond
// them cannot be judged. Said here, not only in code, so that the n/a is not read as a failure.
std::string rerank_note(const DatasetRun& dataset, const Protocol& protocol) {
  std::vector<std::string> labels;
  std::vector<int> ks;
  for (const auto& run : dataset.descriptors) {
    const Metrics& m = run.evaluation.metrics;
    if (!recall_at(m, 1, protocol.recall_denominator)) continue;
    bool cut = false;
    for (int k : protocol.recall_at_k) {
      if (!recall_at(m, k, protocol.recall_denominator)) {
        cut = true;
        if (std::find(ks.begin(), ks.end(), k) == ks.end()) ks.push_back(k);
      }
    }
    if (cut) labels.push_back(markdown_cell(run.id));
  }
  if (labels.empty()) return "";
  std::sort(ks.begin(), ks.end());
  std::vector<std::string> columns;
  for (int k : ks) columns.push_back(fmt::format("Recall@{}", k));
  return fmt::format(
      "\nn/a under {} for {}: these descriptors re-rank only the candidates their key "
      "pre-search hands over (their `candidates` parameter), so a K beyond them cannot be "
      "judged.\n",
      fmt::join(columns, ", "), fmt::join(labels, ", "));
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
                         format_metric(recall_at(m, 1, protocol.recall_denominator)));
    for (int k : protocol.recall_at_k) {
      if (k == 1) continue;
      table += fmt::format(" {} |", format_metric(recall_at(m, k, protocol.recall_denominator)));
    }
    table += fmt::format(" {} | {} |\n", m.queries, m.revisits);
  }
  return table + rerank_note(dataset, protocol);
}

}  // namespace radarpr
