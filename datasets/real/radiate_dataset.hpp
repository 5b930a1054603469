#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>

#include "datasets/dataset_keys.hpp"
#include "datasets/dataset_types.hpp"
#include "datasets/real/real_dataset.hpp"
#include "datasets/scan_sequence.hpp"

namespace radarpr {

// RADIATE (Navtech CTS350-X), datasets.md:
//   <root>/<sequence>/Navtech_Polar/<000001>.png   576 range rows x 400 azimuth columns, no
//                                                  metadata
//   <root>/<sequence>/Navtech_Polar.txt            "Frame: 000001 Time: <unix s>" per line
// The public sequences carry no usable ground truth, so the positions are `none`: the sequence
// can be extracted and benchmarked, and evaluation refuses it. GPS_IMU_Twist.txt, when present,
// is checked against the radar clock and reported (the sample's GPS clock is ~64 s off).
struct RadiateOptions {
  RealDatasetOptions common;
};

inline constexpr double kRadiateRangeResolution = 0.173611;

// Frame number -> time (ns) from a "Frame: N Time: <unix s>" file. Throws naming file and line.
std::map<std::int64_t, std::int64_t> read_radiate_frame_times(const std::filesystem::path& path);

std::unique_ptr<ScanSequence> open_radiate(const RadiateOptions& options);

// The "radiate" dataset type: the common keys.
SequenceConfig parse_radiate_keys(DatasetKeys& keys);

}  // namespace radarpr
