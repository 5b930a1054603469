#pragma once

#include <cmath>
#include <memory>
#include <stdexcept>
#include <vector>

#include "descriptors/descriptor.hpp"

namespace radarpr::testing {

inline DescriptorValue vector_value(std::vector<float> values) {
  DescriptorValue value;
  value.rows = 1;
  value.cols = static_cast<int>(values.size());
  value.values = std::move(values);
  return value;
}

// Euclidean distance between values; the search key is the value (the interface's default).
class EuclideanFake : public Descriptor {
 public:
  explicit EuclideanFake(RetrievalMethod method = RetrievalMethod::kdtree) : method_(method) {}

  DescriptorValue extract(const PolarImage& /*scan*/) const override {
    throw std::logic_error("EuclideanFake::extract is not used by these tests");
  }
  double distance(const DescriptorValue& a, const DescriptorValue& b) const override {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.values.size(); ++i) {
      const double difference = double(a.values[i]) - double(b.values[i]);
      sum += difference * difference;
    }
    return std::sqrt(sum);
  }
  bool rotation_invariant() const override { return false; }
  DescriptorShape shape(const ScanGeometry& /*geometry*/) const override { return {1, 0}; }
  RetrievalMethod retrieval_method() const override { return method_; }

 private:
  RetrievalMethod method_;
};

// Cosine distance 1 - cos(a, b); the search key is the value scaled to unit length, whose L2
// distance sqrt(2 - 2 cos) orders the database like the cosine distance. Key != value.
class CosineFake : public Descriptor {
 public:
  DescriptorValue extract(const PolarImage& /*scan*/) const override {
    throw std::logic_error("CosineFake::extract is not used by these tests");
  }
  double distance(const DescriptorValue& a, const DescriptorValue& b) const override {
    double dot = 0.0, norm_a = 0.0, norm_b = 0.0;
    for (std::size_t i = 0; i < a.values.size(); ++i) {
      dot += double(a.values[i]) * b.values[i];
      norm_a += double(a.values[i]) * a.values[i];
      norm_b += double(b.values[i]) * b.values[i];
    }
    return 1.0 - dot / std::sqrt(norm_a * norm_b);
  }
  bool rotation_invariant() const override { return false; }
  DescriptorShape shape(const ScanGeometry& /*geometry*/) const override { return {1, 0}; }
  RetrievalMethod retrieval_method() const override { return RetrievalMethod::kdtree; }
  std::vector<float> search_key(const DescriptorValue& value) const override {
    double norm = 0.0;
    for (const float v : value.values) norm += double(v) * v;
    std::vector<float> key;
    for (const float v : value.values) key.push_back(static_cast<float>(v / std::sqrt(norm)));
    return key;
  }
};

// Scan Context's scheme in miniature: the key is the value's first element only (a coarse,
// "ring key"-like summary), the distance is the Euclidean distance of whole values, and the
// `candidates` nearest keys are re-ranked by it.
class KeyThenRerankFake : public EuclideanFake {
 public:
  explicit KeyThenRerankFake(std::size_t candidates) : candidates_(candidates) {}
  RetrievalMethod retrieval_method() const override { return RetrievalMethod::key_then_rerank; }
  std::vector<float> search_key(const DescriptorValue& value) const override {
    return {value.values.front()};
  }
  std::size_t rerank_candidates() const override { return candidates_; }

 private:
  std::size_t candidates_;
};

// Exhaustive retrieval through prepared distances: the prepared object precomputes each value's
// sum once and answers |sum(q) - sum(d)|, which equals distance(); it counts how often it was
// prepared, so a test can see that the per-value work is done once per search.
class PreparedSumFake : public EuclideanFake {
 public:
  PreparedSumFake() : EuclideanFake(RetrievalMethod::exhaustive) {}
  double distance(const DescriptorValue& a, const DescriptorValue& b) const override {
    return std::abs(sum(a) - sum(b));
  }
  std::unique_ptr<PreparedDistances> prepare_distances(
      const std::vector<DescriptorValue>& queries,
      const std::vector<DescriptorValue>& database) const override {
    ++prepare_calls;
    auto prepared = std::make_unique<Prepared>();
    for (const auto& value : queries) prepared->query_sums.push_back(sum(value));
    for (const auto& value : database) prepared->database_sums.push_back(sum(value));
    return prepared;
  }
  mutable int prepare_calls = 0;

 private:
  struct Prepared final : PreparedDistances {
    std::vector<double> query_sums, database_sums;
    double distance(std::size_t query, std::size_t database_index) const override {
      return std::abs(query_sums[query] - database_sums[database_index]);
    }
  };
  static double sum(const DescriptorValue& value) {
    double total = 0.0;
    for (const float element : value.values) total += element;
    return total;
  }
};

}  // namespace radarpr::testing
