#include "evaluation/results/auc_size.hpp"

#include <algorithm>
#include <tuple>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace radarpr {

std::vector<AucSizePoint> auc_size_points(const RunResults& run) {
  std::vector<AucSizePoint> points;
  std::vector<double> auc_sums;
  for (const bool multi : {false, true}) {
    for (std::size_t d = 0; d < run.descriptors.size(); ++d) {
      for (const auto& row : run.rows) {
        if (row.multi_session != multi || row.descriptor != run.descriptors[d]) continue;
        auto point = std::find_if(points.begin(), points.end(), [&](const AucSizePoint& p) {
          return p.multi_session == multi && p.descriptor == row.descriptor &&
                 p.payload_bytes == row.payload_bytes;
        });
        if (point == points.end()) {
          points.push_back({multi, row.descriptor, row.label, d, row.payload_bytes, {}, 0, 0});
          auc_sums.push_back(0.0);
          point = points.end() - 1;
        }
        const auto at = static_cast<std::size_t>(point - points.begin());
        ++point->datasets_run;
        if (row.roc_auc) {
          ++point->datasets_averaged;
          auc_sums[at] += *row.roc_auc;
        }
      }
    }
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (points[i].datasets_averaged > 0) {
      points[i].mean_auc = auc_sums[i] / static_cast<double>(points[i].datasets_averaged);
    }
  }
  return points;
}

std::optional<std::string> auc_size_unequal_note(const std::vector<AucSizePoint>& points) {
  // Means are comparable within a session kind when every point averages as many datasets;
  // n/a AUCs for all alike (a kind with no negatives) leave them comparable.
  std::vector<std::string> kinds;
  for (const bool multi : {false, true}) {
    std::vector<std::string> counts;
    std::optional<std::size_t> first;
    bool unequal = false;
    for (const auto& p : points) {
      if (p.multi_session != multi) continue;
      if (!first) first = p.datasets_averaged;
      unequal = unequal || p.datasets_averaged != *first;
      counts.push_back(fmt::format("{} {} of {}", p.label, p.datasets_averaged, p.datasets_run));
    }
    if (unequal) {
      kinds.push_back(
          fmt::format("{} session: {}", multi ? "multi" : "single", fmt::join(counts, ", ")));
    }
  }
  if (kinds.empty()) return std::nullopt;
  return fmt::format(
      "the mean ROC AUCs are over different numbers of datasets (an undefined AUC is left "
      "out), so they do not compare like for like; {}",
      fmt::join(kinds, "; "));
}

}  // namespace radarpr
