#pragma once

#include "descriptors/descriptor.hpp"
#include "descriptors/descriptor_registry.hpp"
#include "descriptors/features/cen2018.hpp"
#include "descriptors/features/polar_features.hpp"

namespace radarpr {

// ReFeree (Choi, Kim, Cho, ICRA 2024 workshop), descriptors.md §2: per block of azimuths, the
// share of free cells lying before each azimuth's farthest feature. Registered as `referee`.
struct RefereeParams {
  int alpha = 50;  // number of azimuth blocks = descriptor length
  Cen2018Params cen;
};

// The alpha x 1 descriptor of a feature set: Phi_a = free cells at r < r*_a (0 without
// features), K_i = sum over block i of Phi_a / (|block i| * R). Throws std::invalid_argument when
// the features have fewer than alpha azimuths.
DescriptorValue referee_from_features(const PolarFeatures& features, int alpha);

class RefereeDescriptor final : public Descriptor {
 public:
  explicit RefereeDescriptor(RefereeParams params);

  DescriptorValue extract(const PolarImage& scan) const override;
  double distance(const DescriptorValue& a, const DescriptorValue& b) const override;  // L2
  // The L2 distance of the values: a KD-tree over them finds the exact nearest.
  RetrievalMethod retrieval_method() const override { return RetrievalMethod::kdtree; }
  bool rotation_invariant() const override { return false; }
  DescriptorShape shape(const ScanGeometry& /*geometry*/) const override {
    return {params_.alpha, 1};
  }

  const RefereeParams& params() const { return params_; }

 private:
  RefereeParams params_;
};

// Registry entry: alpha (50) plus the shared Cen 2018 parameters.
DescriptorInfo make_referee_info();

}  // namespace radarpr
