#pragma once

#include <vector>

#include "datasets/byte_image.hpp"
#include "descriptors/features/polar_features.hpp"

namespace radarpr::test {

// A hand-built A x R feature mask (one inner vector of feature bins per azimuth), through the
// dense-mask path the descriptors accept.
inline PolarFeatures features_from_rows(int range_bins, const std::vector<std::vector<int>>& rows) {
  ByteImage mask(static_cast<int>(rows.size()), range_bins, 0);
  for (int a = 0; a < mask.rows(); ++a) {
    for (const int r : rows[static_cast<std::size_t>(a)]) mask(a, r) = 1;
  }
  return PolarFeatures::from_mask(mask);
}

}  // namespace radarpr::test
