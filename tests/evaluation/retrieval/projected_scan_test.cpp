// The projected key scan (the KD-tree strategy's search where trees would not prune): exact
// against brute force whatever the key length, the ties, the offsets and the prefixes; and the
// planner's choice between it and the trees.
#include "evaluation/retrieval/projected_key_scan.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "evaluation/retrieval/retrieval.hpp"
#include "tests/evaluation/fake_descriptors.hpp"
#include "tests/evaluation/retrieval/retrieval_reference.hpp"

namespace radarpr {
namespace {

using retrieval_detail::CandidateSet;
using retrieval_detail::ProjectedKeyScan;
using testing::brute_force;
using testing::EuclideanFake;
using testing::expect_same;
using testing::growing_prefixes;
using testing::uniform_values;
using testing::vector_value;

// A drive in miniature: a slowly wandering point in `dimension` axes, with noise; revisits come
// from laps over the same path. Like real descriptors, neighbours are far closer than typical
// pairs but the noise spreads over every axis.
std::vector<DescriptorValue> drive_values(std::size_t count, std::size_t dimension, unsigned seed) {
  std::mt19937 path(1);  // the same path for every seed: only the noise differs
  std::mt19937 rng(seed);
  std::normal_distribution<float> noise(0.0f, 0.05f);
  std::vector<float> frequency(dimension);
  std::uniform_real_distribution<float> uniform(0.5f, 3.0f);
  for (float& f : frequency) f = uniform(path);
  std::vector<DescriptorValue> values;
  for (std::size_t i = 0; i < count; ++i) {
    const float t = static_cast<float>(i % 500) / 500.0f * 6.2831853f;  // a lap every 500
    std::vector<float> v(dimension);
    for (std::size_t d = 0; d < dimension; ++d)
      v[d] = std::sin(frequency[d] * t + static_cast<float>(d)) + noise(rng);
    values.push_back(vector_value(std::move(v)));
  }
  return values;
}

// The scan on its own: candidates re-ranked by the exact distance must give brute force's
// top-k. Runs in this thread, so the diagnostics count this scan only.
std::vector<std::vector<Neighbour>> scan_then_rank(const std::vector<DescriptorValue>& database,
                                                   const std::vector<DescriptorValue>& queries,
                                                   const std::vector<std::size_t>& ends,
                                                   std::size_t k) {
  const std::size_t dimension = database.front().values.size();
  std::vector<float> keys;
  for (const auto& value : database)
    keys.insert(keys.end(), value.values.begin(), value.values.end());
  std::vector<float> query_keys;
  for (const auto& value : queries) {
    query_keys.insert(query_keys.end(), value.values.begin(), value.values.end());
  }
  const ProjectedKeyScan scan(keys.data(), database.size(), dimension);
  const std::vector<float> projected = scan.project(query_keys.data(), queries.size());
  float scale = scan.max_squared_norm();
  for (std::size_t q = 0; q < queries.size(); ++q) {
    float norm = 0.0f;
    for (std::size_t d = 0; d < dimension; ++d)
      norm += projected[q * dimension + d] * projected[q * dimension + d];
    scale = std::max(scale, norm);
  }
  const float band = std::max(1e-6f * scale, ProjectedKeyScan::projection_error(scale));
  std::vector<CandidateSet> candidates(queries.size(), CandidateSet(k, band));
  scan.collect(projected.data(), ends, candidates);
  const EuclideanFake descriptor;
  std::vector<std::vector<Neighbour>> results(queries.size());
  for (std::size_t q = 0; q < queries.size(); ++q) {
    for (const std::size_t j : candidates[q].indices()) {
      EXPECT_LT(j, ends[q]) << "query " << q;
      results[q].push_back({j, descriptor.distance(queries[q], database[j])});
    }
    std::sort(results[q].begin(), results[q].end(), [](const Neighbour& a, const Neighbour& b) {
      return a.distance < b.distance || (a.distance == b.distance && a.index < b.index);
    });
    results[q].resize(std::min(k, results[q].size()));
  }
  return results;
}

// Key lengths around the bound stages (8 box axes, 10 and 16 leading axes) and beyond the
// rotated limit (128), with single-session prefixes (some empty) and k = 1 and 4; with the
// vector kernels (where the CPU has them) and with the portable ones.
TEST(ProjectedKeyScan, MatchesBruteForceForEveryKeyLength) {
  const EuclideanFake descriptor;
  for (const bool vector_kernels : {true, false}) {
    ProjectedKeyScan::allow_vector_kernels(vector_kernels);
    for (const std::size_t dimension : {1u, 3u, 8u, 9u, 10u, 16u, 17u, 50u, 130u}) {
      const auto values = uniform_values(700, dimension, 10 + static_cast<unsigned>(dimension));
      const auto ends = growing_prefixes(values.size(), 25);
      for (const std::size_t k : {1u, 4u}) {
        SCOPED_TRACE(::testing::Message() << dimension << " axes, k = " << k
                                          << (vector_kernels ? "" : ", portable kernels"));
        expect_same(scan_then_rank(values, values, ends, k),
                    brute_force(descriptor, values, values, ends, k));
      }
    }
  }
  ProjectedKeyScan::allow_vector_kernels(true);
}

TEST(ProjectedKeyScan, MatchesBruteForceOnADriveAndSkipsMostKeys) {
  const auto database = drive_values(6000, 40, 3);
  const auto queries = drive_values(600, 40, 4);
  const std::vector<std::size_t> ends(queries.size(), database.size());
  ProjectedKeyScan::full_distances_in_thread() = 0;
  ProjectedKeyScan::visited_keys_in_thread() = 0;
  expect_same(scan_then_rank(database, queries, ends, 3),
              brute_force(EuclideanFake(), database, queries, ends, 3));
  // Not a timing: the bounds must reject most of the 3.6 million pairs (lanes of 8 queries visit
  // a leaf together, so visited keys count once per 8 queries).
  EXPECT_LT(ProjectedKeyScan::full_distances_in_thread(), queries.size() * database.size() / 10);
  EXPECT_LT(ProjectedKeyScan::visited_keys_in_thread() * 8, queries.size() * database.size());
}

// Exact duplicates (ties broken by the smaller index), near-duplicates closer than float
// resolution of the squared norms, and a large common offset that the centring removes.
TEST(ProjectedKeyScan, ResolvesTiesNearTiesAndOffsetsExactly) {
  const EuclideanFake descriptor;
  auto database = uniform_values(900, 24, 5, 1000.0f, 1001.0f);
  for (std::size_t i = 1; i < database.size(); i += 3) database[i] = database[i - 1];
  for (std::size_t i = 2; i < database.size(); i += 3) {
    database[i] = database[i - 2];
    database[i].values[5] += 1e-4f;
  }
  std::vector<DescriptorValue> queries;
  for (std::size_t i = 0; i < 60; ++i) queries.push_back(database[i * 13]);
  const auto others = uniform_values(60, 24, 6, 1000.0f, 1001.0f);
  queries.insert(queries.end(), others.begin(), others.end());
  std::vector<std::size_t> ends(queries.size(), database.size());
  for (std::size_t q = 0; q < ends.size(); q += 7) ends[q] = q;  // some short prefixes
  for (const bool vector_kernels : {true, false}) {
    ProjectedKeyScan::allow_vector_kernels(vector_kernels);
    for (const std::size_t k : {1u, 2u, 5u}) {
      SCOPED_TRACE(::testing::Message() << "k = " << k << (vector_kernels ? "" : ", portable"));
      expect_same(scan_then_rank(database, queries, ends, k),
                  brute_force(descriptor, database, queries, ends, k));
    }
  }
  ProjectedKeyScan::allow_vector_kernels(true);
}

// Through retrieve_nearest: high-dimensional keys take the scan, keys along a curve the trees;
// both exact.
TEST(ProjectedKeyScan, ThePlannerPicksItWhereTreesWouldVisitMostKeys) {
  const EuclideanFake descriptor;
  const auto noisy = drive_values(4000, 50, 7);
  const auto ends = growing_prefixes(noisy.size(), 50);
  std::size_t built = ProjectedKeyScan::built_in_process();
  expect_same(retrieve_nearest(descriptor, noisy, noisy, ends, 10),
              brute_force(descriptor, noisy, noisy, ends, 10));
  EXPECT_EQ(ProjectedKeyScan::built_in_process(), built + 1);

  // A curve in the plane, sampled densely: trees touch a few keys per query.
  std::vector<DescriptorValue> curve;
  for (std::size_t i = 0; i < 5000; ++i) {
    const float t = static_cast<float>(i) * 0.01f;
    curve.push_back(vector_value({std::cos(t) * (1.0f + 0.001f * t), std::sin(t)}));
  }
  const auto curve_ends = growing_prefixes(curve.size(), 30);
  built = ProjectedKeyScan::built_in_process();
  expect_same(retrieve_nearest(descriptor, curve, curve, curve_ends, 3),
              brute_force(descriptor, curve, curve, curve_ends, 3));
  EXPECT_EQ(ProjectedKeyScan::built_in_process(), built);
}

}  // namespace
}  // namespace radarpr
