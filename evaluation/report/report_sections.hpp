#pragma once

#include <optional>
#include <string>
#include <vector>

#include "evaluation/report/html_page.hpp"
#include "evaluation/results/results_reader.hpp"
#include "evaluation/results/table.hpp"

namespace radarpr {

// The page's Table I heading: the table1 files' metrics and Recall@1.
inline constexpr const char* kPageMetricsTableTitle =
    "Table I: ROC AUC, F1-max and Recall@1 per dataset";

// The sections of a run's index.html: overview, Table I and II, the figures, the protocol, the
// descriptor ids and the machine and timing, all from summary.json. `figures` in the order the
// report wrote them (auc_vs_size, per dataset pr/roc, then the matching graphs).
struct ReportTables {
  Table metrics;    // Table I
  Table sizes;      // Table II
  Table auc_means;  // table3: the AUC-against-size figure's values
  Table retrieval;  // table4: PR-AUC, Recall@1, R@100P
};

// `auc_note`: auc_size_unequal_note, shown beside the figure.
std::vector<PageSection> report_sections(const RunResults& run, const ReportTables& tables,
                                         const std::optional<std::string>& auc_note,
                                         const std::vector<PageFigure>& figures);

// A summary.json value as summary.md writes it: a string without quotes, 20 not 20.0.
std::string json_text(const nlohmann::json& value);

// The protocol in words (the same sentence summary.md opens with) and as JSON.
std::string protocol_html(const nlohmann::json& protocol);

}  // namespace radarpr
