#pragma once

#include <cmath>
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
  std::vector<float> search_key(const DescriptorValue& value) const override {
    double norm = 0.0;
    for (const float v : value.values) norm += double(v) * v;
    std::vector<float> key;
    for (const float v : value.values) key.push_back(static_cast<float>(v / std::sqrt(norm)));
    return key;
  }
};

}  // namespace radarpr::testing
