#pragma once

#include <optional>
#include <string_view>
#include <vector>

namespace radarpr {

// How TP/FP/FN/TN are assigned at a threshold (protocols.md, "Labels per threshold").
enum class LabelRule {
  standard,        // rejected revisit -> FN, rejected non-revisit -> TN (MulRan evaluator)
  retrieved_pair,  // rejected -> FN when the retrieved frame is within the radius (ReFeree code)
};

// Which thresholds the PR/ROC curves are computed at (protocols.md, "Scores and thresholds").
enum class ThresholdSweep {
  exact,        // every distinct top-1 distance
  linear100,    // 100 evenly spaced between the smallest and the largest distance
  mulran_grid,  // 50 in [0, 0.01] and 50 in [0.01, 1]
};

// The scans a trainable descriptor (a codebook) learns from, per dataset.
enum class TrainingSource {
  database,           // the database session; in a single session, the sequence itself
  training_sequence,  // the dataset's own "training" sequence
};

// The evaluation protocol; every result file records it.
struct Protocol {
  // Single session: a query may match frames at least this many frames older...
  int exclude_recent_frames = 50;
  // ...or, when set, at least this many seconds older (replaces the frame count).
  std::optional<double> exclude_recent_seconds;
  double revisit_radius_m = 20.0;
  LabelRule labels = LabelRule::standard;
  ThresholdSweep sweep = ThresholdSweep::exact;
  std::vector<int> recall_at_k = {1, 5, 10};  // sorted, unique, >= 1
  TrainingSource train_on = TrainingSource::database;
};

std::string_view to_string(LabelRule rule);
std::string_view to_string(ThresholdSweep sweep);
std::string_view to_string(TrainingSource source);
std::optional<TrainingSource> parse_training_source(std::string_view text);
std::optional<LabelRule> parse_label_rule(std::string_view text);
std::optional<ThresholdSweep> parse_threshold_sweep(std::string_view text);

}  // namespace radarpr
