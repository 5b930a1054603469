#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "datasets/polar_image.hpp"

namespace radarpr {

// A descriptor's value: `rows` x `cols` floats, row-major. Every built-in stores float32.
struct DescriptorValue {
  int rows = 0;
  int cols = 0;
  std::vector<float> values;

  std::size_t element_count() const { return values.size(); }
  std::size_t payload_bytes() const { return values.size() * sizeof(float); }
};

// How the evaluation engine may search a database of this descriptor's values.
enum class RetrievalMethod {
  // search_key() vectors in a KD-tree: their L2 distance orders the database exactly as
  // distance() does, so the KD-tree nearest neighbour is the descriptor's nearest neighbour.
  kdtree,
  // distance() against every eligible database value.
  exhaustive,
};

// The plugin interface every place-recognition descriptor implements (architecture.md). An
// instance is immutable after construction and used from several threads at once.
class Descriptor {
 public:
  virtual ~Descriptor() = default;

  virtual DescriptorValue extract(const PolarImage& scan) const = 0;
  // Smaller = more similar; descriptors built on a similarity expose 1 - similarity or the like.
  virtual double distance(const DescriptorValue& a, const DescriptorValue& b) const = 0;
  virtual bool rotation_invariant() const = 0;

  virtual RetrievalMethod retrieval_method() const { return RetrievalMethod::kdtree; }
  // The KD-tree key of a value (see RetrievalMethod::kdtree); the value itself by default.
  virtual std::vector<float> search_key(const DescriptorValue& value) const { return value.values; }
  // Heading of scan `query` relative to scan `database` in radians, (-pi, pi], for descriptors
  // that can estimate it.
  virtual std::optional<double> estimate_yaw(const DescriptorValue& /*query*/,
                                             const DescriptorValue& /*database*/) const {
    return std::nullopt;
  }
};

}  // namespace radarpr
