#pragma once

#include <filesystem>
#include <memory>

#include "datasets/dataset_keys.hpp"
#include "datasets/dataset_types.hpp"
#include "datasets/pose_track.hpp"
#include "datasets/real/real_dataset.hpp"
#include "datasets/scan_sequence.hpp"

namespace radarpr {

// OORD, the Oxford Offroad Radar Dataset (Navtech CTS350-X), datasets.md:
//   <root>/<site>/<date>/Navtech_CTS350-X_Radar/<t>.png   Oxford layout; rows are sometimes
//                                                         dropped, encoder bytes unreliable
//   <root>/<site>/<date>/MicrostrainMIP/gps.csv          header with timestamp, utm_northing,
//                                                         utm_easting
// The sequence key is "<site>/<date>", e.g. "bellmouth/2021-11-25-12-31-19".
struct OordOptions {
  RealDatasetOptions common;
  // Every scan is resampled to this many rows, the rows present taken as uniformly spread.
  int azimuths = 400;
};

inline constexpr double kOordRangeResolution = 0.0432;

// MicrostrainMIP/gps.csv: x = utm_easting, y = utm_northing, yaw = 0 (no heading).
PoseTrack read_oord_gps(const std::filesystem::path& path);

// Positions: global (UTM).
std::unique_ptr<ScanSequence> open_oord(const OordOptions& options);

// The "oord" dataset type: the common keys and "azimuths" (rows every scan is resampled to).
SequenceConfig parse_oord_keys(DatasetKeys& keys);

}  // namespace radarpr
