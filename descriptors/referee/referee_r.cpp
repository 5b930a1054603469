#include "descriptors/referee/referee_r.hpp"

#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>

#include "descriptors/features/cen2018_parameters.hpp"
#include "descriptors/referee/referee_common.hpp"

namespace radarpr {
namespace {

double squared_norm(const std::vector<float>& values) {
  double sum = 0.0;
  for (const float v : values) sum += static_cast<double>(v) * v;
  return sum;
}

}  // namespace

std::vector<RangeChunk> referee_r_chunks(int range_bin_count, int window, RefereeRBinning binning) {
  if (window < 1 || range_bin_count < window) {
    throw std::invalid_argument("referee_r: window " + std::to_string(window) +
                                " must be >= 1 and <= the scan's " +
                                std::to_string(range_bin_count) + " range bins");
  }
  std::vector<RangeChunk> chunks;
  if (binning == RefereeRBinning::cpp_quirk) {
    chunks.push_back({0, 1});
    for (int last = window; last < range_bin_count; last += window) {
      chunks.push_back({last - window + 1, window});
    }
    return chunks;
  }
  int first = 0;
  for (const int length :
       split_evenly(range_bin_count, range_bin_count / window, "referee_r (range chunks)")) {
    chunks.push_back({first, length});
    first += length;
  }
  return chunks;
}

DescriptorValue referee_r_from_features(const PolarFeatures& features,
                                        const RefereeRParams& params) {
  const int azimuths = features.azimuth_count();
  if (azimuths < 1) throw std::invalid_argument("referee_r: the scan has no azimuth");
  const std::vector<RangeChunk> chunks =
      referee_r_chunks(features.range_bin_count(), params.window, params.binning);
  const std::vector<int> features_per_bin = features.features_per_range_bin();
  DescriptorValue value{static_cast<int>(chunks.size()), 1, {}};
  for (const RangeChunk& chunk : chunks) {
    std::int64_t free_cells = 0;  // sum of Z_r = A - features at r
    for (int r = chunk.first; r < chunk.first + chunk.length; ++r) {
      free_cells += azimuths - features_per_bin[static_cast<std::size_t>(r)];
    }
    const double scale = params.normalize ? static_cast<double>(azimuths) * chunk.length : 1.0;
    value.values.push_back(static_cast<float>(static_cast<double>(free_cells) / scale));
  }
  return value;
}

RefereeRDescriptor::RefereeRDescriptor(RefereeRParams params) : params_(params) {
  cen2018_kernel(params_.cen);  // rejects a bad sigma now rather than on the first scan
  if (params_.window < 1) {
    throw std::invalid_argument("referee_r: window must be >= 1, got " +
                                std::to_string(params_.window));
  }
}

DescriptorValue RefereeRDescriptor::extract(const PolarImage& scan) const {
  check_polar_scan(scan, "referee_r");
  return referee_r_from_features(extract_cen2018_features(scan, params_.cen), params_);
}

DescriptorShape RefereeRDescriptor::shape(const ScanGeometry& geometry) const {
  const auto chunks = referee_r_chunks(geometry.range_bins, params_.window, params_.binning);
  return {static_cast<int>(chunks.size()), 1};
}

double RefereeRDescriptor::distance(const DescriptorValue& a, const DescriptorValue& b) const {
  if (params_.metric == RefereeRMetric::l2) return l2_distance(a, b, "referee_r");
  check_same_shape(a, b, "referee_r");
  const double norm_a = std::sqrt(squared_norm(a.values));
  const double norm_b = std::sqrt(squared_norm(b.values));
  if (norm_a == 0.0 && norm_b == 0.0) return 0.0;
  if (norm_a == 0.0 || norm_b == 0.0) return 0.5;
  double dot = 0.0;
  for (std::size_t i = 0; i < a.values.size(); ++i) {
    dot += static_cast<double>(a.values[i]) * b.values[i];
  }
  return 1.0 - dot / (norm_a * norm_b);
}

std::vector<float> RefereeRDescriptor::search_key(const DescriptorValue& value) const {
  if (params_.metric == RefereeRMetric::l2) return value.values;
  const double norm = std::sqrt(squared_norm(value.values));
  std::vector<float> key(value.values.size(), 0.0f);
  if (norm == 0.0) return key;
  for (std::size_t i = 0; i < key.size(); ++i) {
    key[i] = static_cast<float>(value.values[i] / norm);
  }
  return key;
}

DescriptorInfo make_referee_r_info() {
  const RefereeRParams defaults;
  std::vector<ParameterSpec> own = {
      {.name = "window",
       .kind = ParameterKind::integer,
       .default_value = std::int64_t{defaults.window},
       .description = "range bins per chunk: n = floor(R / window) chunks",
       .minimum = 1.0,
       .maximum = 100000.0},
      {.name = "normalize",
       .kind = ParameterKind::boolean,
       .default_value = defaults.normalize,
       .description = "divide each chunk's free-cell count by A * chunk length"},
      {.name = "binning",
       .kind = ParameterKind::choice,
       .default_value = std::string("chunks"),
       .description =
           "near-equal chunks, or the public C++ chunks closing on r % window == 0 (parity)",
       .choices = {"chunks", "cpp_quirk"}},
      {.name = "metric",
       .kind = ParameterKind::choice,
       .default_value = std::string("l2"),
       .description = "Euclidean distance, or 1 - cosine similarity as the public C++ (parity)",
       .choices = {"l2", "cosine"}},
  };
  return DescriptorInfo{
      "referee_r", "R-ReFeree: free cells per range chunk over all azimuths (rotation-invariant)",
      with_cen2018_parameters(std::move(own)),
      [](const ParameterValues& values) -> std::unique_ptr<Descriptor> {
        RefereeRParams params;
        params.window = static_cast<int>(values.integer("window"));
        params.normalize = values.boolean("normalize");
        params.binning = choice_value<RefereeRBinning>(
            values, "binning",
            {{"chunks", RefereeRBinning::chunks}, {"cpp_quirk", RefereeRBinning::cpp_quirk}});
        params.metric = choice_value<RefereeRMetric>(
            values, "metric", {{"l2", RefereeRMetric::l2}, {"cosine", RefereeRMetric::cosine}});
        params.cen = cen2018_params_from(values);
        return std::make_unique<RefereeRDescriptor>(params);
      },
      [](const Descriptor& descriptor, const PolarImage& scan) {
        const RefereeRParams params = dynamic_cast<const RefereeRDescriptor&>(descriptor).params();
        return cen2018_then_descriptor_stages(
            params.cen, scan,
            [params](const PolarFeatures& features) {
              return referee_r_from_features(features, params);
            },
            "the range-chunk counts (referee_r_from_features)");
      }};
}

RADARPR_REGISTER_DESCRIPTOR(referee_r, make_referee_r_info)

}  // namespace radarpr
