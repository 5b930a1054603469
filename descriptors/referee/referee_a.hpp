#pragma once

#include <optional>
#include <span>

#include "descriptors/descriptor.hpp"
#include "descriptors/descriptor_registry.hpp"
#include "descriptors/features/cen2018.hpp"
#include "descriptors/features/polar_features.hpp"

namespace radarpr {

// A-ReFeree (journal follow-up, arXiv 2410.01325), descriptors.md §3: the ReFeree block profile
// counting every cell before the farthest feature, used to estimate the heading between two
// scans. Registered as `referee_a`.
struct RefereeAParams {
  int alpha = 50;
  Cen2018Params cen;
};

// alpha x 1: Phi_a = r*_a, the number of cells at r < r*_a, features included (0 without
// features) - §2's index range with features counted too; K_i = sum over block i of
// Phi_a / (|block i| * R). Throws std::invalid_argument when there are fewer than alpha azimuths.
DescriptorValue referee_a_from_features(const PolarFeatures& features, int alpha);

// The circular shift s in [0, n) maximising cos(roll(query, s), database), where
// roll(v, s)[i] = v[(i - s) mod n]; the smallest s among ties. Empty when either vector is zero
// (no heading information). Throws std::invalid_argument on different or zero lengths.
std::optional<int> referee_a_best_shift(std::span<const float> query,
                                        std::span<const float> database);

class RefereeADescriptor final : public Descriptor {
 public:
  explicit RefereeADescriptor(RefereeAParams params);

  DescriptorValue extract(const PolarImage& scan) const override;
  double distance(const DescriptorValue& a, const DescriptorValue& b) const override;  // L2
  // The L2 distance of the values: a KD-tree over them finds the exact nearest.
  RetrievalMethod retrieval_method() const override { return RetrievalMethod::kdtree; }
  bool rotation_invariant() const override { return false; }
  DescriptorShape shape(const ScanGeometry& /*geometry*/) const override {
    return {params_.alpha, 1};
  }

  // yaw = 2 pi s / alpha wrapped to (-pi, pi], s = referee_a_best_shift(query, database).
  // Sign: a positive yaw means the query sensor is turned by yaw in the direction of increasing
  // azimuth index relative to the database one - query row a sees what database row
  // a + yaw / (2 pi / A) saw. Empty when either value is all zero.
  std::optional<double> estimate_yaw(const DescriptorValue& query,
                                     const DescriptorValue& database) const override;

  const RefereeAParams& params() const { return params_; }

 private:
  RefereeAParams params_;
};

// Registry entry: alpha (50) plus the shared Cen 2018 parameters.
DescriptorInfo make_referee_a_info();

}  // namespace radarpr
