// The Open-RadVLAD and VPR-Bench presets replayed on hand-computed cases: what each published
// evaluator computes from the same retrieved lists (protocols.md, "Replay presets").
#include <gtest/gtest.h>

#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "evaluation/config/experiment_config.hpp"
#include "evaluation/descriptor_evaluation.hpp"
#include "evaluation/ground_truth.hpp"
#include "evaluation/metrics.hpp"
#include "evaluation/protocol.hpp"
#include "evaluation/results/session_matrix_tables.hpp"

namespace radarpr {
namespace {

void expect_near(const std::optional<double>& value, double expected) {
  ASSERT_TRUE(value.has_value());
  EXPECT_NEAR(*value, expected, 1e-12);
}

Neighbour neighbour(std::size_t index, double distance) {
  Neighbour n;
  n.index = index;
  n.distance = distance;
  return n;
}

// Database d0 (0,0), d1 (100,0), d2 (200,0); four queries, each with its ranked list of all
// three frames:
//   q0 (10,0):  d0 d1 d2   d0 is 10 m away: right at rank 1
//   q1 (125,0): d1 d0 d2   d1 is exactly 25 m away: a positive only with an inclusive radius
//   q2 (205,0): d0 d1 d2   d2 is 5 m away: right at rank 3
//   q3 (500,0): d2 d0 d1   nothing within 25 m
std::vector<QueryResult> four_queries(const Protocol& protocol) {
  const RevisitGroundTruth truth({{0, 0}, {100, 0}, {200, 0}}, protocol.revisit_radius_m,
                                 protocol.radius_comparison);
  const std::vector<std::vector<Neighbour>> neighbours = {
      {neighbour(0, 0.1), neighbour(1, 0.5), neighbour(2, 0.9)},
      {neighbour(1, 0.2), neighbour(0, 0.6), neighbour(2, 0.8)},
      {neighbour(0, 0.3), neighbour(1, 0.4), neighbour(2, 0.7)},
      {neighbour(2, 0.4), neighbour(0, 0.5), neighbour(1, 0.6)}};
  return build_query_results(neighbours, {{10, 0}, {125, 0}, {205, 0}, {500, 0}}, truth,
                             std::vector<std::size_t>(4, 3));
}

// Open-RadVLAD's do_eval: positives = positions closer than 25 m (strict), Recall@k = queries
// with a positive among the k nearest / all queries: q0 at k >= 1, q2 at k >= 3, so 1/4, 1/4,
// 2/4. Over the revisit queries (q0, q2) the same hits give 1/2, 1/2, 1.
TEST(OpenRadvladPreset, RecallOverAllQueriesWithAStrict25MetreRadius) {
  const Protocol protocol = protocol_preset(ProtocolPreset::open_radvlad);
  EXPECT_EQ(protocol.revisit_radius_m, 25.0);
  EXPECT_EQ(protocol.radius_comparison, RadiusComparison::strict);
  EXPECT_EQ(protocol.recall_denominator, RecallDenominator::all_queries);
  EXPECT_EQ(protocol.pair_aggregation, PairAggregation::median);
  EXPECT_EQ(protocol.exclude_recent_frames, 50);  // the code has no single session

  const auto results = four_queries(protocol);
  ASSERT_EQ(results.size(), 4u);
  EXPECT_FALSE(results[1].revisit);  // 25 m is not < 25 m
  const auto curve = compute_curve(results, sweep_thresholds(results, protocol.sweep),
                                   protocol.labels, protocol.threshold_comparison);
  const Metrics m =
      compute_metrics(results, curve, {1, 2, 3}, protocol.roc_auc, protocol.threshold_comparison);
  EXPECT_EQ(m.queries, 4u);
  EXPECT_EQ(m.revisits, 2u);
  expect_near(recall_at(m, 1, RecallDenominator::all_queries), 0.25);
  expect_near(recall_at(m, 2, RecallDenominator::all_queries), 0.25);
  expect_near(recall_at(m, 3, RecallDenominator::all_queries), 0.5);
  expect_near(recall_at(m, 1, RecallDenominator::revisit_queries), 0.5);
  expect_near(recall_at(m, 3, RecallDenominator::revisit_queries), 1.0);
  // OpenPlaceRecognition's denominator: the queries with a positive in their database, which
  // are the revisit queries.
  expect_near(recall_at(m, 1, RecallDenominator::queries_with_positive), 0.5);
  expect_near(recall_at(m, 3, RecallDenominator::queries_with_positive), 1.0);

  // The same lists with an inclusive 25 m radius: q1's top-1 is now right (2/4 at k = 1).
  Protocol inclusive = protocol;
  inclusive.radius_comparison = RadiusComparison::inclusive;
  const auto inclusive_results = four_queries(inclusive);
  const Metrics mi = compute_metrics(inclusive_results, {}, {1}, inclusive.roc_auc);
  expect_near(recall_at(mi, 1, RecallDenominator::all_queries), 0.5);
}

// Five queries: A d 1 right, B d 2 wrong, C d 3 wrong, D d 4 right, E d 4 wrong (ranks of the
// first right frame 1, 3, 0, 1, 0). VPR-Bench: matches [1 0 0 1 0], scores minus the distances.
//   precision_recall_curve, from the highest score: {A} P 1 R 1/2; {A,B} 1/2, 1/2;
//   {A,B,C} 1/3, 1/2; all 2/5, 1; then the end point (R 0, P 1).
//   auc(recall, precision) = 1/2 * (1 + 1)/2 + 1/2 * (1/3 + 2/5)/2 = 1/2 + 11/60 = 41/60.
//   roc_auc_score: A above B, C, E (3), D ties E (1/2): 3.5 / 6 = 7/12.
//   Extended precision: precision[-2] = 1, so (1 + the recall at the first precision of 1, 1/2)
//   / 2 = 3/4. RecallRate@N over all five queries: N = 1 2/5, N = 3 3/5.
std::vector<QueryResult> five_queries() {
  const auto make = [](std::size_t query, double distance, bool correct, bool revisit,
                       std::size_t rank) {
    QueryResult r;
    r.query = query;
    r.distance = distance;
    r.correct = correct;
    r.revisit = revisit;
    r.first_correct_rank = rank;
    return r;
  };
  return {make(0, 1.0, true, true, 1), make(1, 2.0, false, true, 3), make(2, 3.0, false, false, 0),
          make(3, 4.0, true, true, 1), make(4, 4.0, false, false, 0)};
}

TEST(VprBenchPreset, ReplaysPrecisionRecallRocAndExtendedPrecision) {
  const Protocol protocol = protocol_preset(ProtocolPreset::vpr_bench);
  EXPECT_EQ(protocol.labels, LabelRule::retrieved_pair);
  EXPECT_EQ(protocol.sweep, ThresholdSweep::exact);
  EXPECT_EQ(protocol.threshold_comparison, ThresholdComparison::inclusive);
  EXPECT_EQ(protocol.roc_auc, RocAucVariant::query_ranks);
  EXPECT_EQ(protocol.recall_denominator, RecallDenominator::all_queries);

  const auto results = five_queries();
  const auto curve = compute_curve(results, sweep_thresholds(results, protocol.sweep),
                                   protocol.labels, protocol.threshold_comparison);
  ASSERT_EQ(curve.size(), 4u);
  // Counts per threshold (d <= 1, 2, 3, 4): a rejected right top-1 is the only FN.
  const std::vector<std::vector<std::size_t>> counts = {
      {1, 0, 1, 3}, {1, 1, 1, 2}, {1, 2, 1, 1}, {2, 3, 0, 0}};
  for (std::size_t i = 0; i < curve.size(); ++i) {
    EXPECT_EQ(curve[i].counts.tp, counts[i][0]) << i;
    EXPECT_EQ(curve[i].counts.fp, counts[i][1]) << i;
    EXPECT_EQ(curve[i].counts.fn, counts[i][2]) << i;
    EXPECT_EQ(curve[i].counts.tn, counts[i][3]) << i;
  }
  const Metrics m =
      compute_metrics(results, curve, {1, 3}, protocol.roc_auc, protocol.threshold_comparison);
  expect_near(m.pr_auc_vpr_bench, 41.0 / 60.0);
  expect_near(m.roc_auc, 7.0 / 12.0);
  expect_near(m.extended_precision_vpr_bench, 0.75);
  expect_near(recall_at(m, 1, RecallDenominator::all_queries), 0.4);
  expect_near(recall_at(m, 3, RecallDenominator::all_queries), 0.6);
  // F1-max: 2TP / (2TP + FP + FN) at d <= 1: 2/3.
  expect_near(m.f1_max, 2.0 / 3.0);
  // The query-ranks AUC does not depend on the sweep.
  expect_near(roc_auc_query_ranks(results), 7.0 / 12.0);
}

// When the nearest top-1 is wrong, VPR-Bench's precision[-2] is 0, so its extended precision is
// (0 + 0) / 2; radarpr's takes the first threshold with a non-zero recall instead (P 1/2 at
// d <= 2): (1/2 + 0) / 2.
TEST(VprBenchPreset, ExtendedPrecisionStartsAtTheFirstAcceptedQuery) {
  auto results = five_queries();
  results = {results[1], results[3]};  // B d 2 wrong, D d 4 right
  const auto curve = compute_curve(results, sweep_thresholds(results, ThresholdSweep::exact),
                                   LabelRule::retrieved_pair);
  const Metrics m = compute_metrics(results, curve, {1}, RocAucVariant::query_ranks);
  expect_near(m.extended_precision_vpr_bench, 0.0);
  expect_near(m.extended_precision, 0.25);
  expect_near(m.roc_auc, 0.0);  // the wrong one is nearer
  // One class only: VPR-Bench prints that ROC is not computable; here it is undefined.
  EXPECT_FALSE(roc_auc_query_ranks({results[1]}).has_value());
  // No query accepted at all (no thresholds): both undefined, never 0.
  const Metrics none = compute_metrics(results, {}, {1});
  EXPECT_FALSE(none.extended_precision_vpr_bench.has_value());
  EXPECT_FALSE(none.extended_precision.has_value());
}

TEST(EvaluatorPresets, ConfigsNameThemAndKeysStillOverride) {
  nlohmann::json protocol = {{"preset", "open_radvlad"}};
  Protocol parsed = parse_protocol_object(protocol, "protocol");
  EXPECT_EQ(parsed.preset, ProtocolPreset::open_radvlad);
  EXPECT_EQ(parsed.revisit_radius_m, 25.0);
  // The record names every key under a preset, so that reading it back gives the same protocol.
  nlohmann::json record = protocol_to_json(parsed);
  EXPECT_EQ(record.at("preset"), "open_radvlad");
  EXPECT_EQ(record.at("recall_denominator"), "all_queries");
  EXPECT_EQ(record.at("pair_aggregation"), "median");
  EXPECT_EQ(record.at("radius_comparison"), "strict");
  record.erase("score");
  const Protocol again = parse_protocol_object(record, "protocol");
  EXPECT_EQ(again.radius_comparison, RadiusComparison::strict);
  EXPECT_EQ(again.recall_denominator, RecallDenominator::all_queries);

  protocol = {{"preset", "vpr_bench"},
              {"recall_denominator", "queries_with_positive"},
              {"pair_aggregation", "median"}};
  parsed = parse_protocol_object(protocol, "protocol");
  EXPECT_EQ(parsed.roc_auc, RocAucVariant::query_ranks);
  EXPECT_EQ(parsed.recall_denominator, RecallDenominator::queries_with_positive);
  EXPECT_EQ(parsed.pair_aggregation, PairAggregation::median);

  EXPECT_THROW(parse_protocol_object({{"recall_denominator", "revisits"}}, "protocol"),
               ConfigError);
  EXPECT_THROW(parse_protocol_object({{"pair_aggregation", "max"}}, "protocol"), ConfigError);
  // radarpr's own protocol names neither key (its results stay as they were).
  const nlohmann::json plain = protocol_to_json(Protocol{});
  EXPECT_FALSE(plain.contains("recall_denominator"));
  EXPECT_FALSE(plain.contains("pair_aggregation"));
}

// A session matrix under a preset aggregates Recall@K under the preset's denominator, named.
TEST(EvaluatorPresets, MatrixRecallColumnsNameTheirDenominator) {
  const Protocol protocol = protocol_preset(ProtocolPreset::open_radvlad);
  const auto names = matrix_metric_names(protocol);
  EXPECT_NE(std::find(names.begin(), names.end(), "recall_at_1_all_queries"), names.end());
  EXPECT_NE(std::find(names.begin(), names.end(), "recall_at_5_all_queries"), names.end());
  const auto results = four_queries(protocol);
  const Metrics m = compute_metrics(results, {}, {1, 3});
  expect_near(matrix_metric_value(m, "recall_at_1_all_queries"), 0.25);
  expect_near(matrix_metric_value(m, "recall_at_3_all_queries"), 0.5);
  expect_near(matrix_metric_value(m, "recall_at_3"), 1.0);
  expect_near(matrix_metric_value(m, "recall_at_1_with_positive"), 0.5);
  EXPECT_THROW(matrix_metric_value(m, "recall_at_1_everything"), std::logic_error);
}

}  // namespace
}  // namespace radarpr
