#include "evaluation/retrieval/retrieval_declaration.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "evaluation/retrieval/retrieval.hpp"
#include "tests/evaluation/fake_descriptors.hpp"

namespace radarpr {
namespace {

using testing::vector_value;

// A descriptor as a plugin author writes it: normalised histograms compared by the Hellinger
// distance, retrieval left at the interface's default. Hellinger and L2 order histograms
// differently, so a KD-tree over the values would return wrong nearest neighbours.
class HellingerHistogram : public Descriptor {
 public:
  DescriptorValue extract(const PolarImage& /*scan*/) const override {
    throw std::logic_error("HellingerHistogram::extract is not used by these tests");
  }
  double distance(const DescriptorValue& a, const DescriptorValue& b) const override {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.values.size(); ++i) {
      const double difference = std::sqrt(double(a.values[i])) - std::sqrt(double(b.values[i]));
      sum += difference * difference;
    }
    return std::sqrt(0.5 * sum);
  }
  bool rotation_invariant() const override { return true; }
  DescriptorShape shape(const ScanGeometry& /*geometry*/) const override { return {1, 12}; }
};

// The same distance with a wrong declaration: a KD-tree over the raw histograms.
class HellingerClaimingKdTree : public HellingerHistogram {
 public:
  RetrievalMethod retrieval_method() const override { return RetrievalMethod::kdtree; }
};

// The same distance with a right declaration: the square roots' L2 distance is sqrt(2) times the
// Hellinger distance, so a KD-tree over them is exact.
class HellingerWithSquareRootKey : public HellingerClaimingKdTree {
 public:
  std::vector<float> search_key(const DescriptorValue& value) const override {
    std::vector<float> key;
    for (const float v : value.values) key.push_back(std::sqrt(v));
    return key;
  }
};

class HellingerClaimingL2 : public HellingerHistogram {
 public:
  RetrievalMethod retrieval_method() const override { return RetrievalMethod::exhaustive_l2; }
};

// 350 histograms of 12 bins, sparse and uneven like range histograms of radar returns.
std::vector<DescriptorValue> histograms(unsigned seed) {
  std::mt19937 random(seed);
  std::gamma_distribution<float> weight(0.3f, 1.0f);
  std::vector<DescriptorValue> values;
  for (int i = 0; i < 350; ++i) {
    std::vector<float> bins(12);
    float total = 0.0f;
    for (float& bin : bins) total += bin = weight(random);
    for (float& bin : bins) bin /= total;
    values.push_back(vector_value(bins));
  }
  return values;
}

std::size_t nearest_by(const std::vector<DescriptorValue>& database, const DescriptorValue& query,
                       std::size_t skip, const auto& distance) {
  std::size_t best = database.size();
  double best_distance = INFINITY;
  for (std::size_t d = 0; d < database.size(); ++d) {
    if (d == skip) continue;
    const double value = distance(query, database[d]);
    if (value < best_distance) {
      best_distance = value;
      best = d;
    }
  }
  return best;
}

TEST(RetrievalDeclaration, DefaultRetrievalFindsTheNearestByTheDescriptorsOwnDistance) {
  const HellingerHistogram descriptor;
  EXPECT_EQ(descriptor.retrieval_method(), RetrievalMethod::exhaustive);
  const auto values = histograms(17);
  // A second session of 350 histograms queried against the first.
  const std::vector<DescriptorValue> queries = histograms(18);
  const std::vector<DescriptorValue>& database = values;
  const auto found = retrieve_nearest(descriptor, database, queries,
                                      std::vector<std::size_t>(queries.size(), database.size()), 1);
  const auto l2 = [](const DescriptorValue& a, const DescriptorValue& b) {
    return testing::EuclideanFake().distance(a, b);
  };
  const auto hellinger = [&](const DescriptorValue& a, const DescriptorValue& b) {
    return descriptor.distance(a, b);
  };
  std::size_t l2_disagrees = 0;
  for (std::size_t q = 0; q < queries.size(); ++q) {
    ASSERT_EQ(found[q].size(), 1u);
    EXPECT_EQ(found[q][0].index, nearest_by(database, queries[q], database.size(), hellinger))
        << "query " << q;
    if (nearest_by(database, queries[q], database.size(), l2) != found[q][0].index) ++l2_disagrees;
  }
  // The data must be able to tell the two apart, or this test could not fail.
  EXPECT_GT(l2_disagrees, 0u) << "of " << queries.size();
}

TEST(RetrievalDeclaration, AWrongKdTreeDeclarationIsRefused) {
  const auto values = histograms(17);
  try {
    retrieve_nearest(HellingerClaimingKdTree(), values, values,
                     std::vector<std::size_t>(values.size(), values.size()), 1);
    FAIL() << "expected the kdtree declaration to be refused";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("declares kdtree retrieval"), std::string::npos)
        << error.what();
  }
  EXPECT_THROW(check_retrieval_declaration(HellingerClaimingL2(), values, values),
               std::invalid_argument);
}

TEST(RetrievalDeclaration, ARightDeclarationPassesAndIsExact) {
  const auto values = histograms(17);
  const HellingerWithSquareRootKey descriptor;
  const std::vector<DescriptorValue> queries = histograms(18);
  const std::vector<DescriptorValue>& database = values;
  const auto found = retrieve_nearest(descriptor, database, queries,
                                      std::vector<std::size_t>(queries.size(), database.size()), 1);
  for (std::size_t q = 0; q < queries.size(); ++q) {
    EXPECT_EQ(found[q][0].index,
              nearest_by(database, queries[q], database.size(),
                         [&](const auto& a, const auto& b) { return descriptor.distance(a, b); }));
  }
  // Built-in fast paths pass their own checks.
  EXPECT_NO_THROW(check_retrieval_declaration(
      testing::EuclideanFake(RetrievalMethod::exhaustive_l2), values, values));
  EXPECT_NO_THROW(check_retrieval_declaration(testing::CosineFake(), values, values));
}

}  // namespace
}  // namespace radarpr
