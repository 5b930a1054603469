#pragma once

#include <filesystem>
#include <memory>

#include "datasets/dataset_keys.hpp"
#include "datasets/dataset_types.hpp"
#include "datasets/pose_track.hpp"
#include "datasets/real/real_dataset.hpp"
#include "datasets/scan_sequence.hpp"

namespace radarpr {

// MulRan (DCC, KAIST, Riverside, Sejong; Navtech CIR204-H), datasets.md:
//   <root>/<sequence>/sensor_data/radar/polar/<t_ns>.png              native: range rows x 400
//   <root>/<sequence>/sensor_data/radar/polar_oxford_form/<t_ns>.png  Oxford layout, ns stamps
//   <root>/<sequence>/global_pose.csv   t_ns + row-major 3x4 [R|t], no header
// Files are named by the last azimuth's time; the pose is interpolated there.
enum class MulranPolarFolder {
  automatic,          // polar/ when it exists (every sequence has it), else polar_oxford_form/
  polar,              // the native images
  polar_oxford_form,  // the Oxford-layout copies (with per-azimuth times and encoder angles)
};

struct MulranOptions {
  RealDatasetOptions common;
  MulranPolarFolder folder = MulranPolarFolder::automatic;
};

inline constexpr double kMulranRangeResolution = 200.0 / 3360.0;  // 0.0595238 m/bin

// global_pose.csv: x = column 4, y = column 8 (0-based, after the time), yaw = atan2(R10, R00).
// Throws std::runtime_error naming the file and line of a bad row.
PoseTrack read_mulran_global_pose(const std::filesystem::path& path);

// Positions: global (every MulRan sequence of a place shares the frame).
std::unique_ptr<ScanSequence> open_mulran(const MulranOptions& options);

// The "mulran" dataset type: the common keys and "polar" (auto, polar, polar_oxford_form).
SequenceConfig parse_mulran_keys(DatasetKeys& keys);

}  // namespace radarpr
