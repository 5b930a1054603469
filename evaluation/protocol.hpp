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
  // The ReFeree code's 100: evenly spaced from the smallest non-zero top-1 distance to the largest
  // (single session), or to the largest + (largest - smallest) / 100 (multi session).
  referee_grid,
};

// When a threshold accepts a query's top-1 distance d.
enum class ThresholdComparison {
  inclusive,  // d <= threshold (radarpr, the MulRan evaluator)
  strict,     // d < threshold (the ReFeree code)
};

// Which ROC AUC the `roc_auc` metric is (protocols.md, "Metrics").
enum class RocAucVariant {
  // The trapezoid over the sweep's (FPR, TPR) points with (0,0) and (1,1) added.
  trapezoid,
  // The ReFeree code's: every pair accepted at every threshold of the sweep pooled into one
  // sample (label: the pair is wrong; score: its distance), and the ROC AUC of that sample
  // (scikit-learn's roc_auc_score).
  pooled_pairs,
  // VPR-Bench's: scikit-learn's roc_auc_score over the queries, one sample each (label: its top-1
  // is right; score: minus its distance), ties counted half. It does not depend on the sweep.
  query_ranks,
};

// What Recall@K is a share of (protocols.md, "Recall denominators"). All three are reported; this
// says which one the summary's Recall@K columns and a session matrix's aggregates show.
enum class RecallDenominator {
  revisit_queries,        // queries with a frame within the radius among those they may match
  all_queries,            // every evaluated query (Open-RadVLAD's and VPR-Bench's code)
  queries_with_positive,  // queries with a positive in their database (OpenPlaceRecognition)
};

// How a session matrix's per-pair values are summarised in its headline (protocols.md, "Session
// matrices"): every aggregate lists mean and median; this names the one the evaluator reports.
enum class PairAggregation {
  mean,    // OpenPlaceRecognition, radarpr
  median,  // Open-RadVLAD
};

// The scans a trainable descriptor (a codebook) learns from, per dataset.
enum class TrainingSource {
  database,           // the database session; in a single session, the sequence itself
  training_sequence,  // the dataset's own "training" sequence
};

// Whether a frame exactly revisit_radius_m away counts as a revisit.
enum class RadiusComparison {
  inclusive,  // distance <= radius (radarpr)
  strict,     // distance < radius (the MulRan evaluator's isRevisitGlobalLoc.m, is_revisit.m)
};

// A published evaluator replayed under one name (protocols.md, "Protocol presets"): the preset
// sets the defaults of the keys below, and a key given in the config still overrides it.
enum class ProtocolPreset {
  radarpr,              // radarpr's own protocol (the default)
  mulran_sc_evaluator,  // gisbi-kim/scancontext fast_evaluator_radar/main.m
  referee_code,         // sparolab/referee's evaluation (util/recognition/recognition_utils.py)
  open_radvlad,         // mttgdd/open-radvlad src/eval.py (do_eval), launch/vlad.py
  vpr_bench,            // MubarizZaffar/VPR-Bench performance_comparison.py
};

// The evaluation protocol; every result file records it.
struct Protocol {
  ProtocolPreset preset = ProtocolPreset::radarpr;
  // Single session: a query may match frames at least this many frames older...
  int exclude_recent_frames = 50;
  // ...or, when set, at least this many seconds older (replaces the frame count).
  std::optional<double> exclude_recent_seconds;
  double revisit_radius_m = 20.0;
  RadiusComparison radius_comparison = RadiusComparison::inclusive;
  // Heading-aware ground truth: when set, a frame is a positive only when its heading also
  // differs from the query's by at most this many degrees, in (0, 180] (protocols.md, "Ground
  // truth"). Empty: position only.
  std::optional<double> revisit_max_yaw_deg;
  LabelRule labels = LabelRule::standard;
  ThresholdSweep sweep = ThresholdSweep::exact;
  ThresholdComparison threshold_comparison = ThresholdComparison::inclusive;
  RocAucVariant roc_auc = RocAucVariant::trapezoid;
  std::vector<int> recall_at_k = {1, 5, 10};  // sorted, unique, >= 1
  RecallDenominator recall_denominator = RecallDenominator::revisit_queries;
  PairAggregation pair_aggregation = PairAggregation::mean;
  TrainingSource train_on = TrainingSource::database;
};

// The protocol a preset stands for, before any individual key is applied:
// radarpr: 50 frames excluded, inclusive radius, standard labels, exact sweep;
// mulran_sc_evaluator: a query matches frames >= 49 older (candidates 1 .. end - 49), strict
// radius, standard labels, mulran_grid (its 100 thresholds);
// referee_code: frames >= 51 older, strict radius, retrieved_pair labels, referee_grid sweep,
// strict threshold comparison, pooled-pairs ROC AUC;
// open_radvlad: a revisit within 25 m, strict radius, Recall@K over all queries, median over
// session pairs;
// vpr_bench: retrieved_pair labels, exact sweep, query-ranks ROC AUC, Recall@K over all queries.
Protocol protocol_preset(ProtocolPreset preset);

std::string_view to_string(ProtocolPreset preset);
std::optional<ProtocolPreset> parse_protocol_preset(std::string_view text);
std::string_view to_string(RadiusComparison comparison);
std::optional<RadiusComparison> parse_radius_comparison(std::string_view text);
std::string_view to_string(LabelRule rule);
std::string_view to_string(ThresholdSweep sweep);
std::string_view to_string(TrainingSource source);
std::optional<TrainingSource> parse_training_source(std::string_view text);
std::optional<LabelRule> parse_label_rule(std::string_view text);
std::optional<ThresholdSweep> parse_threshold_sweep(std::string_view text);
std::string_view to_string(ThresholdComparison comparison);
std::optional<ThresholdComparison> parse_threshold_comparison(std::string_view text);
std::string_view to_string(RocAucVariant variant);
std::optional<RocAucVariant> parse_roc_auc_variant(std::string_view text);
std::string_view to_string(RecallDenominator denominator);
std::optional<RecallDenominator> parse_recall_denominator(std::string_view text);
std::string_view to_string(PairAggregation aggregation);
std::optional<PairAggregation> parse_pair_aggregation(std::string_view text);

}  // namespace radarpr
