#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "datasets/scan_sequence.hpp"
#include "datasets/synthetic/drive/drive_path.hpp"
#include "datasets/synthetic/radar/radar_presets.hpp"
#include "datasets/synthetic/radar/radar_renderer.hpp"
#include "datasets/synthetic/world/synthetic_world.hpp"
#include "datasets/synthetic/world/world_params.hpp"

namespace radarpr {

// A synthetic radar dataset: a procedural world (synthetic::WorldParams on the street grid of
// synthetic::CityLayout) driven in laps (synthetic::DriveParams) by a simulated spinning radar
// (synthetic::RadarModel) in some weather. Everything is a deterministic function of this config.
struct SyntheticConfig {
  std::uint64_t seed = 7;  // the city and every noise stream
  // Sessions of one seed share the city; each drives slightly off the lane centre (lateral
  // offset of ~session_offset_m), at a different speed profile, with its own heading and
  // speckle noise, and starts a day later: for multi-session evaluation. At most 1000.
  int session = 0;
  int scan_count = 600;  // at most 10^6
  // Whole microseconds (as real Navtech stamps) between 2000 and 2100.
  std::int64_t start_time_ns = 1'700'000'000'000'000'000;  // 2023-11-14T22:13:20Z
  synthetic::RadarModel radar;
  synthetic::CityLayout city;  // the street grid of every world kind
  synthetic::WorldParams world;
  synthetic::DriveParams drive;
  synthetic::Weather weather = synthetic::Weather::clear;
  // Each azimuth is measured from where the sensor is at that moment of the sweep.
  bool motion_distortion = true;
};

// Throws std::invalid_argument naming the first bad field.
void validate(const SyntheticConfig& config);

// Scans are rendered on demand in load_image(); the same index always gives the same pixels,
// whatever the call order or thread (the noise of scan i is seeded by (seed, session, i)).
class SyntheticSequence : public ScanSequence {
 public:
  explicit SyntheticSequence(SyntheticConfig config);

  std::string name() const override;
  std::string fingerprint() const override;
  const std::vector<ScanRecord>& records() const override { return records_; }
  // Scan `index` with azimuth times spread over one revolution, the middle azimuth (row A/2) at
  // the record's timestamp, the sensor moving along the drive during the sweep and the moving
  // vehicles where they are at that time. Throws std::out_of_range for a bad index.
  PolarImage load_image(std::size_t index) const override;
  // Poses are exact and share the town's frame across sessions: global. Geometry comes from the
  // config, so describing needs no rendering.
  DatasetReport describe() const override;

  const SyntheticConfig& config() const { return config_; }
  const synthetic::World& world() const { return world_; }
  // The sensor's motion over scan `index`'s revolution (still when motion_distortion is off).
  synthetic::SensorSweep sweep(std::size_t index) const;
  // The moving vehicles around the sensor at scan `index`'s time (what load_image renders
  // beside world()).
  synthetic::World traffic(std::size_t index) const;

 private:
  SyntheticConfig config_;
  std::vector<ScanRecord> records_;
  synthetic::World world_;
  synthetic::RadarModel effective_radar_;  // config radar in the config weather
};

}  // namespace radarpr
