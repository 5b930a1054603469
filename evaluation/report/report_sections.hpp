#pragma once

#include <string>
#include <vector>

#include "evaluation/report/html_page.hpp"
#include "evaluation/report/results_reader.hpp"
#include "evaluation/report/table.hpp"

namespace radarpr {

// The sections of a run's index.html: overview, Table I and II, the figures, the protocol, the
// descriptor ids and the machine and timing, all from summary.json. `figures` in the order the
// report wrote them (auc_vs_size, per dataset pr/roc, then the matching graphs).
std::vector<PageSection> report_sections(const RunResults& run, const Table& table1,
                                         const Table& table2,
                                         const std::vector<PageFigure>& figures);

// The protocol in words (the same sentence summary.md opens with) and as JSON.
std::string protocol_html(const nlohmann::json& protocol);

}  // namespace radarpr
