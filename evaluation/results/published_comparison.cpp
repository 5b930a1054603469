#include "evaluation/results/published_comparison.hpp"

#include <algorithm>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "evaluation/results/csv_file.hpp"
#include "evaluation/results/summary_table.hpp"
#include "evaluation/text_escaping.hpp"

namespace radarpr {
namespace {

std::optional<double> difference(const std::optional<double>& run,
                                 const std::optional<double>& paper) {
  if (!run || !paper) return std::nullopt;
  return *run - *paper;
}

std::optional<double> mean(const std::vector<double>& values) {
  if (values.empty()) return std::nullopt;
  double sum = 0.0;
  for (double value : values) sum += value;
  return sum / static_cast<double>(values.size());
}

std::string signed_metric(const std::optional<double>& value) {
  return value ? fmt::format("{:+.3f}", *value) : "n/a";
}

std::string csv_number(const std::optional<double>& value) {
  return value ? fmt::format("{}", *value) : "";
}

const DatasetRun* find_dataset(const ExperimentRun& run, const std::string& name) {
  const auto it = std::find_if(run.datasets.begin(), run.datasets.end(),
                               [&](const DatasetRun& dataset) { return dataset.name == name; });
  return it == run.datasets.end() ? nullptr : &*it;
}

}  // namespace

std::optional<double> PublishedComparisonRow::auc_difference() const {
  return difference(run_auc, paper_auc);
}

std::optional<double> PublishedComparisonRow::f1_max_difference() const {
  return difference(run_f1_max, paper_f1_max);
}

std::vector<PublishedComparisonRow> published_comparison(const ExperimentConfig& config,
                                                         const ExperimentRun& run) {
  std::vector<PublishedComparisonRow> rows;
  if (!config.published) return rows;
  const PublishedTables& tables = config.published->tables;
  for (std::size_t d = 0; d < config.descriptors.size(); ++d) {
    const std::string label = config.descriptors[d].display_name();
    const auto paper_row = tables.table_1.find(label);
    if (paper_row == tables.table_1.end()) continue;
    for (const std::string& column : tables.datasets) {
      PublishedComparisonRow row;
      row.descriptor = label;
      row.published_dataset = column;
      std::vector<double> aucs;
      std::vector<double> f1s;
      for (const auto& [run_name, published_name] : config.published->datasets) {
        if (published_name != column) continue;
        const DatasetRun* dataset = find_dataset(run, run_name);
        if (dataset == nullptr || d >= dataset->descriptors.size()) continue;
        row.run_datasets.push_back(run_name);
        const Metrics& metrics = dataset->descriptors[d].evaluation.metrics;
        if (metrics.roc_auc) aucs.push_back(*metrics.roc_auc);
        if (metrics.f1_max) f1s.push_back(*metrics.f1_max);
      }
      if (row.run_datasets.empty()) continue;
      row.run_auc = mean(aucs);
      row.run_f1_max = mean(f1s);
      const auto& scores = paper_row->second.at(column);
      row.paper_auc = scores.auc;
      row.paper_f1_max = scores.f1_max;
      rows.push_back(std::move(row));
    }
  }
  return rows;
}

std::string published_comparison_markdown(const ExperimentConfig& config,
                                          const ExperimentRun& run) {
  if (!config.published) return "";
  const PublishedTables& tables = config.published->tables;
  const auto rows = published_comparison(config, run);
  std::size_t known = 0;
  for (const auto& row : rows) known += row.paper_auc || row.paper_f1_max ? 1 : 0;
  std::string md = fmt::format(
      "## Beside the published Table I\n\nPaper: {} Its values: {}. Difference = this run - "
      "paper; n/a where either is unknown. A paper dataset that several datasets of this run "
      "stand for gets the mean of their values. {} of {} rows have a published value.\n\n",
      markdown_cell(tables.source), markdown_cell(tables.file.generic_string()), known,
      rows.size());
  if (!tables.table_1_status.empty()) {
    md += fmt::format("The file says: {}\n\n", markdown_cell(tables.table_1_status));
  }
  md +=
      "| descriptor | paper dataset | datasets here | AUC paper | AUC here | AUC difference | "
      "F1-max paper | F1-max here | F1-max difference |\n"
      "|---|---|---|---:|---:|---:|---:|---:|---:|\n";
  for (const auto& row : rows) {
    md += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
                      markdown_cell(row.descriptor), markdown_cell(row.published_dataset),
                      markdown_cell(fmt::format("{}", fmt::join(row.run_datasets, ", "))),
                      format_metric(row.paper_auc), format_metric(row.run_auc),
                      signed_metric(row.auc_difference()), format_metric(row.paper_f1_max),
                      format_metric(row.run_f1_max), signed_metric(row.f1_max_difference()));
  }

  // Table II: the run's shape and paper bytes (its first dataset's) beside the paper's.
  md +=
      "\n## Beside the published Table II\n\n| descriptor | paper shape | shape here | paper "
      "bytes | paper bytes here | difference | what the paper's bytes count |\n"
      "|---|---|---|---:|---:|---:|---|\n";
  for (std::size_t d = 0; d < config.descriptors.size(); ++d) {
    const std::string label = config.descriptors[d].display_name();
    const auto paper = std::find_if(tables.table_2.begin(), tables.table_2.end(),
                                    [&](const auto& size) { return size.descriptor == label; });
    if (paper == tables.table_2.end() || run.datasets.empty() ||
        d >= run.datasets.front().descriptors.size()) {
      continue;
    }
    const DescriptorRun& here = run.datasets.front().descriptors[d];
    const auto here_bytes = static_cast<long long>(here.paper_bytes);
    md += fmt::format("| {} | {} | {}x{} | {} | {} | {} | {} |\n", markdown_cell(label),
                      fmt::format("{}", fmt::join(paper->shape, "x")), here.rows, here.cols,
                      paper->bytes ? std::to_string(*paper->bytes) : "n/a", here_bytes,
                      paper->bytes ? fmt::format("{:+}", here_bytes - *paper->bytes) : "n/a",
                      markdown_cell(paper->convention.empty() ? "not stated" : paper->convention));
  }
  return md + "\n";
}

std::string published_comparison_csv(const ExperimentConfig& config, const ExperimentRun& run) {
  std::string csv =
      csv_line({"descriptor", "paper_dataset", "datasets_here", "auc_paper", "auc_here",
                "auc_difference", "f1_max_paper", "f1_max_here", "f1_max_difference"});
  for (const auto& row : published_comparison(config, run)) {
    csv += csv_line({row.descriptor, row.published_dataset,
                     fmt::format("{}", fmt::join(row.run_datasets, ";")), csv_number(row.paper_auc),
                     csv_number(row.run_auc), csv_number(row.auc_difference()),
                     csv_number(row.paper_f1_max), csv_number(row.run_f1_max),
                     csv_number(row.f1_max_difference())});
  }
  return csv;
}

}  // namespace radarpr
