// The retrieval strategies other than the KD-tree: key pre-search + re-rank, exhaustive search
// through prepared distances, and blocked L2 matrix products (retrieval.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "evaluation/parallel.hpp"
#include "evaluation/retrieval/blocked_l2_search.hpp"
#include "evaluation/retrieval/retrieval.hpp"
#include "tests/evaluation/fake_descriptors.hpp"
#include "tests/evaluation/retrieval/retrieval_reference.hpp"

namespace radarpr {
namespace {

using testing::brute_force;
using testing::EuclideanFake;
using testing::expect_same;
using testing::KeyThenRerankFake;
using testing::PreparedSumFake;
using testing::vector_value;

std::vector<DescriptorValue> random_values(std::size_t count, std::size_t dimension,
                                           unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<float> element(0.0f, 1.0f);
  std::vector<DescriptorValue> values;
  for (std::size_t i = 0; i < count; ++i) {
    std::vector<float> v(dimension);
    for (float& x : v) x = element(rng);
    values.push_back(vector_value(std::move(v)));
  }
  return values;
}

std::vector<std::size_t> single_session_ends(std::size_t count, std::size_t exclude) {
  std::vector<std::size_t> ends(count);
  for (std::size_t q = 0; q < count; ++q) ends[q] = q >= exclude ? q - exclude : 0;
  return ends;
}

// Keys (first elements) 0, 1, 2, 10 and query key 0.4: the two nearest keys are values 0 and 1.
// Whole-value distances from the query (0.4, 5): value 0 (0, 0) -> sqrt(0.16 + 25) = 5.016,
// value 1 (1, 5) -> 0.6, value 2 (2, 5) -> 1.6, value 3 (10, 5) -> 9.6.
// With two candidates the re-ranked list is [1, 0]: value 2, nearer than value 0, is never seen.
TEST(KeyThenRerank, ReRanksTheNearestKeysOnly) {
  const KeyThenRerankFake descriptor(2);
  const std::vector<DescriptorValue> database = {vector_value({0, 0}), vector_value({1, 5}),
                                                 vector_value({2, 5}), vector_value({10, 5})};
  const std::vector<DescriptorValue> queries = {vector_value({0.4f, 5})};
  const auto result = retrieve_nearest(descriptor, database, queries, {4}, 10);
  ASSERT_EQ(result[0].size(), 2u);
  EXPECT_EQ(result[0][0].index, 1u);
  EXPECT_NEAR(result[0][0].distance, 0.6, 1e-6);
  EXPECT_EQ(result[0][1].index, 0u);
  EXPECT_NEAR(result[0][1].distance, std::sqrt(0.16 + 25.0), 1e-6);
  // With three candidates value 2 enters at rank 2.
  const auto wider = retrieve_nearest(KeyThenRerankFake(3), database, queries, {4}, 10);
  ASSERT_EQ(wider[0].size(), 3u);
  EXPECT_EQ(wider[0][1].index, 2u);
}

// The same as searching the `candidates` nearest keys by brute force (ties by smaller index)
// and ranking them by distance; also over thousands of frames, where the KD-trees are used.
TEST(KeyThenRerank, MatchesBruteForceOfKeysThenDistances) {
  const std::size_t candidates = 5;
  const KeyThenRerankFake descriptor(candidates);
  auto values = random_values(3000, 6, 11);
  // Repeated keys make ties at the candidate boundary.
  for (std::size_t i = 0; i < values.size(); i += 7) values[i].values[0] = 0.5f;
  const auto ends = single_session_ends(values.size(), 50);
  const auto result = retrieve_nearest(descriptor, values, values, ends, 3);
  for (std::size_t q = 0; q < values.size(); q += 37) {
    std::vector<std::pair<float, std::size_t>> by_key;
    for (std::size_t j = 0; j < ends[q]; ++j) {
      const float difference = values[q].values[0] - values[j].values[0];
      by_key.emplace_back(difference * difference, j);
    }
    std::sort(by_key.begin(), by_key.end());
    by_key.resize(std::min(candidates, by_key.size()));
    std::vector<Neighbour> expected;
    for (const auto& [key_distance, j] : by_key) {
      expected.push_back({j, descriptor.distance(values[q], values[j])});
    }
    std::sort(expected.begin(), expected.end(), [](const Neighbour& a, const Neighbour& b) {
      return a.distance < b.distance || (a.distance == b.distance && a.index < b.index);
    });
    expected.resize(std::min<std::size_t>(3, expected.size()));
    expect_same({result[q]}, {expected});
  }
}

TEST(KeyThenRerank, RejectsZeroCandidates) {
  const std::vector<DescriptorValue> values = {vector_value({0, 0})};
  EXPECT_THROW(retrieve_nearest(KeyThenRerankFake(0), values, values, {1}, 1),
               std::invalid_argument);
}

TEST(ExhaustiveRetrieval, PreparesOncePerSearchAndMatchesBruteForce) {
  const PreparedSumFake descriptor;
  const auto database = random_values(300, 4, 3);
  const auto queries = random_values(40, 4, 4);
  const std::vector<std::size_t> ends(queries.size(), database.size());
  const auto result = retrieve_nearest(descriptor, database, queries, ends, 5);
  EXPECT_EQ(descriptor.prepare_calls, 1);
  expect_same(result, brute_force(descriptor, database, queries, ends, 5));
}

// More queries and database values than one block of each (256 x 512), single and multi session.
TEST(ExhaustiveL2, MatchesBruteForceAcrossBlocks) {
  const EuclideanFake descriptor(RetrievalMethod::exhaustive_l2);
  const auto values = random_values(1100, 300, 5);
  const auto ends = single_session_ends(values.size(), 50);
  expect_same(retrieve_nearest(descriptor, values, values, ends, 10),
              brute_force(descriptor, values, values, ends, 10));

  const auto queries = random_values(300, 300, 6);
  const std::vector<std::size_t> all(queries.size(), values.size());
  expect_same(retrieve_nearest(descriptor, values, queries, all, 3),
              brute_force(descriptor, values, queries, all, 3));
}

// Queries sampled across a single session, as a benchmark times them: one block of queries whose
// eligible prefixes grow from empty to most of the database (the products skip, per database
// block, the queries with nothing in it), and the same queries out of order (no skipping).
TEST(ExhaustiveL2, MatchesBruteForceForQueriesSpreadOverASession) {
  const EuclideanFake descriptor(RetrievalMethod::exhaustive_l2);
  const auto values = random_values(2100, 64, 9);
  std::vector<DescriptorValue> queries;
  std::vector<std::size_t> ends;
  for (std::size_t q = 0; q < values.size(); q += 37) {
    queries.push_back(values[q]);
    ends.push_back(q >= 50 ? q - 50 : 0);
  }
  expect_same(retrieve_nearest(descriptor, values, queries, ends, 2),
              brute_force(descriptor, values, queries, ends, 2));
  std::reverse(queries.begin(), queries.end());
  std::reverse(ends.begin(), ends.end());
  expect_same(retrieve_nearest(descriptor, values, queries, ends, 2),
              brute_force(descriptor, values, queries, ends, 2));
}

// The threads share the tiles (a query block against a database block) of as many query blocks
// as there are threads, candidates merged under each query block's lock: the same result
// whatever the thread count, single and multi session.
TEST(ExhaustiveL2, SameResultWhateverTheThreadCount) {
  const EuclideanFake descriptor(RetrievalMethod::exhaustive_l2);
  const auto values = random_values(1300, 40, 11);
  const auto single = single_session_ends(values.size(), 50);
  const auto queries = random_values(90, 40, 12);
  const std::vector<std::size_t> all(queries.size(), values.size());
  const auto expected_single = brute_force(descriptor, values, values, single, 3);
  const auto expected_multi = brute_force(descriptor, values, queries, all, 3);
  for (const int threads : {1, 2, 3, 8}) {
    set_default_thread_count(threads);
    expect_same(retrieve_nearest(descriptor, values, values, single, 3), expected_single);
    expect_same(retrieve_nearest(descriptor, values, queries, all, 3), expected_multi);
  }
  set_default_thread_count(0);
}

// Values read in place from one contiguous matrix (as from a memory map) give the in-memory
// search's result, single and multi session, and every database value read is released again.
TEST(ExhaustiveL2, ContiguousRowsMatchTheInMemorySearch) {
  const EuclideanFake descriptor(RetrievalMethod::exhaustive_l2);
  const std::size_t dimension = 1500;  // one full 1024-float slice and a partial one
  const auto values = random_values(1300, dimension, 21);
  std::vector<float> matrix;
  for (const DescriptorValue& value : values) {
    matrix.insert(matrix.end(), value.values.begin(), value.values.end());
  }
  std::vector<int> released(values.size(), 0);
  const L2Rows rows(matrix.data(), values.size(), values.front().rows, values.front().cols,
                    [&](std::size_t begin, std::size_t end) {
                      for (std::size_t i = begin; i < end; ++i) ++released[i];
                    });
  const auto single = single_session_ends(values.size(), 50);
  for (const int threads : {1, 2}) {
    set_default_thread_count(threads);
    expect_same(retrieval_detail::retrieve_exhaustive_l2(descriptor, rows, rows, single, 3),
                retrieve_nearest(descriptor, values, values, single, 3));
  }
  set_default_thread_count(0);
  EXPECT_TRUE(std::all_of(released.begin(), released.end(), [](int n) { return n > 0; }));

  const auto queries = random_values(40, dimension, 22);
  std::vector<float> query_matrix;
  for (const DescriptorValue& value : queries) {
    query_matrix.insert(query_matrix.end(), value.values.begin(), value.values.end());
  }
  const L2Rows query_rows(query_matrix.data(), queries.size(), queries.front().rows,
                          queries.front().cols);
  const std::vector<std::size_t> all(queries.size(), values.size());
  expect_same(retrieval_detail::retrieve_exhaustive_l2(descriptor, rows, query_rows, all, 2),
              brute_force(descriptor, values, queries, all, 2));
}

// Exact duplicates and near-duplicates that float matrix products cannot tell apart: the exact
// distance decides, ties by the smaller index.
TEST(ExhaustiveL2, ResolvesNearTiesExactly) {
  const EuclideanFake descriptor(RetrievalMethod::exhaustive_l2);
  auto database = random_values(600, 2000, 7);
  for (std::size_t i = 1; i < database.size(); i += 3) database[i] = database[i - 1];
  for (std::size_t i = 2; i < database.size(); i += 3) {
    database[i] = database[i - 2];
    database[i].values[17] += 1e-4f;
  }
  const auto queries = random_values(50, 2000, 8);
  std::vector<DescriptorValue> near_queries;
  for (std::size_t i = 0; i < 50; ++i) near_queries.push_back(database[i * 11]);
  const std::vector<std::size_t> ends(50, database.size());
  expect_same(retrieve_nearest(descriptor, database, queries, ends, 4),
              brute_force(descriptor, database, queries, ends, 4));
  expect_same(retrieve_nearest(descriptor, database, near_queries, ends, 4),
              brute_force(descriptor, database, near_queries, ends, 4));
}

// A value whose squared norm cannot enter float distances is refused, naming the first such
// value, database values before queries, also when no query may see it.
TEST(ExhaustiveL2, RefusesUnusableValuesNamingTheFirst) {
  const EuclideanFake descriptor(RetrievalMethod::exhaustive_l2);
  const auto database = random_values(1200, 40, 31);
  const auto queries = random_values(30, 40, 32);
  const std::vector<std::size_t> all(queries.size(), database.size());
  auto error = [&](const std::vector<DescriptorValue>& d, const std::vector<DescriptorValue>& q,
                   const std::vector<std::size_t>& ends) -> std::string {
    try {
      retrieval_detail::retrieve_exhaustive_l2(descriptor, d, q, ends, 2);
    } catch (const std::invalid_argument& refused) {
      return refused.what();
    }
    return "no error";
  };
  const std::string database_nan =
      "retrieve_nearest: database value 700 has a NaN or infinite "
      "element";
  auto bad = database;
  bad[1100].values[5] = 1e30f;  // squared norm 1e60
  bad[700].values[3] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(error(bad, queries, all), database_nan);
  EXPECT_EQ(error(bad, queries, std::vector<std::size_t>(queries.size(), 600)), database_nan);
  auto bad_queries = queries;
  bad_queries[20].values[0] = std::numeric_limits<float>::infinity();
  EXPECT_EQ(error(database, bad_queries, all),
            "retrieve_nearest: query value 20 has a NaN or infinite element");
  EXPECT_EQ(error(bad, bad_queries, all), database_nan);
  bad[700] = database[700];
  EXPECT_EQ(error(bad, queries, all)
                .rfind("retrieve_nearest: database value 1100 has a squared "
                       "norm of 1",
                       0),
            0u);
  EXPECT_EQ(error(database, queries, all), "no error");
}

// Refused before any distance() runs: this fake's distance(), like a plugin's may, reads the
// second value at the first one's length (AddressSanitizer reported the read past its end).
TEST(ExhaustiveL2, RejectsValuesOfDifferentLengths) {
  const EuclideanFake descriptor(RetrievalMethod::exhaustive_l2);
  const std::vector<DescriptorValue> database = {vector_value({0, 0}), vector_value({1})};
  const std::vector<DescriptorValue> queries = {vector_value({0, 0})};
  EXPECT_THROW(retrieve_nearest(descriptor, database, queries, {2}, 1), std::invalid_argument);
}

}  // namespace
}  // namespace radarpr
