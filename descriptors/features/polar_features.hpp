#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "datasets/byte_image.hpp"

namespace radarpr {

// Point features of one polar scan, stored compactly: for every azimuth row, the range bins of
// its features in increasing order. The dense equivalent is a binary A x R mask; every ReFeree
// variant only needs per-azimuth and per-range counts, which this layout gives without scanning
// 1.3 M mask bytes.
class PolarFeatures {
 public:
  PolarFeatures() = default;
  // An empty feature set (no feature anywhere) of the given shape.
  PolarFeatures(int azimuth_count, int range_bin_count);

  // From a dense A x R mask (any non-zero byte is a feature); throws std::invalid_argument on an
  // empty mask.
  static PolarFeatures from_mask(const ByteImage& mask);
  // The dense A x R mask, 1 = feature, 0 = free.
  ByteImage to_mask() const;

  // Appends the next azimuth row; `bins` must be strictly increasing and inside [0, R).
  void add_azimuth(std::span<const int> bins);

  int azimuth_count() const { return static_cast<int>(offsets_.size()) - 1; }
  int range_bin_count() const { return range_bin_count_; }
  // The feature bins of azimuth `a`, increasing.
  std::span<const int> azimuth(int a) const {
    return std::span<const int>(bins_).subspan(offsets_[a], offsets_[a + 1] - offsets_[a]);
  }
  std::size_t feature_count() const { return bins_.size(); }
  // Number of features at every range bin, summed over azimuths (R values).
  std::vector<int> features_per_range_bin() const;

  friend bool operator==(const PolarFeatures&, const PolarFeatures&) = default;

 private:
  int range_bin_count_ = 0;
  std::vector<std::size_t> offsets_{0};  // azimuth a owns bins_[offsets_[a], offsets_[a + 1])
  std::vector<int> bins_;
};

}  // namespace radarpr
