#pragma once

#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include "descriptors/descriptor.hpp"
#include "descriptors/descriptor_registry.hpp"
#include "descriptors/precomputed/external_values.hpp"
#include "descriptors/precomputed/precomputed_table.hpp"

namespace radarpr {

enum class PrecomputedDistance { l2, cosine };

struct PrecomputedParams {
  // Files; "{dataset}" and "{role}" (query, database, training) are replaced per sequence.
  std::string values;
  std::string timestamps;  // empty: the values CSV's `timestamp` column
  PrecomputedTimeUnit time_unit = PrecomputedTimeUnit::ns;
  double tolerance_ms = 1.0;
  PrecomputedDistance distance = PrecomputedDistance::l2;
  bool rotation_invariant = false;  // what the values' author claims; shown in the tables
};

// `precomputed`: descriptor values computed outside radarpr (a learned model in Python, another
// framework), one row per scan, evaluated under radarpr's protocol like any descriptor. The rows
// are matched to the sequence's scans by time (precomputed_table.hpp); nothing is extracted from
// the images. Values are D x 1; shape() reports D once the values file is known.
class PrecomputedDescriptor final : public Descriptor, public ExternalValues {
 public:
  explicit PrecomputedDescriptor(PrecomputedParams params);

  // Refused: the values come from the files, not from a scan image.
  DescriptorValue extract(const PolarImage& scan) const override;
  // l2: Euclidean. cosine: 1 - cos(a, b); with a zero vector 0.5 * |key(a) - key(b)|^2, as
  // referee_r's cosine, so that the KD-tree order over search_key() equals this order.
  double distance(const DescriptorValue& a, const DescriptorValue& b) const override;
  bool rotation_invariant() const override { return params_.rotation_invariant; }
  // D x 1: D from the values file (read when its path has no placeholder, else when the first
  // sequence's values are read); 0 x 1 before that.
  DescriptorShape shape(const ScanGeometry& geometry) const override;
  RetrievalMethod retrieval_method() const override { return RetrievalMethod::kdtree; }
  // l2: the value. cosine: the value scaled to unit length (a zero vector stays zero).
  std::vector<float> search_key(const DescriptorValue& value) const override;

  std::vector<DescriptorValue> values_for(const ExternalSequence& sequence) const override;

  const PrecomputedParams& params() const { return params_; }

 private:
  PrecomputedParams params_;
  mutable std::atomic<int> dimension_{0};
};

// "{dataset}" and "{role}" of `pattern` replaced.
std::string expand_precomputed_path(const std::string& pattern, const ExternalSequence& sequence);

DescriptorInfo make_precomputed_info();

}  // namespace radarpr
