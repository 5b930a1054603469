#include "descriptors/referee/referee_common.hpp"

#include "descriptors/features/cen2018_parameters.hpp"

#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>

namespace radarpr {

std::vector<int> split_evenly(int count, int parts, std::string_view what) {
  if (parts < 1 || parts > count) {
    throw std::invalid_argument(std::string(what) + ": cannot split " + std::to_string(count) +
                                " items into " + std::to_string(parts) +
                                " non-empty blocks (need 1 <= blocks <= items)");
  }
  std::vector<int> lengths(static_cast<std::size_t>(parts), count / parts);
  for (int i = 0; i < count % parts; ++i) ++lengths[static_cast<std::size_t>(i)];
  return lengths;
}

void check_polar_scan(const PolarImage& scan, std::string_view descriptor) {
  if (scan.power.empty()) {
    throw std::invalid_argument(
        std::string(descriptor) + ": expected a non-empty A x R polar image, got " +
        std::to_string(scan.power.rows()) + " x " + std::to_string(scan.power.cols()));
  }
}

DescriptorValue azimuth_block_profile(
    const PolarFeatures& features, int alpha,
    const std::function<double(std::span<const int>)>& per_azimuth, std::string_view descriptor) {
  const int azimuths = features.azimuth_count();
  if (alpha < 1 || azimuths < alpha) {
    throw std::invalid_argument(
        std::string(descriptor) + ": the scan has " + std::to_string(azimuths) +
        " azimuths, fewer than alpha = " + std::to_string(alpha) + " blocks");
  }
  const std::vector<int> blocks =
      split_evenly(azimuths, alpha, std::string(descriptor) + " (azimuths into alpha blocks)");
  const double range_bins = features.range_bin_count();
  DescriptorValue value{alpha, 1, {}};
  value.values.reserve(blocks.size());
  int a = 0;
  for (const int length : blocks) {
    double sum = 0.0;
    for (int end = a + length; a < end; ++a) sum += per_azimuth(features.azimuth(a));
    value.values.push_back(static_cast<float>(sum / (length * range_bins)));
  }
  return value;
}

void check_same_shape(const DescriptorValue& a, const DescriptorValue& b,
                      std::string_view descriptor) {
  if (a.rows != b.rows || a.cols != b.cols || a.values.size() != b.values.size() ||
      a.values.size() != static_cast<std::size_t>(a.rows) * static_cast<std::size_t>(a.cols)) {
    throw std::invalid_argument(std::string(descriptor) + ": cannot compare a " +
                                std::to_string(a.rows) + " x " + std::to_string(a.cols) + " (" +
                                std::to_string(a.values.size()) + " values) descriptor with a " +
                                std::to_string(b.rows) + " x " + std::to_string(b.cols) + " (" +
                                std::to_string(b.values.size()) + " values) one");
  }
}

double l2_distance(const DescriptorValue& a, const DescriptorValue& b,
                   std::string_view descriptor) {
  check_same_shape(a, b, descriptor);
  double sum = 0.0;
  for (std::size_t i = 0; i < a.values.size(); ++i) {
    const double d = static_cast<double>(a.values[i]) - b.values[i];
    sum += d * d;
  }
  return std::sqrt(sum);
}

ParameterSpec alpha_parameter_spec() {
  return {.name = "alpha",
          .kind = ParameterKind::integer,
          .default_value = std::int64_t{50},
          .description = "number of consecutive azimuth blocks (the descriptor length)",
          .minimum = 1.0,
          .maximum = 100000.0};
}

std::vector<ParameterSpec> with_cen2018_parameters(std::vector<ParameterSpec> own) {
  for (ParameterSpec& spec : cen2018_parameter_specs()) own.push_back(std::move(spec));
  return own;
}

std::vector<ExtractionStage> cen2018_then_descriptor_stages(
    const Cen2018Params& cen, const PolarImage& scan,
    std::function<DescriptorValue(const PolarFeatures&)> from_features, std::string what) {
  auto features = std::make_shared<const PolarFeatures>(extract_cen2018_features(scan, cen));
  return {
      {std::string(kFeaturesStage), "Cen 2018 point features (extract_cen2018_features)",
       [cen, &scan] { extract_cen2018_features(scan, cen); }},
      {std::string(kDescriptorStage), std::move(what),
       [features, from_features = std::move(from_features)] { from_features(*features); }},
  };
}

}  // namespace radarpr
