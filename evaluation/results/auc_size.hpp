#pragma once

#include <optional>
#include <string>
#include <vector>

#include "evaluation/results/results_reader.hpp"

namespace radarpr {

// One point of the AUC-against-size figure: a descriptor configuration's ROC AUC averaged over
// the datasets of one session kind it ran on (the ReFeree paper's Figure 1 plots one value per
// kind).
struct AucSizePoint {
  bool multi_session = false;
  std::string descriptor;            // the id
  std::string label;                 // the table name
  std::size_t descriptor_index = 0;  // position in the run's descriptors: its figure colour
  double payload_bytes = 0.0;
  std::optional<double> mean_auc;     // none when every AUC of the kind is undefined
  std::size_t datasets_averaged = 0;  // datasets with a defined ROC AUC
  std::size_t datasets_run = 0;       // datasets of that kind the configuration ran on
};

// Single-session points first, then multi; within a kind in config order (and, when a shape
// follows the scan geometry, one point per payload size).
std::vector<AucSizePoint> auc_size_points(const RunResults& run);

// When the points of one session kind average different numbers of datasets (n/a AUCs), their
// means are not comparable: a sentence saying which, else nothing.
std::optional<std::string> auc_size_unequal_note(const std::vector<AucSizePoint>& points);

}  // namespace radarpr
