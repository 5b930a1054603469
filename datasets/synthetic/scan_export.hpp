#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "datasets/byte_image.hpp"
#include "datasets/polar_image.hpp"
#include "datasets/scan_sequence.hpp"

namespace radarpr::synthetic {

// Writing scans in the layout the real datasets use, so generated data goes through the same
// loaders and decoders as real data (the `folder` type):
//   <folder>/scans/<t_us>.png   Oxford layout: per azimuth row an int64 LE µs timestamp, a
//                               uint16 LE encoder count (0..5599), the valid flag 255, then the
//                               range bins; named by the scan's (middle azimuth's) time in µs
//   <folder>/poses.csv          timestamp,x,y,yaw (µs, metres, radians), one row per scan

// The Oxford-layout image of one scan: A x (11 + R) bytes. Needs azimuth times; encoder
// counts come from the azimuth angles. Throws std::invalid_argument otherwise.
ByteImage to_oxford_layout(const PolarImage& image);

// The file of scan `record` inside `folder`/scans.
std::filesystem::path scan_png_path(const std::filesystem::path& folder, const ScanRecord& record);

// Writes one scan as an Oxford-layout PNG (creating folders). Throws std::runtime_error naming
// the file when it cannot be written.
void write_oxford_png(const std::filesystem::path& path, const PolarImage& image);

// Writes <folder>/poses.csv for `records`, every number exactly (shortest round-trip decimal),
// so that reading it back gives the same poses. Throws std::runtime_error naming the file.
void write_folder_poses(const std::filesystem::path& folder,
                        const std::vector<ScanRecord>& records);

// Writes `image` as a PNG (default compression, no extra chunks: the same pixels always give the
// same bytes) or `text`, through a temporary file renamed into place, so a reader - another
// thread or process sharing a cache - sees the whole file or none. Creates the folders. Throws
// std::runtime_error naming the file.
void write_png_atomically(const std::filesystem::path& path, const ByteImage& image);
void write_text_atomically(const std::filesystem::path& path, const std::string& text);

}  // namespace radarpr::synthetic
