#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "datasets/dataset_keys.hpp"
#include "datasets/dataset_report.hpp"
#include "datasets/dataset_types.hpp"
#include "datasets/polar_png.hpp"
#include "datasets/pose_track.hpp"
#include "datasets/real/real_dataset.hpp"
#include "datasets/scan_sequence.hpp"

namespace radarpr {

// A generic layout for anyone's own data (README, "Real datasets"):
//   <root>/<sequence>/scans/<t>.png   polar PNGs in either layout, named by their Unix time in
//                                     µs or ns
//   <root>/<sequence>/poses.csv       header "timestamp,x,y[,yaw]": Unix time (µs or ns, or
//                                     seconds with a decimal point), metres, radians
struct FolderOptions {
  RealDatasetOptions common;                    // common.range_resolution_m is required
  std::string scans = "scans";                  // relative to the sequence folder
  std::string poses = "poses.csv";              // relative to the sequence folder; empty = no poses
  std::optional<PolarPngLayout> layout;         // unset = told from each image's shape
  PositionFrame frame = PositionFrame::global;  // global or local
};

// Throws std::runtime_error naming the file and line of a bad row or a missing column.
PoseTrack read_folder_poses(const std::filesystem::path& path);

std::unique_ptr<ScanSequence> open_folder(const FolderOptions& options);

// The "folder" dataset type: the common keys, "scans", "poses", "layout", "position_frame";
// range_resolution_m is required.
SequenceConfig parse_folder_keys(DatasetKeys& keys);

}  // namespace radarpr
