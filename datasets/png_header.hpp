#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

namespace radarpr {

// What a PNG file says about itself without being decoded: its IHDR chunk.
struct PngHeader {
  int width = 0;
  int height = 0;
  int bit_depth = 0;    // bits per sample: 8 for the radar PNGs
  int colour_type = 0;  // 0 = grayscale
};

// The largest radar PNG accepted: no sensor comes near (Navtech scans are at most a few thousand
// range bins by a few thousand azimuths), and a header claiming more is corrupt or hostile. A
// decode is thereby bounded (2^25 pixels of at most 8 bytes: 256 MiB) by these limits, never by
// what a header claims.
inline constexpr std::uint32_t kMaxPngSide = 32768;
inline constexpr std::uint64_t kMaxPngPixels = std::uint64_t{1} << 25;

// Checks a header against the limits above and against the file's size (deflate compresses at
// most 1032:1, so a small file cannot hold a huge image). Throws std::runtime_error naming
// `name` and the limit.
void check_png_geometry(const PngHeader& header, std::uint64_t file_size, const std::string& name);

// Checks a whole PNG in memory before it is handed to a decoder: the signature, the IHDR chunk
// (geometry as above), and every chunk's declared length against the bytes left, up to an IEND
// chunk. Returns the header; throws std::runtime_error naming `name` and the first fault.
PngHeader check_png_bytes(const std::uint8_t* data, std::size_t size, const std::string& name);

// Reads the first 26 bytes (signature, IHDR) and the last 12 (the IEND chunk) of a PNG: a cheap
// check of every scan when a sequence opens, so a truncated or wrong-size file is found before
// hours of extraction rather than during them. Throws std::runtime_error naming the file when it
// cannot be read, is not a PNG, has no IHDR chunk first, or does not end with an IEND chunk
// (truncated, or still being copied); or when its geometry or the length of a chunk before the
// image data fails the checks above.
PngHeader read_png_header(const std::filesystem::path& path);

}  // namespace radarpr
