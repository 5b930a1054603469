#pragma once

#include <cstdint>
#include <filesystem>

namespace radarpr {

// What a PNG file says about itself without being decoded: its IHDR chunk.
struct PngHeader {
  int width = 0;
  int height = 0;
  int bit_depth = 0;    // bits per sample: 8 for the radar PNGs
  int colour_type = 0;  // 0 = grayscale
};

// Reads the first 26 bytes (signature, IHDR) and the last 12 (the IEND chunk) of a PNG: a cheap
// check of every scan when a sequence opens, so a truncated or wrong-size file is found before
// hours of extraction rather than during them. Throws std::runtime_error naming the file when it
// cannot be read, is not a PNG, has no IHDR chunk first, or does not end with an IEND chunk
// (truncated, or still being copied).
PngHeader read_png_header(const std::filesystem::path& path);

}  // namespace radarpr
