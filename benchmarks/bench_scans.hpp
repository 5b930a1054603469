#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "datasets/polar_image.hpp"
#include "datasets/polar_png.hpp"

namespace radarpr::bench {

// A scan the extraction benchmarks run on, with the PNG file it is decoded from.
struct BenchScan {
  std::string label;   // e.g. "400x3360": names the scan in benchmark names and tables
  std::string radar;   // the sensor whose geometry it has, e.g. "Navtech CIR204-H (MulRan)"
  std::string source;  // where the pixels come from, for the report
  bool real = false;   // a recorded scan, or a synthetic one
  std::filesystem::path png;
  PolarPngOptions options;  // how read_polar_png decodes `png`
  std::uintmax_t png_bytes = 0;
  PolarImage image;  // `png` decoded once
};

// The two scan geometries of the ReFeree paper: 400 x 3360 (MulRan's CIR204-H, MulRan's native
// polar PNG) and 400 x 3768 (Oxford's CTS350-X, Oxford-layout PNG). Each is a real sample under
// `real_data_root` (the shared data folder: referee_mulran_kaist03/native/000000.png, the first
// scan of oxford_radar_robotcar_tiny_radarslampy/radar/) when present, otherwise a synthetic scan
// of that geometry written as a PNG of the same layout into `scratch_folder` (created).
std::vector<BenchScan> prepare_bench_scans(const std::filesystem::path& real_data_root,
                                           const std::filesystem::path& scratch_folder);

// A synthetic scan of `range_bins` bins at `range_resolution_m` (the synthetic town's first scan).
PolarImage synthetic_bench_image(int range_bins, double range_resolution_m);

// Writes `image` as a PNG of `layout`: MulRan native (range rows, azimuth columns) or Oxford
// (azimuth rows after 11 bytes of time, encoder and flag; times in µs from `start_time_us`).
// Throws std::runtime_error when the file cannot be written.
void write_polar_png(const PolarImage& image, PolarPngLayout layout,
                     const std::filesystem::path& path, std::int64_t start_time_us);

}  // namespace radarpr::bench
