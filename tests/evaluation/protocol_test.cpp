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

}  // namespace
}  // namespace radarpr
