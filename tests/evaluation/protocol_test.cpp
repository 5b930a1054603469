#include "evaluation/protocol.hpp"

#include <gtest/gtest.h>

namespace radarpr {
namespace {

TEST(ProtocolNames, LabelRulesRoundTrip) {
  EXPECT_EQ(to_string(LabelRule::standard), "standard");
  EXPECT_EQ(to_string(LabelRule::retrieved_pair), "retrieved_pair");
  EXPECT_EQ(parse_label_rule("standard"), LabelRule::standard);
  EXPECT_EQ(parse_label_rule("retrieved_pair"), LabelRule::retrieved_pair);
}

TEST(ProtocolNames, ThresholdSweepsRoundTrip) {
  EXPECT_EQ(to_string(ThresholdSweep::exact), "exact");
  EXPECT_EQ(to_string(ThresholdSweep::linear100), "linear100");
  EXPECT_EQ(to_string(ThresholdSweep::mulran_grid), "mulran_grid");
  EXPECT_EQ(parse_threshold_sweep("exact"), ThresholdSweep::exact);
  EXPECT_EQ(parse_threshold_sweep("linear100"), ThresholdSweep::linear100);
  EXPECT_EQ(parse_threshold_sweep("mulran_grid"), ThresholdSweep::mulran_grid);
}

TEST(ProtocolNames, UnknownNamesAreRejected) {
  EXPECT_EQ(parse_label_rule("Standard"), std::nullopt);  // names are case-sensitive
  EXPECT_EQ(parse_label_rule(""), std::nullopt);
  EXPECT_EQ(parse_label_rule("retrieved pair"), std::nullopt);
  EXPECT_EQ(parse_threshold_sweep("linear"), std::nullopt);
  EXPECT_EQ(parse_threshold_sweep("exact "), std::nullopt);
}

TEST(ProtocolDefaults, MatchProtocolsDocument) {
  const Protocol protocol;
  EXPECT_EQ(protocol.exclude_recent_frames, 50);
  EXPECT_FALSE(protocol.exclude_recent_seconds.has_value());
  EXPECT_EQ(protocol.revisit_radius_m, 20.0);
  EXPECT_EQ(protocol.labels, LabelRule::standard);
  EXPECT_EQ(protocol.sweep, ThresholdSweep::exact);
  EXPECT_EQ(protocol.recall_at_k, (std::vector<int>{1, 5, 10}));
}

TEST(ProtocolPresets, EachSetsItsEvaluatorsRules) {
  const Protocol radarpr = protocol_preset(ProtocolPreset::radarpr);
  EXPECT_EQ(radarpr.exclude_recent_frames, Protocol{}.exclude_recent_frames);
  EXPECT_EQ(radarpr.radius_comparison, RadiusComparison::inclusive);
  EXPECT_EQ(radarpr.sweep, ThresholdSweep::exact);

  // main.m: candidates 1 .. end - (50 - 1), dist < criteria, 100 thresholds, misses counted for
  // every rejected revisit.
  const Protocol mulran = protocol_preset(ProtocolPreset::mulran_sc_evaluator);
  EXPECT_EQ(mulran.preset, ProtocolPreset::mulran_sc_evaluator);
  EXPECT_EQ(mulran.exclude_recent_frames, 49);
  EXPECT_EQ(mulran.radius_comparison, RadiusComparison::strict);
  EXPECT_EQ(mulran.labels, LabelRule::standard);
  EXPECT_EQ(mulran.sweep, ThresholdSweep::mulran_grid);

  // sparolab/referee util/recognition/recognition_utils.py: the query at i searches
  // descriptor[:i - 50], translation_diff < gt_threshold, similarity_distance < loop_thresh,
  // roc_auc_score over the pooled accepted pairs.
  const Protocol referee = protocol_preset(ProtocolPreset::referee_code);
  EXPECT_EQ(referee.exclude_recent_frames, 51);
  EXPECT_EQ(referee.radius_comparison, RadiusComparison::strict);
  EXPECT_EQ(referee.labels, LabelRule::retrieved_pair);
  EXPECT_EQ(referee.sweep, ThresholdSweep::referee_grid);
  EXPECT_EQ(referee.threshold_comparison, ThresholdComparison::strict);
  EXPECT_EQ(referee.roc_auc, RocAucVariant::pooled_pairs);
  // The other presets keep the inclusive threshold and the trapezoid.
  EXPECT_EQ(mulran.threshold_comparison, ThresholdComparison::inclusive);
  EXPECT_EQ(mulran.roc_auc, RocAucVariant::trapezoid);
  EXPECT_EQ(radarpr.roc_auc, RocAucVariant::trapezoid);
}

TEST(ProtocolPresets, NamesRoundTrip) {
  for (const auto preset : {ProtocolPreset::radarpr, ProtocolPreset::mulran_sc_evaluator,
                            ProtocolPreset::referee_code}) {
    EXPECT_EQ(parse_protocol_preset(to_string(preset)), preset);
  }
  EXPECT_EQ(parse_protocol_preset("mulran"), std::nullopt);
  EXPECT_EQ(parse_radius_comparison("strict"), RadiusComparison::strict);
  EXPECT_EQ(parse_radius_comparison("inclusive"), RadiusComparison::inclusive);
  EXPECT_EQ(parse_radius_comparison("<"), std::nullopt);
  EXPECT_EQ(parse_threshold_sweep("referee_grid"), ThresholdSweep::referee_grid);
  EXPECT_EQ(parse_threshold_comparison("strict"), ThresholdComparison::strict);
  EXPECT_EQ(parse_threshold_comparison("inclusive"), ThresholdComparison::inclusive);
  EXPECT_EQ(parse_threshold_comparison("<="), std::nullopt);
  EXPECT_EQ(parse_roc_auc_variant("pooled_pairs"), RocAucVariant::pooled_pairs);
  EXPECT_EQ(parse_roc_auc_variant("trapezoid"), RocAucVariant::trapezoid);
  EXPECT_EQ(parse_roc_auc_variant("pooled"), std::nullopt);
}

}  // namespace
}  // namespace radarpr
