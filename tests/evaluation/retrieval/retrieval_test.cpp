#include "evaluation/retrieval/retrieval.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <stdexcept>
#include <vector>

#include "tests/evaluation/fake_descriptors.hpp"
#include "tests/evaluation/retrieval/retrieval_reference.hpp"

namespace radarpr {
namespace {

using testing::brute_force;
using testing::CosineFake;
using testing::EuclideanFake;
using testing::expect_same;
using testing::growing_prefixes;
using testing::uniform_values;
using testing::vector_value;

TEST(RetrieveNearest, HandExampleOrdersByDistanceThenIndex) {
  // 1-D database 5, 1, 3, 1, 3 and query 2: distances 3, 1, 1, 1, 1.
  const std::vector<DescriptorValue> database = {vector_value({5}), vector_value({1}),
                                                 vector_value({3}), vector_value({1}),
                                                 vector_value({3})};
  const std::vector<DescriptorValue> queries = {vector_value({2})};
  for (const auto method : {RetrievalMethod::kdtree, RetrievalMethod::exhaustive}) {
    const EuclideanFake descriptor(method);
    const auto found = retrieve_nearest(descriptor, database, queries, {5}, 3);
    ASSERT_EQ(found[0].size(), 3u);
    // Four frames tie at 1: the three smallest indices 1, 2, 3, each at distance 1.
    for (std::size_t r = 0; r < 3; ++r) {
      EXPECT_EQ(found[0][r].index, r + 1);
      EXPECT_EQ(found[0][r].distance, 1.0);
    }
    // k = 5 adds index 4 (distance 1) and then index 0 (distance 3).
    const auto all = retrieve_nearest(descriptor, database, queries, {5}, 5);
    ASSERT_EQ(all[0].size(), 5u);
    EXPECT_EQ(all[0][3].index, 4u);
    EXPECT_EQ(all[0][4].index, 0u);
    EXPECT_EQ(all[0][4].distance, 3.0);
  }
}

TEST(RetrieveNearest, KdTreeMatchesBruteForceSingleSessionLowDimension) {
  // 3-D keys: the trees prune well, so the KD-tree path is the one searched.
  const auto values = uniform_values(3000, 3, 1);
  const auto ends = growing_prefixes(values.size(), 20);
  const EuclideanFake descriptor;
  expect_same(retrieve_nearest(descriptor, values, values, ends, 5),
              brute_force(descriptor, values, values, ends, 5));
}

TEST(RetrieveNearest, KdTreeMatchesBruteForceSingleSessionHighDimension) {
  // 48-D uniform keys defeat a KD-tree; whichever way it searches, the result must be exact.
  const auto values = uniform_values(1200, 48, 2);
  const auto ends = growing_prefixes(values.size(), 50);
  const EuclideanFake descriptor;
  expect_same(retrieve_nearest(descriptor, values, values, ends, 10),
              brute_force(descriptor, values, values, ends, 10));
}

TEST(RetrieveNearest, KdTreeMatchesBruteForceWithManyTies) {
  // Keys from {0, 1, 2}^3: 27 distinct points over 2000 frames, so nearly every rank is a tie.
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> level(0, 2);
  std::vector<DescriptorValue> values;
  for (int i = 0; i < 2000; ++i) {
    values.push_back(vector_value({float(level(rng)), float(level(rng)), float(level(rng))}));
  }
  const auto ends = growing_prefixes(values.size(), 10);
  for (const auto method : {RetrievalMethod::kdtree, RetrievalMethod::exhaustive}) {
    const EuclideanFake descriptor(method);
    expect_same(retrieve_nearest(descriptor, values, values, ends, 7),
                brute_force(descriptor, values, values, ends, 7));
  }
}

TEST(RetrieveNearest, KdTreeMatchesBruteForceMultiSession) {
  const auto database = uniform_values(2500, 4, 4);
  const auto queries = uniform_values(300, 4, 5);
  const std::vector<std::size_t> ends(queries.size(), database.size());
  const EuclideanFake descriptor;
  expect_same(retrieve_nearest(descriptor, database, queries, ends, 10),
              brute_force(descriptor, database, queries, ends, 10));
}

TEST(RetrieveNearest, KdTreeMatchesBruteForceForEndsInAnyOrder) {
  const auto database = uniform_values(1500, 5, 6);
  const auto queries = uniform_values(400, 5, 7);
  std::mt19937 rng(8);
  std::uniform_int_distribution<std::size_t> end_of(0, database.size());
  std::vector<std::size_t> ends(queries.size());
  for (std::size_t& end : ends) end = end_of(rng);
  const EuclideanFake descriptor;
  expect_same(retrieve_nearest(descriptor, database, queries, ends, 4),
              brute_force(descriptor, database, queries, ends, 4));
}

TEST(RetrieveNearest, SearchKeysDifferentFromValuesReportTheDescriptorDistance) {
  // Hand example: query (2, 0) against (1, 0), (0, 2), (3, 3).
  // Cosine distances 1 - 1 = 0, 1 - 0 = 1, 1 - 6/(2*sqrt(18)) = 1 - 1/sqrt(2) ~ 0.293:
  // order 0, 2, 1. (Plain L2 on the values would give 1, 2.83, 3.16: order 0, 1, 2.)
  const CosineFake descriptor;
  const std::vector<DescriptorValue> database = {vector_value({1, 0}), vector_value({0, 2}),
                                                 vector_value({3, 3})};
  const std::vector<DescriptorValue> queries = {vector_value({2, 0})};
  const auto found = retrieve_nearest(descriptor, database, queries, {3}, 3);
  ASSERT_EQ(found[0].size(), 3u);
  EXPECT_EQ(found[0][0].index, 0u);
  EXPECT_NEAR(found[0][0].distance, 0.0, 1e-12);
  EXPECT_EQ(found[0][1].index, 2u);
  EXPECT_NEAR(found[0][1].distance, 1.0 - 1.0 / std::sqrt(2.0), 1e-12);
  EXPECT_EQ(found[0][2].index, 1u);
  EXPECT_NEAR(found[0][2].distance, 1.0, 1e-12);
}

TEST(RetrieveNearest, CosineKeysMatchBruteForce) {
  // Values of very different lengths: the keys (unit vectors) differ from the values.
  auto values = uniform_values(2000, 4, 9, -1.0f, 1.0f);
  std::mt19937 rng(10);
  std::uniform_real_distribution<float> scale(0.5f, 20.0f);
  for (DescriptorValue& value : values) {
    const float s = scale(rng);
    for (float& x : value.values) x *= s;
  }
  const auto ends = growing_prefixes(values.size(), 30);
  const CosineFake descriptor;
  expect_same(retrieve_nearest(descriptor, values, values, ends, 5),
              brute_force(descriptor, values, values, ends, 5));
}

TEST(RetrieveNearest, FewerEligibleThanKReturnsAllEligible) {
  const auto database = uniform_values(10, 3, 11);
  const auto queries = uniform_values(2, 3, 12);
  for (const auto method : {RetrievalMethod::kdtree, RetrievalMethod::exhaustive}) {
    const EuclideanFake descriptor(method);
    const auto found = retrieve_nearest(descriptor, database, queries, {3, 10}, 25);
    ASSERT_EQ(found[0].size(), 3u);
    ASSERT_EQ(found[1].size(), 10u);
    expect_same(found, brute_force(descriptor, database, queries, {3, 10}, 25));
  }
}

TEST(RetrieveNearest, NoEligibleFrameGivesNoNeighbour) {
  const auto values = uniform_values(5, 3, 13);
  for (const auto method : {RetrievalMethod::kdtree, RetrievalMethod::exhaustive}) {
    const EuclideanFake descriptor(method);
    const auto found = retrieve_nearest(descriptor, values, values, {0, 0, 0, 0, 0}, 3);
    ASSERT_EQ(found.size(), 5u);
    for (const auto& neighbours : found) EXPECT_TRUE(neighbours.empty());
    // An empty database and k = 0 are no-ops as well.
    const std::vector<DescriptorValue> none;
    const auto against_nothing = retrieve_nearest(descriptor, none, values, {0, 0, 0, 0, 0}, 3);
    for (const auto& neighbours : against_nothing) EXPECT_TRUE(neighbours.empty());
    const auto no_k = retrieve_nearest(descriptor, values, values, {0, 1, 2, 3, 4}, 0);
    for (const auto& neighbours : no_k) EXPECT_TRUE(neighbours.empty());
    EXPECT_TRUE(retrieve_nearest(descriptor, values, none, {}, 3).empty());
  }
}

TEST(RetrieveNearest, RejectsBadInput) {
  const EuclideanFake descriptor;
  const auto values = uniform_values(4, 3, 14);
  // One eligible end per query, none beyond the database.
  EXPECT_THROW(retrieve_nearest(descriptor, values, values, {0, 1}, 1), std::invalid_argument);
  EXPECT_THROW(retrieve_nearest(descriptor, values, values, {0, 1, 2, 5}, 1),
               std::invalid_argument);
  // Search keys of different lengths, within the database or between database and queries.
  auto ragged = values;
  ragged[2] = vector_value({1, 2});
  EXPECT_THROW(retrieve_nearest(descriptor, ragged, ragged, {0, 0, 1, 2}, 1),
               std::invalid_argument);
  const std::vector<DescriptorValue> short_queries = {vector_value({1, 2})};
  EXPECT_THROW(retrieve_nearest(descriptor, values, short_queries, {4}, 1), std::invalid_argument);
  // Keys so large that squared distances overflow float: an error, not a silently dropped query.
  const std::vector<DescriptorValue> huge = {vector_value({1e20f}), vector_value({3e20f})};
  const std::vector<DescriptorValue> huge_query = {vector_value({-1e20f})};
  EXPECT_THROW(retrieve_nearest(descriptor, huge, huge_query, {2}, 1), std::invalid_argument);
}

}  // namespace
}  // namespace radarpr
