#pragma once

#include <optional>
#include <string>
#include <vector>

#include "evaluation/results/auc_size.hpp"
#include "evaluation/results/results_reader.hpp"
#include "evaluation/results/table.hpp"

namespace radarpr {

// The headings summary.md and the report give Table I and Table II.
inline constexpr const char* kMetricsTableTitle = "Table I: ROC AUC and F1-max per dataset";
inline constexpr const char* kSizeTableTitle = "Table II: descriptor size";
inline constexpr const char* kRetrievalTableTitle =
    "Retrieval per dataset: PR-AUC, Recall@1 and R@100P";

// Table I and II are built here only: summary.md (results_writer) and the report (table1/2
// files, index.html) both show these.
// The ReFeree paper's Table I: one row per descriptor (config order), per dataset its ROC AUC and
// F1-max with 3 decimals (summary.md's rounding), the best of each column in bold.
Table metrics_table(const RunResults& run);
// The ReFeree paper's Table II: per descriptor its shape(s), element type, payload and paper bytes
// (each distinct shape the datasets gave, "a / b"), and rotation invariance.
Table size_table(const RunResults& run);

// Table I as the report's page shows it: per dataset ROC AUC, F1-max and Recall@1 (the headline
// number of place-recognition papers, beside the ReFeree paper's two), the best of each column in
// bold. summary.md and the table1 files keep metrics_table.
Table metrics_recall_table(const RunResults& run);

// What place-recognition papers report besides Table I: per descriptor and dataset the PR-AUC
// (trapezoid over the sweep), Recall@1 (of the revisit queries) and R@100P (the recall at the
// highest threshold with no false positive), 3 decimals, the best of each column in bold.
Table retrieval_table(const RunResults& run);

// The AUC-against-size figure's points as a table: descriptor, session kind, payload bytes,
// mean ROC AUC (3 decimals) and "datasets averaged of run". Kept out of Table I, whose values
// are summary.md's.
Table auc_size_table(const std::vector<AucSizePoint>& points);

// "0.912" or "n/a", as summary.md writes a metric.
std::string metric_text(const std::optional<double>& value);
// The table with no cell in bold (summary.md's plain copy).
Table without_bold(Table table);
// Marks bold, in each listed column, every cell showing the column's highest value.
void bold_best(Table& table, const std::vector<std::size_t>& columns);

}  // namespace radarpr
