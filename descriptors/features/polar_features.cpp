#include "descriptors/features/polar_features.hpp"

#include <cstdint>
#include <stdexcept>
#include <string>

namespace radarpr {

PolarFeatures::PolarFeatures(int azimuth_count, int range_bin_count)
    : range_bin_count_(range_bin_count) {
  if (azimuth_count < 0 || range_bin_count < 0) {
    throw std::invalid_argument("PolarFeatures: negative shape " + std::to_string(azimuth_count) +
                                " x " + std::to_string(range_bin_count));
  }
  offsets_.assign(static_cast<std::size_t>(azimuth_count) + 1, 0);
}

PolarFeatures PolarFeatures::from_mask(const ByteImage& mask) {
  if (mask.empty()) {
    throw std::invalid_argument("PolarFeatures::from_mask: expected a non-empty A x R mask, got " +
                                std::to_string(mask.rows()) + " x " + std::to_string(mask.cols()));
  }
  PolarFeatures features(0, mask.cols());
  std::vector<int> row_bins;
  for (int a = 0; a < mask.rows(); ++a) {
    row_bins.clear();
    const std::uint8_t* row = mask.row(a);
    for (int r = 0; r < mask.cols(); ++r) {
      if (row[r] != 0) row_bins.push_back(r);
    }
    features.add_azimuth(row_bins);
  }
  return features;
}

ByteImage PolarFeatures::to_mask() const {
  ByteImage mask(azimuth_count(), range_bin_count_, 0);
  for (int a = 0; a < azimuth_count(); ++a) {
    std::uint8_t* row = mask.row(a);
    for (const int r : azimuth(a)) row[r] = 1;
  }
  return mask;
}

void PolarFeatures::add_azimuth(std::span<const int> bins) {
  int previous = -1;
  for (const int r : bins) {
    if (r <= previous || r >= range_bin_count_) {
      throw std::invalid_argument("PolarFeatures::add_azimuth: bin " + std::to_string(r) +
                                  " is not increasing or outside [0, " +
                                  std::to_string(range_bin_count_) + ")");
    }
    previous = r;
  }
  bins_.insert(bins_.end(), bins.begin(), bins.end());
  offsets_.push_back(bins_.size());
}

std::vector<int> PolarFeatures::features_per_range_bin() const {
  std::vector<int> counts(static_cast<std::size_t>(range_bin_count_), 0);
  for (const int r : bins_) ++counts[static_cast<std::size_t>(r)];
  return counts;
}

}  // namespace radarpr
