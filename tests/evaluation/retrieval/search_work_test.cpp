// Where the exhaustive strategies spend their work: RaPlace's spectra once per value for a whole
// search, and the blocked L2 search's float products checked exactly even where they cancel.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "descriptors/descriptor_registry.hpp"
#include "descriptors/raplace/circular_correlation.hpp"
#include "evaluation/retrieval/retrieval.hpp"
#include "tests/evaluation/fake_descriptors.hpp"
#include "tests/evaluation/retrieval/retrieval_reference.hpp"

namespace radarpr {
namespace {

using testing::brute_force;
using testing::EuclideanFake;
using testing::expect_same;

std::vector<DescriptorValue> random_values(std::size_t count, int rows, int cols, unsigned seed,
                                           float offset = 0.0f) {
  std::mt19937 generator(seed);
  std::normal_distribution<float> element;
  std::vector<DescriptorValue> values;
  for (std::size_t i = 0; i < count; ++i) {
    std::vector<float> v(static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols));
    for (float& x : v) x = offset + element(generator);
    values.push_back({rows, cols, std::move(v)});
  }
  return values;
}

// Other threads compute the pairs; the spectra, counted for the whole process, are computed
// once per value: 60 + 40, not 60 x 40.
TEST(SearchWork, RaplaceComputesEachSpectrumOncePerSearch) {
  const DescriptorInstance instance = DescriptorRegistry::global().create_from_id("raplace");
  const DescriptorShape shape = instance.descriptor->shape({});
  const auto database = random_values(60, shape.rows, shape.cols, 3);
  const auto queries = random_values(40, shape.rows, shape.cols, 4);
  const raplace::CorrelationWork before = raplace::correlation_work();
  const auto found = retrieve_nearest(*instance.descriptor, database, queries,
                                      std::vector<std::size_t>(queries.size(), database.size()), 5);
  EXPECT_EQ(raplace::correlation_work().spectra - before.spectra, 100u);
  ASSERT_EQ(found.size(), queries.size());
  EXPECT_EQ(found[0].size(), 5u);
}

// The screened search (float correlations, then exact distances near the top) returns exactly
// what computing every distance returns: with near-ties (copies and whole-column shifts of
// earlier values, where only rounding separates the distances), an all-zero value and query, for
// the paper's theta shift, the public code's rho shift and RaPlace-DS's odd number of columns,
// single and multi session, more database values than one screening block.
TEST(SearchWork, RaplaceScreenedSearchEqualsEveryDistance) {
  for (const char* id :
       {"raplace", "raplace:parity=official", "raplace:sinogram_cols=7,sinogram_rows=16"}) {
    const DescriptorInstance instance = DescriptorRegistry::global().create_from_id(id);
    const Descriptor& descriptor = *instance.descriptor;
    const DescriptorShape shape = descriptor.shape({});
    auto database = random_values(300, shape.rows, shape.cols, 8);
    auto queries = random_values(70, shape.rows, shape.cols, 9);
    for (std::size_t i = 0; i < 40; ++i) {
      // Value 260 + i: a copy of value i shifted by one column (theta), or unshifted.
      DescriptorValue copy = database[i];
      if (i % 2 == 1) {
        for (int r = 0; r < shape.rows; ++r) {
          for (int c = 0; c < shape.cols; ++c) {
            copy.values[static_cast<std::size_t>(r * shape.cols + c)] =
                database[i].values[static_cast<std::size_t>(r * shape.cols + (c + 1) % shape.cols)];
          }
        }
      }
      database[260 + i] = copy;
      if (i < 20) queries[i] = copy;
    }
    std::fill(database[7].values.begin(), database[7].values.end(), 0.0f);
    std::fill(queries[30].values.begin(), queries[30].values.end(), 0.0f);
    const std::vector<std::size_t> all(queries.size(), database.size());
    expect_same(retrieve_nearest(descriptor, database, queries, all, 4),
                brute_force(descriptor, database, queries, all, 4));
    const std::vector<std::size_t> prefixes = testing::growing_prefixes(database.size(), 5);
    expect_same(retrieve_nearest(descriptor, database, database, prefixes, 3),
                brute_force(descriptor, database, database, prefixes, 3));
  }
}

// A large common offset makes |q|^2 + |d|^2 - 2 q.d cancel almost entirely in float: the band
// then holds most values and the exact distance decides. Long values (several 256-element
// float sums per dot product), single session and multi session.
TEST(SearchWork, BlockedL2StaysExactWhereTheExpansionCancels) {
  const EuclideanFake descriptor(RetrievalMethod::exhaustive_l2);
  const auto database = random_values(700, 1, 1000, 5, 300.0f);
  const auto queries = random_values(300, 1, 1000, 6, 300.0f);
  const std::vector<std::size_t> all(queries.size(), database.size());
  expect_same(retrieve_nearest(descriptor, database, queries, all, 3),
              brute_force(descriptor, database, queries, all, 3));
  std::vector<std::size_t> prefixes(database.size());
  for (std::size_t q = 0; q < prefixes.size(); ++q) prefixes[q] = q >= 20 ? q - 20 : 0;
  expect_same(retrieve_nearest(descriptor, database, database, prefixes, 2),
              brute_force(descriptor, database, database, prefixes, 2));
}

}  // namespace
}  // namespace radarpr
