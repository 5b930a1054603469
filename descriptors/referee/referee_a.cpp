#include "descriptors/referee/referee_a.hpp"

#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>

#include "descriptors/features/cen2018_parameters.hpp"
#include "descriptors/referee/referee_common.hpp"

namespace radarpr {

DescriptorValue referee_a_from_features(const PolarFeatures& features, int alpha) {
  return azimuth_block_profile(
      features, alpha,
      [](std::span<const int> bins) -> double { return bins.empty() ? 0.0 : bins.back(); },
      "referee_a");
}

std::optional<int> referee_a_best_shift(std::span<const float> query,
                                        std::span<const float> database) {
  if (query.empty() || query.size() != database.size()) {
    throw std::invalid_argument("referee_a: cannot align descriptors of " +
                                std::to_string(query.size()) + " and " +
                                std::to_string(database.size()) + " values");
  }
  const std::size_t n = query.size();
  double query_norm = 0.0;
  double database_norm = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    query_norm += static_cast<double>(query[i]) * query[i];
    database_norm += static_cast<double>(database[i]) * database[i];
  }
  if (query_norm == 0.0 || database_norm == 0.0) return std::nullopt;
  // The norms do not change with the shift, so the largest dot product is the largest cosine.
  int best_shift = 0;
  double best_dot = -std::numeric_limits<double>::infinity();
  for (std::size_t s = 0; s < n; ++s) {
    double dot = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      dot += static_cast<double>(query[(i + n - s) % n]) * database[i];
    }
    if (dot > best_dot) {
      best_dot = dot;
      best_shift = static_cast<int>(s);
    }
  }
  return best_shift;
}

RefereeADescriptor::RefereeADescriptor(RefereeAParams params) : params_(params) {
  cen2018_kernel(params_.cen);  // rejects a bad sigma now rather than on the first scan
}

DescriptorValue RefereeADescriptor::extract(const PolarImage& scan) const {
  check_polar_scan(scan, "referee_a");
  return referee_a_from_features(extract_cen2018_features(scan, params_.cen), params_.alpha);
}

double RefereeADescriptor::distance(const DescriptorValue& a, const DescriptorValue& b) const {
  return l2_distance(a, b, "referee_a");
}

std::optional<double> RefereeADescriptor::estimate_yaw(const DescriptorValue& query,
                                                       const DescriptorValue& database) const {
  check_same_shape(query, database, "referee_a");
  const std::optional<int> shift = referee_a_best_shift(query.values, database.values);
  if (!shift) return std::nullopt;
  double yaw = 2.0 * std::numbers::pi * *shift / static_cast<double>(query.values.size());
  if (yaw > std::numbers::pi) yaw -= 2.0 * std::numbers::pi;  // (-pi, pi]
  return yaw;
}

DescriptorInfo make_referee_a_info() {
  return DescriptorInfo{
      "referee_a",
      "A-ReFeree: per azimuth block, the share of cells before the farthest Cen 2018 feature; "
      "estimates the heading by circular shift",
      with_cen2018_parameters({alpha_parameter_spec()}),
      [](const ParameterValues& values) -> std::unique_ptr<Descriptor> {
        RefereeAParams params;
        params.alpha = static_cast<int>(values.integer("alpha"));
        params.cen = cen2018_params_from(values);
        return std::make_unique<RefereeADescriptor>(params);
      },
      [](const Descriptor& descriptor, const PolarImage& scan) {
        const RefereeAParams params = dynamic_cast<const RefereeADescriptor&>(descriptor).params();
        return cen2018_then_descriptor_stages(
            params.cen, scan,
            [alpha = params.alpha](const PolarFeatures& features) {
              return referee_a_from_features(features, alpha);
            },
            "the block profile (referee_a_from_features)");
      }};
}

RADARPR_REGISTER_DESCRIPTOR(referee_a, make_referee_a_info)

}  // namespace radarpr
