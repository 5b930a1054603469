#include "evaluation/results/paper_tables.hpp"

#include <algorithm>
#include <initializer_list>
#include <optional>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace radarpr {

std::string metric_text(const std::optional<double>& value) {
  return value ? fmt::format("{:.3f}", *value) : "n/a";
}

Table without_bold(Table table) {
  for (auto& row : table.rows) {
    for (auto& cell : row) cell.bold = false;
  }
  return table;
}

void bold_best(Table& table, const std::vector<std::size_t>& columns) {
  for (std::size_t c : columns) {
    // Compared as shown: two values that print alike are equally best.
    std::optional<double> best;
    for (const auto& row : table.rows) {
      if (row[c].text == "n/a" || row[c].text.empty()) continue;
      const double value = std::stod(row[c].text);
      if (!best || value > *best) best = value;
    }
    if (!best) continue;
    for (auto& row : table.rows) {
      if (row[c].text != "n/a" && !row[c].text.empty() && std::stod(row[c].text) == *best) {
        row[c].bold = true;
      }
    }
  }
}

namespace {

// A metric column of a per-dataset table: its header after the dataset name, and the row field.
struct MetricColumn {
  const char* suffix;
  std::optional<double> ResultRow::*value;
};

// One row per descriptor (config order, named by its label), per dataset one column per metric
// with 3 decimals ("n/a" when undefined or when the descriptor has no row there), the best of
// each column in bold.
Table per_dataset_table(const RunResults& run, std::initializer_list<MetricColumn> metrics) {
  Table table;
  table.header = {"descriptor"};
  table.numeric = {false};
  std::vector<std::size_t> metric_columns;
  table.groups.push_back({"", 1, {"descriptor"}});
  for (const auto& dataset : run.datasets) {
    ColumnGroup group{dataset, 0, {}};
    for (const auto& metric : metrics) {
      table.header.push_back(dataset + metric.suffix);
      table.numeric.push_back(true);
      metric_columns.push_back(table.header.size() - 1);
      group.subheaders.push_back(std::string(metric.suffix).substr(1));  // without the space
      ++group.columns;
    }
    table.groups.push_back(std::move(group));
  }
  for (const auto& id : run.descriptors) {
    std::vector<TableCell> row{{id}};
    for (const auto& dataset : run.datasets) {
      const ResultRow* result = run.find(dataset, id);
      if (result != nullptr) row.front().text = result->label;
      for (const auto& metric : metrics) {
        row.push_back({result ? metric_text(result->*metric.value) : "n/a"});
      }
    }
    table.rows.push_back(std::move(row));
  }
  bold_best(table, metric_columns);
  return table;
}

}  // namespace

Table metrics_table(const RunResults& run) {
  return per_dataset_table(run, {{" AUC", &ResultRow::roc_auc}, {" F1-max", &ResultRow::f1_max}});
}

Table metrics_recall_table(const RunResults& run) {
  return per_dataset_table(run, {{" AUC", &ResultRow::roc_auc},
                                 {" F1-max", &ResultRow::f1_max},
                                 {" R@1", &ResultRow::recall_at_1}});
}

Table retrieval_table(const RunResults& run) {
  return per_dataset_table(run, {{" PR-AUC", &ResultRow::pr_auc},
                                 {" R@1", &ResultRow::recall_at_1},
                                 {" R@100P", &ResultRow::recall_at_100_precision}});
}

Table size_table(const RunResults& run) {
  Table table;
  table.header = {
      "descriptor",        "id", "shape", "element type", "payload bytes", "paper bytes",
      "rotation-invariant"};
  table.numeric = {false, false, false, false, true, true, false};
  for (const auto& id : run.descriptors) {
    // A shape can follow the scan geometry (R-ReFeree's chunks follow R): list each one seen.
    std::vector<std::string> shapes, payloads, papers;
    const ResultRow* first = nullptr;
    for (const auto& dataset : run.datasets) {
      const ResultRow* r = run.find(dataset, id);
      if (r == nullptr) continue;
      if (first == nullptr) first = r;
      const std::string shape = fmt::format("{}x{}", r->rows, r->cols);
      if (std::find(shapes.begin(), shapes.end(), shape) != shapes.end()) continue;
      shapes.push_back(shape);
      payloads.push_back(fmt::format("{:.0f}", r->payload_bytes));
      papers.push_back(fmt::format("{:.0f}", r->paper_bytes));
    }
    if (first == nullptr) continue;
    table.rows.push_back({{first->label},
                          {id, false, true},
                          {fmt::format("{}", fmt::join(shapes, " / "))},
                          {first->element_type},
                          {fmt::format("{}", fmt::join(payloads, " / "))},
                          {fmt::format("{}", fmt::join(papers, " / "))},
                          {first->rotation_invariant ? "yes" : "no"}});
  }
  return table;
}

Table auc_size_table(const std::vector<AucSizePoint>& points) {
  Table table;
  table.header = {"descriptor", "session", "payload bytes", "mean ROC AUC", "datasets averaged"};
  table.numeric = {false, false, true, true, true};
  for (const auto& p : points) {
    table.rows.push_back({{p.label},
                          {p.multi_session ? "multi" : "single"},
                          {fmt::format("{:.0f}", p.payload_bytes)},
                          {metric_text(p.mean_auc)},
                          {fmt::format("{} of {}", p.datasets_averaged, p.datasets_run)}});
  }
  return table;
}

}  // namespace radarpr
