#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "descriptors/descriptor.hpp"

namespace radarpr::bench {

// Synthetic descriptor values with the structure of a drive, for the retrieval benchmarks.
//
// A drive is a smooth path through descriptor space: consecutive scans have similar values, and
// a revisit brings the values back near those of the first visit. So the sensor drives a closed
// route `laps` times at constant speed; the route is a smooth closed curve in a few latent
// dimensions (`modes` random Fourier modes each, amplitude falling as 1/mode), mapped linearly
// into the descriptor's elements (a random matrix, plus an offset of 1 so that values are
// mostly positive, as powers and shares are); every lap is shifted a little (`lap_variation`,
// a different line through the same streets) and every element gets uniform noise of standard
// deviation `noise`. Pure uniform noise would be the KD-tree's worst case (no low-dimensional
// structure at all), which real descriptors are not.
struct DriveValuesSpec {
  std::size_t count = 1000;  // scans
  int rows = 50;             // the descriptor's shape
  int cols = 1;
  // Sessions share the route and its mapping; lap shifts and noise differ.
  int session = 0;
  std::uint64_t seed = 1;
  int laps = 4;
  int latent_dimensions = 8;
  int modes = 6;
  double lap_variation = 0.05;  // latent units; the route spans about +-2 per latent dimension
  double noise = 0.02;
};

// Deterministic in the spec (value i never depends on the thread count). Throws
// std::invalid_argument for a non-positive count, shape, laps, latent dimensions or modes.
std::vector<DescriptorValue> drive_values(const DriveValuesSpec& spec);

// The same values one at a time, for drives too large to hold (written to a file a block at a
// time): value(i, out) writes value i's rows x cols floats, equal to drive_values(spec)[i].
class DriveValueGenerator {
 public:
  // Throws like drive_values.
  explicit DriveValueGenerator(const DriveValuesSpec& spec);
  std::size_t dimension() const { return dimension_; }
  void value(std::size_t i, float* out) const;

 private:
  DriveValuesSpec spec_;
  std::size_t dimension_ = 0;
  std::vector<double> coefficients_;
  std::vector<float> mapping_;
  std::vector<double> lap_shifts_;
};

}  // namespace radarpr::bench
