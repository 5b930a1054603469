#include "datasets/polar_image.hpp"

#include <numbers>

namespace radarpr {

std::vector<double> uniform_azimuths(int azimuth_count) {
  std::vector<double> angles(static_cast<std::size_t>(azimuth_count));
  for (int a = 0; a < azimuth_count; ++a) {
    angles[static_cast<std::size_t>(a)] = 2.0 * std::numbers::pi * a / azimuth_count;
  }
  return angles;
}

}  // namespace radarpr
