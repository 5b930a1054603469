#include "descriptors/referee/referee.hpp"

#include <memory>

#include "descriptors/features/cen2018_parameters.hpp"
#include "descriptors/referee/referee_common.hpp"

namespace radarpr {

DescriptorValue referee_from_features(const PolarFeatures& features, int alpha) {
  return azimuth_block_profile(
      features, alpha,
      [](std::span<const int> bins) -> double {
        if (bins.empty()) return 0.0;
        // Every feature of the azimuth lies at r <= r*; all but r* itself lie before it.
        const int farthest = bins.back();
        return farthest - static_cast<int>(bins.size() - 1);
      },
      "referee");
}

RefereeDescriptor::RefereeDescriptor(RefereeParams params) : params_(params) {
  cen2018_kernel(params_.cen);  // rejects a bad sigma now rather than on the first scan
}

DescriptorValue RefereeDescriptor::extract(const PolarImage& scan) const {
  check_polar_scan(scan, "referee");
  return referee_from_features(extract_cen2018_features(scan, params_.cen), params_.alpha);
}

double RefereeDescriptor::distance(const DescriptorValue& a, const DescriptorValue& b) const {
  return l2_distance(a, b, "referee");
}

DescriptorInfo make_referee_info() {
  return DescriptorInfo{
      "referee",
      "ReFeree: per azimuth block, the share of free cells before the farthest Cen 2018 feature",
      with_cen2018_parameters({alpha_parameter_spec()}),
      [](const ParameterValues& values) -> std::unique_ptr<Descriptor> {
        RefereeParams params;
        params.alpha = static_cast<int>(values.integer("alpha"));
        params.cen = cen2018_params_from(values);
        return std::make_unique<RefereeDescriptor>(params);
      },
      [](const Descriptor& descriptor, const PolarImage& scan) {
        const RefereeParams params = dynamic_cast<const RefereeDescriptor&>(descriptor).params();
        return cen2018_then_descriptor_stages(
            params.cen, scan,
            [alpha = params.alpha](const PolarFeatures& features) {
              return referee_from_features(features, alpha);
            },
            "the block profile (referee_from_features)");
      }};
}

RADARPR_REGISTER_DESCRIPTOR(referee, make_referee_info)

}  // namespace radarpr
