#include "datasets/synthetic/synthetic_keys.hpp"

#include <cstdint>
#include <stdexcept>

#include <fmt/format.h>

#include "datasets/scan_sequence.hpp"
#include "datasets/synthetic/cached_synthetic_sequence.hpp"
#include "datasets/synthetic/synthetic_sequence.hpp"
#include "datasets/synthetic/world/world_presets.hpp"

namespace radarpr {
namespace {

int int_in(DatasetKeys& keys, const std::string& key, int fallback, int low, int high) {
  const auto value = keys.integer_or(key, fallback);
  if (value < low || value > high) {
    keys.fail(key, fmt::format("must be an integer in [{}, {}], got {}", low, high, value));
  }
  return static_cast<int>(value);
}

double number_in(DatasetKeys& keys, const std::string& key, double fallback, double above,
                 double at_most) {
  const double value = keys.number_or(key, fallback);
  if (!(value > above && value <= at_most)) {
    keys.fail(key, fmt::format("must be a number in ({}, {}], got {}", above, at_most, value));
  }
  return value;
}

// A number in [low, high].
double number_within(DatasetKeys& keys, const std::string& key, double fallback, double low,
                     double high) {
  const double value = keys.number_or(key, fallback);
  if (!(value >= low && value <= high)) {
    keys.fail(key, fmt::format("must be a number in [{}, {}], got {}", low, high, value));
  }
  return value;
}

// Bounds that keep a typo from asking for terabytes: a scan's pixels, the radar's reach (the
// world is generated out to it around the drive) and the drive's length.
constexpr int kMaxScans = 1'000'000;
constexpr int kMaxScanPixels = 1 << 24;
constexpr double kMaxReachM = 500.0;
constexpr int kMaxRouteBlocks = 50;
// A bound for typos only: every world narrows it to at most half its block (75 m at most).
constexpr double kMaxCornerRadiusM = 1000.0;

int block_field(DatasetKeys& keys, const std::string& key, int fallback) {
  const auto value = keys.integer_or(key, fallback);
  if (value < -100'000 || value > 100'000) {
    keys.fail(key, fmt::format("must be in [-100000, 100000] blocks, got {}", value));
  }
  return static_cast<int>(value);
}

// Runs `action` and turns its std::invalid_argument into a ConfigError at `key`.
template <typename Action>
void at_key(DatasetKeys& keys, const std::string& key, Action action) {
  try {
    action();
  } catch (const std::invalid_argument& error) {
    keys.fail(key, error.what());
  }
}

// Presets first, then the keys that override them.
}  // namespace

SequenceConfig parse_synthetic_keys(DatasetKeys& keys) {
  SyntheticConfig config;
  if (keys.has("radar")) {
    at_key(keys, "radar",
           [&] { config.radar = synthetic::radar_preset(keys.required_string("radar")); });
  }
  if (keys.has("world")) {
    at_key(keys, "world", [&] {
      const auto preset = synthetic::world_preset(keys.required_string("world"));
      config.city = preset.layout;
      config.world = preset.params;
      config.radar.ground_clutter = preset.ground_clutter;
      config.radar.ground_clutter_falloff_m = preset.ground_clutter_falloff_m;
    });
  }
  if (keys.has("weather")) {
    at_key(keys, "weather",
           [&] { config.weather = synthetic::weather_from(keys.required_string("weather")); });
  }
  const auto seed = keys.integer_or("seed", static_cast<std::int64_t>(config.seed));
  if (seed < 0) keys.fail("seed", fmt::format("must be >= 0, got {}", seed));
  config.seed = static_cast<std::uint64_t>(seed);
  config.session = int_in(keys, "session", config.session, 0, 1000);
  config.scan_count = int_in(keys, "scans", config.scan_count, 1, kMaxScans);
  // Fewer than 16 of either and every descriptor gives every scan nearly one value.
  config.radar.azimuth_count =
      int_in(keys, "azimuths", config.radar.azimuth_count, kMinScanAzimuths, 100'000);
  config.radar.range_bin_count =
      int_in(keys, "range_bins", config.radar.range_bin_count, kMinScanRangeBins, 1'000'000);
  if (static_cast<long long>(config.radar.azimuth_count) * config.radar.range_bin_count >
      kMaxScanPixels) {
    keys.fail("range_bins", fmt::format("azimuths x range_bins = {} x {} is over {} pixels a scan",
                                        config.radar.azimuth_count, config.radar.range_bin_count,
                                        kMaxScanPixels));
  }
  config.radar.range_resolution_m =
      number_in(keys, "range_resolution_m", config.radar.range_resolution_m, 0.0, 10.0);
  if (config.radar.range_bin_count * config.radar.range_resolution_m > kMaxReachM) {
    keys.fail(
        "range_resolution_m",
        fmt::format("range_bins x range_resolution_m = {} m is beyond any radar's reach "
                    "(at most {} m)",
                    config.radar.range_bin_count * config.radar.range_resolution_m, kMaxReachM));
  }
  config.radar.speckle = keys.boolean_or("speckle", config.radar.speckle);
  config.motion_distortion = keys.boolean_or("motion_distortion", config.motion_distortion);
  // The world's own checks (world_params.cpp) hold the same ranges; here they name the key.
  config.world.traffic = number_within(keys, "traffic", config.world.traffic, 0.0, 5.0);
  config.world.foliage = number_within(keys, "foliage", config.world.foliage, 0.2, 2.0);
  config.world.parked_car_churn =
      number_within(keys, "parked_car_churn", config.world.parked_car_churn, 0.0, 1.0);
  config.drive.route_blocks_x =
      int_in(keys, "route_blocks_x", config.drive.route_blocks_x, 1, kMaxRouteBlocks);
  config.drive.route_blocks_y =
      int_in(keys, "route_blocks_y", config.drive.route_blocks_y, 1, kMaxRouteBlocks);
  config.drive.route_origin_block_x =
      block_field(keys, "route_origin_block_x", config.drive.route_origin_block_x);
  config.drive.route_origin_block_y =
      block_field(keys, "route_origin_block_y", config.drive.route_origin_block_y);
  config.drive.lap_pattern = keys.string_or("lap_pattern", config.drive.lap_pattern);
  const auto lane = keys.integer_or("lane", config.drive.lane);
  if (lane < 0 || lane > 2) keys.fail("lane", fmt::format("must be 0, 1 or 2, got {}", lane));
  config.drive.lane = static_cast<int>(lane);
  // The world narrows it further (the tightest turn, half a block), checked with the drive.
  config.drive.corner_radius_m =
      number_in(keys, "corner_radius_m", config.drive.corner_radius_m, 0.0, kMaxCornerRadiusM);
  config.drive.speed_mps = number_in(keys, "speed_mps", config.drive.speed_mps, 0.0, 60.0);
  keys.finish();
  try {
    validate(config);
  } catch (const std::invalid_argument& error) {
    keys.fail("", error.what());
  }
  // Runs read it through the cache (or the Oxford layout in memory), like real data.
  return {"synthetic", [config] { return open_synthetic(config); },
          std::make_shared<const SyntheticConfig>(config)};
}

}  // namespace radarpr
