#include "evaluation/protocol.hpp"

#include <initializer_list>

namespace radarpr {
namespace {

// The value among `values` whose to_string() is `text`: every parse below is the inverse of its
// to_string, so a name is spelled in one place only.
template <typename Enum>
std::optional<Enum> parse_named(std::string_view text, std::initializer_list<Enum> values) {
  for (const Enum value : values) {
    if (text == to_string(value)) return value;
  }
  return std::nullopt;
}

}  // namespace

// The names below are the ones result files and configs use (protocols.md).

Protocol protocol_preset(ProtocolPreset preset) {
  Protocol protocol;
  protocol.preset = preset;
  switch (preset) {
    case ProtocolPreset::radarpr:
      break;
    case ProtocolPreset::mulran_sc_evaluator:
      protocol.exclude_recent_frames = 49;
      protocol.radius_comparison = RadiusComparison::strict;
      protocol.labels = LabelRule::standard;
      protocol.sweep = ThresholdSweep::mulran_grid;
      break;
    case ProtocolPreset::referee_code:
      // The query at index i searches descriptor[:i - 50]; a pair is right when the positions
      // are < gt_threshold apart; a threshold accepts a distance below it.
      protocol.exclude_recent_frames = 51;
      protocol.radius_comparison = RadiusComparison::strict;
      protocol.labels = LabelRule::retrieved_pair;
      protocol.sweep = ThresholdSweep::referee_grid;
      protocol.threshold_comparison = ThresholdComparison::strict;
      protocol.roc_auc = RocAucVariant::pooled_pairs;
      break;
    case ProtocolPreset::open_radvlad:
      // do_eval: positives are the database frames closer than gps_match_tolerance (25.0 in its
      // config/test.yaml), and Recall@K is the share of all queries with a positive among the K
      // nearest. The code sweeps no threshold: labels, sweep and ROC AUC stay radarpr's.
      protocol.revisit_radius_m = 25.0;
      protocol.radius_comparison = RadiusComparison::strict;
      protocol.recall_denominator = RecallDenominator::all_queries;
      protocol.pair_aggregation = PairAggregation::median;
      break;
    case ProtocolPreset::vpr_bench:
      // performance_comparison.py: a query's label is whether its top-1 is right, its score the
      // top-1 similarity; PR and ROC come from scikit-learn over these (every distinct score a
      // threshold, accepted when score >= threshold); RecallRate@N divides by all queries.
      protocol.labels = LabelRule::retrieved_pair;
      protocol.sweep = ThresholdSweep::exact;
      protocol.threshold_comparison = ThresholdComparison::inclusive;
      protocol.roc_auc = RocAucVariant::query_ranks;
      protocol.recall_denominator = RecallDenominator::all_queries;
      break;
  }
  return protocol;
}

std::string_view to_string(ProtocolPreset preset) {
  switch (preset) {
    case ProtocolPreset::radarpr:
      return "radarpr";
    case ProtocolPreset::mulran_sc_evaluator:
      return "mulran_sc_evaluator";
    case ProtocolPreset::referee_code:
      return "referee_code";
    case ProtocolPreset::open_radvlad:
      return "open_radvlad";
    case ProtocolPreset::vpr_bench:
      return "vpr_bench";
  }
  return "unknown";
}

std::optional<ProtocolPreset> parse_protocol_preset(std::string_view text) {
  return parse_named(text, {ProtocolPreset::radarpr, ProtocolPreset::mulran_sc_evaluator,
                            ProtocolPreset::referee_code, ProtocolPreset::open_radvlad,
                            ProtocolPreset::vpr_bench});
}

std::string_view to_string(RadiusComparison comparison) {
  return comparison == RadiusComparison::strict ? "strict" : "inclusive";
}

std::optional<RadiusComparison> parse_radius_comparison(std::string_view text) {
  return parse_named(text, {RadiusComparison::inclusive, RadiusComparison::strict});
}

std::string_view to_string(LabelRule rule) {
  switch (rule) {
    case LabelRule::standard:
      return "standard";
    case LabelRule::retrieved_pair:
      return "retrieved_pair";
  }
  return "unknown";
}

std::string_view to_string(ThresholdSweep sweep) {
  switch (sweep) {
    case ThresholdSweep::exact:
      return "exact";
    case ThresholdSweep::linear100:
      return "linear100";
    case ThresholdSweep::mulran_grid:
      return "mulran_grid";
    case ThresholdSweep::referee_grid:
      return "referee_grid";
  }
  return "unknown";
}

std::string_view to_string(TrainingSource source) {
  switch (source) {
    case TrainingSource::database:
      return "database";
    case TrainingSource::training_sequence:
      return "training_sequence";
  }
  return "unknown";
}

std::optional<TrainingSource> parse_training_source(std::string_view text) {
  return parse_named(text, {TrainingSource::database, TrainingSource::training_sequence});
}

std::optional<LabelRule> parse_label_rule(std::string_view text) {
  return parse_named(text, {LabelRule::standard, LabelRule::retrieved_pair});
}

std::optional<ThresholdSweep> parse_threshold_sweep(std::string_view text) {
  return parse_named(text, {ThresholdSweep::exact, ThresholdSweep::linear100,
                            ThresholdSweep::mulran_grid, ThresholdSweep::referee_grid});
}

std::string_view to_string(ThresholdComparison comparison) {
  return comparison == ThresholdComparison::strict ? "strict" : "inclusive";
}

std::optional<ThresholdComparison> parse_threshold_comparison(std::string_view text) {
  return parse_named(text, {ThresholdComparison::inclusive, ThresholdComparison::strict});
}

std::string_view to_string(RocAucVariant variant) {
  switch (variant) {
    case RocAucVariant::trapezoid:
      return "trapezoid";
    case RocAucVariant::pooled_pairs:
      return "pooled_pairs";
    case RocAucVariant::query_ranks:
      return "query_ranks";
  }
  return "unknown";
}

std::optional<RocAucVariant> parse_roc_auc_variant(std::string_view text) {
  return parse_named(
      text, {RocAucVariant::trapezoid, RocAucVariant::pooled_pairs, RocAucVariant::query_ranks});
}

std::string_view to_string(RecallDenominator denominator) {
  switch (denominator) {
    case RecallDenominator::revisit_queries:
      return "revisit_queries";
    case RecallDenominator::all_queries:
      return "all_queries";
    case RecallDenominator::queries_with_positive:
      return "queries_with_positive";
  }
  return "unknown";
}

std::optional<RecallDenominator> parse_recall_denominator(std::string_view text) {
  return parse_named(text, {RecallDenominator::revisit_queries, RecallDenominator::all_queries,
                            RecallDenominator::queries_with_positive});
}

std::string_view to_string(PairAggregation aggregation) {
  return aggregation == PairAggregation::median ? "median" : "mean";
}

std::optional<PairAggregation> parse_pair_aggregation(std::string_view text) {
  return parse_named(text, {PairAggregation::mean, PairAggregation::median});
}

}  // namespace radarpr
