#pragma once

#include <filesystem>
#include <memory>

#include "datasets/dataset_keys.hpp"
#include "datasets/dataset_types.hpp"
#include "datasets/pose_track.hpp"
#include "datasets/real/real_dataset.hpp"
#include "datasets/scan_sequence.hpp"

namespace radarpr {

// Oxford Radar RobotCar (Navtech CTS350-X), datasets.md:
//   <root>/<run>/radar/<t_us>.png   Oxford layout, named by the first azimuth's time
//   <root>/<run>/radar.timestamps   "<t_us> <valid>" per line (cross-checked when present)
//   <root>/<run>/gps/ins.csv, gps/gps.csv   UTM northing/easting: global positions
//   <root>/<run>/gt/radar_odometry.csv      relative SE(2) poses: integrated, local positions
enum class OxfordPoseSource {
  automatic,  // ins.csv if it has rows, else gps.csv, else the integrated odometry
  ins,
  gps,
  odometry,
};

struct OxfordOptions {
  RealDatasetOptions common;
  OxfordPoseSource poses = OxfordPoseSource::automatic;
};

// The official SDK's value (the dataset documentation says 0.0438).
inline constexpr double kOxfordRangeResolution = 0.0432;

// gps/ins.csv: x = easting, y = northing, yaw = pi/2 - yaw (the INS heading is clockwise from
// north; Pose2D yaw is counter-clockwise from east).
PoseTrack read_oxford_ins(const std::filesystem::path& path);
// gps/gps.csv: x = easting, y = northing; GPS carries no heading, so yaw = 0.
PoseTrack read_oxford_gps(const std::filesystem::path& path);
// gt/radar_odometry.csv: each row is the pose of the source scan in the destination (previous)
// scan's frame; chaining them from the first destination at the origin gives one pose per scan,
// keyed by the radar timestamps (the scans' file names). Throws naming the line where the chain
// breaks (a destination that is not the previous row's source).
PoseTrack integrate_oxford_radar_odometry(const std::filesystem::path& path);

std::unique_ptr<ScanSequence> open_oxford(const OxfordOptions& options);

// The "oxford" dataset type: the common keys and "poses" (auto, ins, gps, odometry).
SequenceConfig parse_oxford_keys(DatasetKeys& keys);

}  // namespace radarpr
