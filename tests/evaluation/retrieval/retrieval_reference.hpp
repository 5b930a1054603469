#pragma once

// The definition retrieval strategies are checked against: distance() to every eligible frame,
// nearest first, ties by smaller index.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <random>
#include <vector>

#include "evaluation/retrieval/retrieval.hpp"
#include "tests/evaluation/fake_descriptors.hpp"

namespace radarpr::testing {

// `count` vectors of `dimension` floats drawn uniformly from [low, high), the same for a seed.
inline std::vector<DescriptorValue> uniform_values(std::size_t count, std::size_t dimension,
                                                   unsigned seed, float low = 0.0f,
                                                   float high = 1.0f) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> element(low, high);
  std::vector<DescriptorValue> values;
  for (std::size_t i = 0; i < count; ++i) {
    std::vector<float> v(dimension);
    for (float& x : v) x = element(rng);
    values.push_back(vector_value(std::move(v)));
  }
  return values;
}

// Single session: query q may match frames at least `exclude` older (its prefix ends there).
inline std::vector<std::size_t> growing_prefixes(std::size_t count, std::size_t exclude) {
  std::vector<std::size_t> ends(count);
  for (std::size_t q = 0; q < count; ++q) ends[q] = q + 1 >= exclude ? q + 1 - exclude : 0;
  return ends;
}

inline std::vector<std::vector<Neighbour>> brute_force(const Descriptor& descriptor,
                                                       const std::vector<DescriptorValue>& database,
                                                       const std::vector<DescriptorValue>& queries,
                                                       const std::vector<std::size_t>& ends,
                                                       std::size_t k) {
  std::vector<std::vector<Neighbour>> results(queries.size());
  for (std::size_t q = 0; q < queries.size(); ++q) {
    for (std::size_t j = 0; j < ends[q]; ++j) {
      results[q].push_back({j, descriptor.distance(queries[q], database[j])});
    }
    // Stable: equal distances keep increasing index order.
    std::stable_sort(
        results[q].begin(), results[q].end(),
        [](const Neighbour& a, const Neighbour& b) { return a.distance < b.distance; });
    results[q].resize(std::min(k, results[q].size()));
  }
  return results;
}

inline void expect_same(const std::vector<std::vector<Neighbour>>& actual,
                        const std::vector<std::vector<Neighbour>>& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t q = 0; q < expected.size(); ++q) {
    ASSERT_EQ(actual[q].size(), expected[q].size()) << "query " << q;
    for (std::size_t r = 0; r < expected[q].size(); ++r) {
      ASSERT_EQ(actual[q][r].index, expected[q][r].index) << "query " << q << " rank " << r;
      ASSERT_EQ(actual[q][r].distance, expected[q][r].distance) << "query " << q << " rank " << r;
    }
  }
}

}  // namespace radarpr::testing
