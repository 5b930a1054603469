#pragma once

#include <cstdint>
#include <vector>

#include "datasets/byte_image.hpp"

namespace radarpr {

// One radar revolution in polar form, in the orientation every loader delivers (descriptors.md):
// row a = azimuth, column r = range bin. Metadata columns are never part of `power`.
struct PolarImage {
  ByteImage power;                             // A x R
  std::vector<double> azimuths_rad;            // A angles, one per row
  std::vector<std::int64_t> azimuth_times_ns;  // A stamps, empty when the source has none
  double range_resolution_m = 0.0;             // metres per range bin

  int azimuth_count() const { return power.rows(); }
  int range_bin_count() const { return power.cols(); }
};

// Evenly spaced azimuths 2*pi*a/A, for sources that carry no encoder values.
std::vector<double> uniform_azimuths(int azimuth_count);

}  // namespace radarpr
