#include "evaluation/descriptor_evaluation.hpp"

#include <cstdint>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "fake_descriptors.hpp"

namespace radarpr {
namespace {

using testing::EuclideanFake;
using testing::vector_value;

ScanRecord at(double x, double y, std::int64_t index = 0) {
  ScanRecord record;
  record.pose = {x, y, 0.0};
  record.timestamp_ns = index * 250'000'000;
  return record;
}

// Database frames on the x axis: 0 at 0 m, 1 at 100 m, 2 at 50 m, 3 at 5 m; radius 10 m.
RevisitGroundTruth four_frames() {
  return RevisitGroundTruth({{0, 0}, {100, 0}, {50, 0}, {5, 0}}, 10.0);
}

// Query (position)   eligible  neighbours (index, distance)   -> match correct revisit rank
// 0 (0,0)            0         none                           -> skipped
// 1 (1,0)            3         (2, .5), (0, .7)               -> 2  no  yes (0 is 1 m)  2
// 2 (4,0)            4         (3, .3), (1, .4)               -> 3  yes yes             1
// 3 (200,200)        4         (0, .9)                        -> 0  no  no              0
// 4 (2,0)            4         (1, .8)                        -> 1  no  yes (0 is 2 m)  0
// 5 (50,1)           4         (2, .6)                        -> 2  yes yes             1
std::vector<QueryResult> six_queries() {
  const std::vector<std::vector<Neighbour>> neighbours = {
      {}, {{2, 0.5}, {0, 0.7}}, {{3, 0.3}, {1, 0.4}}, {{0, 0.9}}, {{1, 0.8}}, {{2, 0.6}}};
  const std::vector<Position2D> positions = {{0, 0}, {1, 0}, {4, 0}, {200, 200}, {2, 0}, {50, 1}};
  return build_query_results(neighbours, positions, four_frames(), {0, 3, 4, 4, 4, 4});
}

TEST(BuildQueryResults, TopOneCorrectnessRevisitAndFirstCorrectRank) {
  const auto results = six_queries();
  ASSERT_EQ(results.size(), 5u);  // query 0 has no eligible frame
  struct Expected {
    std::size_t query, match;
    double distance;
    bool correct, revisit;
    std::size_t rank;
  };
  const std::vector<Expected> expected = {{1, 2, 0.5, false, true, 2},
                                          {2, 3, 0.3, true, true, 1},
                                          {3, 0, 0.9, false, false, 0},
                                          {4, 1, 0.8, false, true, 0},
                                          {5, 2, 0.6, true, true, 1}};
  for (std::size_t i = 0; i < expected.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(results[i].query, expected[i].query);
    EXPECT_EQ(results[i].match, expected[i].match);
    EXPECT_EQ(results[i].distance, expected[i].distance);
    EXPECT_EQ(results[i].correct, expected[i].correct);
    EXPECT_EQ(results[i].revisit, expected[i].revisit);
    EXPECT_EQ(results[i].first_correct_rank, expected[i].rank);
  }
}

// At threshold 0.5: queries 1 (d .5) and 2 (d .3) are accepted; 3, 4, 5 rejected.
TEST(BuildMatchingGraph, LabelsFollowTheRule) {
  const auto results = six_queries();
  auto labels = [&](LabelRule rule) {
    std::vector<std::pair<std::size_t, GraphLabel>> edges;
    for (const auto& edge : build_matching_graph(results, 0.5, rule)) {
      edges.emplace_back(edge.query, edge.label);
    }
    return edges;
  };
  // standard: 1 accepted wrong FP, 2 accepted correct TP, 3 rejected non-revisit (TN, not drawn),
  // 4 rejected revisit FN, 5 rejected revisit FN.
  EXPECT_EQ(
      labels(LabelRule::standard),
      (std::vector<std::pair<std::size_t, GraphLabel>>{
          {1, GraphLabel::fp}, {2, GraphLabel::tp}, {4, GraphLabel::fn}, {5, GraphLabel::fn}}));
  // retrieved_pair: a rejected query is FN only when its retrieved frame is correct: 5, not 4.
  EXPECT_EQ(labels(LabelRule::retrieved_pair),
            (std::vector<std::pair<std::size_t, GraphLabel>>{
                {1, GraphLabel::fp}, {2, GraphLabel::tp}, {5, GraphLabel::fn}}));
}

// Single session of six frames, 1-D values, exclude 2 frames, radius 10 m:
// frame  x    value  eligible  top-1 (distance)  correct  revisit
// 0      0    0      -         skipped
// 1      50   10     -         skipped
// 2      100  20     {0}       0 (20)            no       no
// 3      1    0.5    {0,1}     0 (0.5)           yes      yes
// 4      51   10.4   {0,1,2}   1 (0.4)           yes      yes
// 5      200  30     {0..3}    2 (10)            no       no
// Standard labels over the exact sweep 0.4, 0.5, 10, 20:
//   0.4: TP 1 FN 1 TN 2 -> TPR .5, FPR 0;  0.5: TP 2 TN 2 -> TPR 1, FPR 0, F1 1
//   10:  TP 2 FP 1 TN 1 -> FPR .5;         20:  TP 2 FP 2    -> FPR 1
// ROC (0,0) (0,.5) (0,1) (.5,1) (1,1) (1,1): AUC = .5*1 + .5*1 = 1.
TEST(EvaluateDescriptor, SingleSessionEndToEndByHand) {
  const std::vector<ScanRecord> records = {at(0, 0, 0), at(50, 0, 1), at(100, 0, 2),
                                           at(1, 0, 3), at(51, 0, 4), at(200, 0, 5)};
  const std::vector<DescriptorValue> values = {vector_value({0}),     vector_value({10}),
                                               vector_value({20}),    vector_value({0.5}),
                                               vector_value({10.4f}), vector_value({30})};
  Protocol protocol;
  protocol.exclude_recent_frames = 2;
  protocol.revisit_radius_m = 10.0;
  protocol.recall_at_k = {1};
  const EuclideanFake descriptor;
  const auto evaluation =
      evaluate_descriptor(descriptor, values, records, nullptr, nullptr, protocol);

  ASSERT_EQ(evaluation.results.size(), 4u);
  EXPECT_EQ(evaluation.results[2].match, 1u);
  const Metrics& m = evaluation.metrics;
  EXPECT_EQ(m.queries, 4u);
  EXPECT_EQ(m.revisits, 2u);
  EXPECT_EQ(m.correct_top1, 2u);
  ASSERT_TRUE(m.roc_auc && m.f1_max && m.f1_max_threshold && m.recall_at_1);
  EXPECT_NEAR(*m.roc_auc, 1.0, 1e-12);
  EXPECT_NEAR(*m.f1_max, 1.0, 1e-12);
  EXPECT_NEAR(*m.f1_max_threshold, 0.5, 1e-6);
  EXPECT_NEAR(*m.recall_at_1, 1.0, 1e-12);
  ASSERT_EQ(evaluation.matching_graph.size(), 2u);  // frames 3 and 4, both TP
  EXPECT_EQ(evaluation.matching_graph[0].query, 3u);
  EXPECT_EQ(evaluation.matching_graph[1].label, GraphLabel::tp);
}

// Multi session; Recall@K must search the largest K asked for, whatever the list's order.
// Query at x 52 with value 16 against database values 20 (x 300), 10 (x 50), 0 (x 0):
// nearest 20 (d 4, wrong), then 10 (d 6, within 2 m): first correct rank 2.
TEST(EvaluateDescriptor, MultiSessionRecallAtKUsesTheLargestK) {
  const std::vector<ScanRecord> database_records = {at(300, 0), at(50, 0), at(0, 0)};
  const std::vector<DescriptorValue> database = {vector_value({20}), vector_value({10}),
                                                 vector_value({0})};
  const std::vector<ScanRecord> query_records = {at(52, 0)};
  const std::vector<DescriptorValue> queries = {vector_value({16})};
  Protocol protocol;
  protocol.recall_at_k = {2, 1};  // deliberately unsorted
  const EuclideanFake descriptor;
  const auto evaluation = evaluate_descriptor(descriptor, queries, query_records, &database,
                                              &database_records, protocol);
  ASSERT_EQ(evaluation.results.size(), 1u);
  EXPECT_EQ(evaluation.results[0].first_correct_rank, 2u);
  EXPECT_EQ(evaluation.metrics.recall_at_k.at(1), 0.0);
  EXPECT_EQ(evaluation.metrics.recall_at_k.at(2), 1.0);
}

// The same query with a key pre-search that re-ranks 2 candidates: Recall@1 and Recall@2 as
// above (keys = values, so the 2 key-nearest are values 20 and 10), Recall@3 undefined because
// the search never looks at a third frame.
TEST(EvaluateDescriptor, RecallBeyondTheRerankedCandidatesIsUndefined) {
  const std::vector<ScanRecord> database_records = {at(300, 0), at(50, 0), at(0, 0)};
  const std::vector<DescriptorValue> database = {vector_value({20}), vector_value({10}),
                                                 vector_value({0})};
  const std::vector<ScanRecord> query_records = {at(52, 0)};
  const std::vector<DescriptorValue> queries = {vector_value({16})};
  Protocol protocol;
  protocol.recall_at_k = {1, 2, 3};
  const testing::KeyThenRerankFake descriptor(2);
  const auto evaluation = evaluate_descriptor(descriptor, queries, query_records, &database,
                                              &database_records, protocol);
  EXPECT_EQ(evaluation.metrics.recall_at_k.at(1), 0.0);
  EXPECT_EQ(evaluation.metrics.recall_at_k.at(2), 1.0);
  EXPECT_FALSE(evaluation.metrics.recall_at_k.at(3).has_value());
}

// Values of a drive on a line, coarsely rounded so that many values tie (the tie rule must
// survive the merge of blocks), in 3 dimensions.
std::vector<DescriptorValue> drive_values(std::size_t count, std::uint32_t seed) {
  std::vector<DescriptorValue> values;
  std::uint32_t state = seed;
  auto next = [&state] {
    state = state * 1664525u + 1013904223u;
    return static_cast<float>((state >> 8) % 7) * 0.5f;
  };
  for (std::size_t i = 0; i < count; ++i) {
    values.push_back(vector_value({static_cast<float>(i % 11), next(), next()}));
  }
  return values;
}

std::vector<ScanRecord> drive_records(std::size_t count, double offset) {
  std::vector<ScanRecord> records;
  for (std::size_t i = 0; i < count; ++i) {
    records.push_back(
        at(static_cast<double>(i % 23) * 4.0 + offset, 0.0, static_cast<std::int64_t>(i)));
  }
  return records;
}

ValueBlocks blocks_of(const std::vector<DescriptorValue>& values, std::size_t block,
                      std::size_t* largest_read) {
  return {values.size(), block,
          [&values, largest_read](std::size_t begin, std::size_t end,
                                  std::vector<DescriptorValue>& into) {
            *largest_read = std::max(*largest_read, end - begin);
            into.assign(values.begin() + static_cast<std::ptrdiff_t>(begin),
                        values.begin() + static_cast<std::ptrdiff_t>(end));
          }};
}

// Read a few values at a time (as an evaluate unit reads a memory-mapped cache entry), every
// retrieval method gives the result of the search over the whole values, ties included, and
// reads no more than a block at a time (but key_then_rerank's database, read whole).
TEST(EvaluateDescriptorInBlocks, EqualsTheWholeSearchForEveryRetrievalMethod) {
  const auto database = drive_values(61, 3);
  const auto queries = drive_values(47, 11);
  const auto database_records = drive_records(database.size(), 0.0);
  const auto query_records = drive_records(queries.size(), 1.5);
  Protocol protocol;
  protocol.recall_at_k = {1, 3, 5};
  std::vector<std::pair<std::string, std::unique_ptr<Descriptor>>> descriptors;
  descriptors.emplace_back("kdtree", std::make_unique<EuclideanFake>(RetrievalMethod::kdtree));
  descriptors.emplace_back("exhaustive",
                           std::make_unique<EuclideanFake>(RetrievalMethod::exhaustive));
  descriptors.emplace_back("exhaustive_l2",
                           std::make_unique<EuclideanFake>(RetrievalMethod::exhaustive_l2));
  descriptors.emplace_back("prepared", std::make_unique<testing::PreparedSumFake>());
  descriptors.emplace_back("key_then_rerank", std::make_unique<testing::KeyThenRerankFake>(4));
  for (const auto& [name, descriptor] : descriptors) {
    const auto whole = evaluate_descriptor(*descriptor, queries, query_records, &database,
                                           &database_records, protocol);
    for (const std::size_t block :
         {std::size_t{1}, std::size_t{5}, std::size_t{16}, std::size_t{1000}}) {
      std::size_t largest_query_read = 0;
      std::size_t largest_database_read = 0;
      const auto blocked = evaluate_descriptor_in_blocks(
          *descriptor, blocks_of(queries, block, &largest_query_read), query_records,
          blocks_of(database, block, &largest_database_read), database_records, protocol);
      const std::string where = name + ", blocks of " + std::to_string(block);
      EXPECT_LE(largest_query_read, block) << where;
      if (name != "key_then_rerank") {
        EXPECT_LE(largest_database_read, block) << where;
      }
      ASSERT_EQ(blocked.results.size(), whole.results.size()) << where;
      for (std::size_t i = 0; i < whole.results.size(); ++i) {
        EXPECT_EQ(blocked.results[i].match, whole.results[i].match) << where << ", query " << i;
        EXPECT_EQ(blocked.results[i].distance, whole.results[i].distance) << where;
        EXPECT_EQ(blocked.results[i].first_correct_rank, whole.results[i].first_correct_rank)
            << where << ", query " << i;
      }
      EXPECT_EQ(blocked.metrics.recall_at_k, whole.metrics.recall_at_k) << where;
      EXPECT_EQ(blocked.metrics.roc_auc, whole.metrics.roc_auc) << where;
      EXPECT_EQ(blocked.metrics.f1_max, whole.metrics.f1_max) << where;
      EXPECT_EQ(blocked.matching_graph.size(), whole.matching_graph.size()) << where;
    }
  }
}

}  // namespace
}  // namespace radarpr
