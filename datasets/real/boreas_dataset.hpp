#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>

#include "datasets/dataset_keys.hpp"
#include "datasets/dataset_types.hpp"
#include "datasets/pose_track.hpp"
#include "datasets/real/real_dataset.hpp"
#include "datasets/scan_sequence.hpp"

namespace radarpr {

// Boreas (Navtech CIR304-H; Boreas-RT: RAS6), datasets.md:
//   <root>/<sequence>/radar/<t>.png                  Oxford layout, named by the middle azimuth's
//                                                    time (µs or ns, detected)
//   <root>/<sequence>/applanix/radar_poses.csv       one pose per scan, header GPSTime, easting,
//                                                    northing, ..., heading
struct BoreasOptions {
  RealDatasetOptions common;
};

// Sequences recorded from this Unix time on (2021-09-21) have the finer range resolution.
inline constexpr std::int64_t kBoreasResolutionChangeUnixS = 1'632'182'400;
inline constexpr double kBoreasEarlyRangeResolution = 0.0596;
inline constexpr double kBoreasLateRangeResolution = 0.04381;

// Resolution by recording date (the first scan's time).
double boreas_range_resolution(std::int64_t first_scan_ns);

// radar_poses.csv: x = easting, y = northing, yaw = heading; GPSTime in µs or ns (detected).
PoseTrack read_boreas_radar_poses(const std::filesystem::path& path);

// Positions: global (UTM).
std::unique_ptr<ScanSequence> open_boreas(const BoreasOptions& options);

// The "boreas" dataset type: the common keys.
SequenceConfig parse_boreas_keys(DatasetKeys& keys);

}  // namespace radarpr
