#include "evaluation/config/sequence_config.hpp"

#include <fmt/format.h>

#include "datasets/scan_sequence.hpp"
#include "datasets/synthetic/cached_synthetic_sequence.hpp"
#include "datasets/synthetic/synthetic_sequence.hpp"
#include "datasets/synthetic/world/world_presets.hpp"
#include "evaluation/config/config_reader.hpp"
#include "evaluation/config/real_dataset_config.hpp"

namespace radarpr {
namespace {

int int_in(ConfigReader& reader, const std::string& key, int fallback, int low, int high) {
  const auto value = reader.integer_or(key, fallback);
  if (value < low || value > high) {
    reader.fail(key, fmt::format("must be an integer in [{}, {}], got {}", low, high, value));
  }
  return static_cast<int>(value);
}

double number_in(ConfigReader& reader, const std::string& key, double fallback, double above,
                 double at_most) {
  const double value = reader.number_or(key, fallback);
  if (!(value > above && value <= at_most)) {
    reader.fail(key, fmt::format("must be a number in ({}, {}], got {}", above, at_most, value));
  }
  return value;
}

// Bounds that keep a typo from asking for terabytes: a scan's pixels, the radar's reach (the
// world is generated out to it around the drive) and the drive's length.
constexpr int kMaxScans = 1'000'000;
constexpr int kMaxScanPixels = 1 << 24;
constexpr double kMaxReachM = 500.0;
constexpr int kMaxRouteBlocks = 50;

int block_field(ConfigReader& reader, const std::string& key, int fallback) {
  const auto value = reader.integer_or(key, fallback);
  if (value < -100'000 || value > 100'000) {
    reader.fail(key, fmt::format("must be in [-100000, 100000] blocks, got {}", value));
  }
  return static_cast<int>(value);
}

// Runs `action` and turns its std::invalid_argument into a ConfigError at `key`.
template <typename Action>
void at_key(ConfigReader& reader, const std::string& key, Action action) {
  try {
    action();
  } catch (const std::invalid_argument& error) {
    reader.fail(key, error.what());
  }
}

// {"type": "synthetic", "world": <preset>, "radar": <preset>, ...}: README, "The synthetic
// world". Presets first, then the keys that override them.
SequenceConfig parse_synthetic(ConfigReader& reader) {
  SyntheticConfig config;
  if (reader.has("radar")) {
    at_key(reader, "radar",
           [&] { config.radar = synthetic::radar_preset(reader.required_string("radar")); });
  }
  if (reader.has("world")) {
    at_key(reader, "world", [&] {
      const auto preset = synthetic::world_preset(reader.required_string("world"));
      config.city = preset.layout;
      config.world = preset.params;
      config.radar.ground_clutter = preset.ground_clutter;
      config.radar.ground_clutter_falloff_m = preset.ground_clutter_falloff_m;
    });
  }
  if (reader.has("weather")) {
    at_key(reader, "weather",
           [&] { config.weather = synthetic::weather_from(reader.required_string("weather")); });
  }
  const auto seed = reader.integer_or("seed", static_cast<std::int64_t>(config.seed));
  if (seed < 0) reader.fail("seed", fmt::format("must be >= 0, got {}", seed));
  config.seed = static_cast<std::uint64_t>(seed);
  config.session = int_in(reader, "session", config.session, 0, 1000);
  config.scan_count = int_in(reader, "scans", config.scan_count, 1, kMaxScans);
  // Fewer than 16 of either and every descriptor gives every scan nearly one value.
  config.radar.azimuth_count =
      int_in(reader, "azimuths", config.radar.azimuth_count, kMinScanAzimuths, 100'000);
  config.radar.range_bin_count =
      int_in(reader, "range_bins", config.radar.range_bin_count, kMinScanRangeBins, 1'000'000);
  if (static_cast<long long>(config.radar.azimuth_count) * config.radar.range_bin_count >
      kMaxScanPixels) {
    reader.fail(
        "range_bins",
        fmt::format("azimuths x range_bins = {} x {} is over {} pixels a scan",
                    config.radar.azimuth_count, config.radar.range_bin_count, kMaxScanPixels));
  }
  config.radar.range_resolution_m =
      number_in(reader, "range_resolution_m", config.radar.range_resolution_m, 0.0, 10.0);
  if (config.radar.range_bin_count * config.radar.range_resolution_m > kMaxReachM) {
    reader.fail(
        "range_resolution_m",
        fmt::format("range_bins x range_resolution_m = {} m is beyond any radar's reach "
                    "(at most {} m)",
                    config.radar.range_bin_count * config.radar.range_resolution_m, kMaxReachM));
  }
  config.radar.speckle = reader.boolean_or("speckle", config.radar.speckle);
  config.motion_distortion = reader.boolean_or("motion_distortion", config.motion_distortion);
  config.world.traffic = reader.number_or("traffic", config.world.traffic);
  config.world.foliage = reader.number_or("foliage", config.world.foliage);
  config.world.parked_car_churn =
      reader.number_or("parked_car_churn", config.world.parked_car_churn);
  config.drive.route_blocks_x =
      int_in(reader, "route_blocks_x", config.drive.route_blocks_x, 1, kMaxRouteBlocks);
  config.drive.route_blocks_y =
      int_in(reader, "route_blocks_y", config.drive.route_blocks_y, 1, kMaxRouteBlocks);
  config.drive.route_origin_block_x =
      block_field(reader, "route_origin_block_x", config.drive.route_origin_block_x);
  config.drive.route_origin_block_y =
      block_field(reader, "route_origin_block_y", config.drive.route_origin_block_y);
  config.drive.lap_pattern = reader.string_or("lap_pattern", config.drive.lap_pattern);
  const auto lane = reader.integer_or("lane", config.drive.lane);
  if (lane < 0 || lane > 2) reader.fail("lane", fmt::format("must be 0, 1 or 2, got {}", lane));
  config.drive.lane = static_cast<int>(lane);
  config.drive.corner_radius_m = reader.number_or("corner_radius_m", config.drive.corner_radius_m);
  config.drive.speed_mps = number_in(reader, "speed_mps", config.drive.speed_mps, 0.0, 60.0);
  reader.finish();
  try {
    validate(config);
  } catch (const std::invalid_argument& error) {
    throw ConfigError(reader.path(), error.what());
  }
  // Runs read it through the cache (or the Oxford layout in memory), like real data.
  return {"synthetic", [config] { return open_synthetic(config); },
          std::make_shared<const SyntheticConfig>(config)};
}

}  // namespace

SequenceConfig parse_sequence_config(ConfigReader reader) {
  const std::string type = reader.required_string("type");
  if (type == "synthetic") return parse_synthetic(reader);
  if (is_real_dataset_type(type)) return parse_real_dataset_config(type, reader);
  reader.fail("type", fmt::format("unknown sequence type '{}' (known: synthetic, mulran, oxford, "
                                  "boreas, oord, radiate, folder)",
                                  type));
}

}  // namespace radarpr
