#include "datasets/synthetic/radar/radar_quantise.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "datasets/synthetic/random.hpp"

namespace radarpr::synthetic {
namespace {

constexpr int kSpeckleLutBits = 12;

// Quantiles of the exponential distribution (speckle of a fully developed scatterer) in units.
const std::array<float, 1 << kSpeckleLutBits>& speckle_table() {
  static const auto table = [] {
    std::array<float, 1 << kSpeckleLutBits> t{};
    for (std::size_t i = 0; i < t.size(); ++i) {
      const double u = (static_cast<double>(i) + 0.5) / static_cast<double>(t.size());
      t[i] = static_cast<float>(20.0 * std::log10(-std::log(1.0 - u)));
    }
    return t;
  }();
  return table;
}

}  // namespace

ByteImage quantise(const EchoBuffer& echoes, const RadarModel& radar, std::uint64_t noise_seed) {
  const int bins = radar.range_bin_count;
  std::vector<float> floor_units(static_cast<std::size_t>(bins));
  std::vector<float> clutter_units(static_cast<std::size_t>(bins));
  std::vector<float> floor_power(static_cast<std::size_t>(bins));
  std::vector<float> clutter_power(static_cast<std::size_t>(bins));
  for (int r = 0; r < bins; ++r) {
    const double range = (r + 0.5) * radar.range_resolution_m;
    // Rain or snow backscatter adds to the receiver noise, strongest near the sensor.
    const double floor =
        radar.noise_floor_far +
        (radar.noise_floor_near - radar.noise_floor_far) *
            std::exp(-range / radar.noise_floor_falloff_m) +
        radar.precipitation_clutter * std::exp(-range / radar.precipitation_falloff_m);
    const double clutter =
        floor + radar.ground_clutter * std::exp(-range / radar.ground_clutter_falloff_m);
    const auto index = static_cast<std::size_t>(r);
    floor_units[index] = static_cast<float>(floor);
    clutter_units[index] = static_cast<float>(clutter);
    floor_power[index] = static_cast<float>(std::pow(10.0, floor / 20.0));
    clutter_power[index] = static_cast<float>(std::pow(10.0, clutter / 20.0));
  }

  // Row by row in separate simple passes (base level, sparse echoes, speckle) so the dense
  // passes stay branch-free: this loop touches every pixel and dominates the render time.
  const auto& speckle = speckle_table();
  constexpr int kDrawsPerRandom = 64 / kSpeckleLutBits;
  constexpr std::uint64_t kLutMask = (1u << kSpeckleLutBits) - 1;
  // Speckle is drawn once per range cell and interpolated in between: real speckle is
  // correlated over the radar's range resolution, which spans several bins.
  const int cell = std::max(
      1, static_cast<int>(std::lround(radar.speckle_correlation_m / radar.range_resolution_m)));
  const auto cells = static_cast<std::size_t>(bins / cell + 2);
  std::vector<float> interpolation(static_cast<std::size_t>(cell));
  for (int j = 0; j < cell; ++j)
    interpolation[static_cast<std::size_t>(j)] = static_cast<float>(j) / static_cast<float>(cell);
  Rng rng(noise_seed);
  std::vector<float> units(cells * static_cast<std::size_t>(cell));
  std::vector<float> nodes(cells + kDrawsPerRandom);
  // Every pixel of every row is written at the end of its row's pass.
  ByteImage power = ByteImage::uninitialised(radar.azimuth_count, bins);
  for (int a = 0; a < radar.azimuth_count; ++a) {
    const float* echo = echoes.row(a);
    const auto lit_end = static_cast<std::size_t>(std::min(echoes.opaque_bin(a), bins));
    const auto end = static_cast<std::size_t>(bins);
    std::copy(clutter_units.begin(), clutter_units.begin() + static_cast<std::ptrdiff_t>(lit_end),
              units.begin());
    std::copy(floor_units.begin() + static_cast<std::ptrdiff_t>(lit_end), floor_units.end(),
              units.begin() + static_cast<std::ptrdiff_t>(lit_end));
    std::fill(units.begin() + bins, units.end(), 0.0f);  // padding up to a whole cell
    for (std::size_t r = 0; r < lit_end; ++r) {
      if (echo[r] > 0.0f) units[r] = 20.0f * std::log10(clutter_power[r] + echo[r]);
    }
    for (std::size_t r = lit_end; r < end; ++r) {
      if (echo[r] > 0.0f) units[r] = 20.0f * std::log10(floor_power[r] + echo[r]);
    }

    if (radar.speckle) {
      for (std::size_t k = 0; k < cells; k += kDrawsPerRandom) {
        std::uint64_t bits = rng.next();
        for (int d = 0; d < kDrawsPerRandom; ++d, bits >>= kSpeckleLutBits) {
          nodes[k + static_cast<std::size_t>(d)] = speckle[bits & kLutMask];
        }
      }
      for (std::size_t k = 0; k + 1 < cells; ++k) {
        float* span = units.data() + k * static_cast<std::size_t>(cell);
        const float step = nodes[k + 1] - nodes[k];
        for (std::size_t j = 0; j < interpolation.size(); ++j) {
          span[j] += nodes[k] + step * interpolation[j];
        }
      }
    }
    std::uint8_t* out = power.row(a);
    for (std::size_t r = 0; r < end; ++r) {
      out[r] = static_cast<std::uint8_t>(std::clamp(units[r] + 0.5f, 0.0f, 255.0f));
    }
  }
  return power;
}

}  // namespace radarpr::synthetic
