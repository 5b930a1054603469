#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "datasets/byte_image.hpp"
#include "datasets/polar_image.hpp"

namespace radarpr {

// How a polar radar PNG stores its scan (datasets.md).
enum class PolarPngLayout {
  // One row per azimuth; bytes 0-7 int64 LE timestamp, 8-9 uint16 LE encoder (0..5599),
  // 10 valid flag, 11.. range-bin power (Oxford, Boreas, OORD, MulRan polar_oxford_form).
  oxford,
  // MulRan's own polar/ images: one row per range bin, one column per azimuth, no metadata.
  mulran_native,
};

std::string_view to_string(PolarPngLayout layout);

// Geometry constants of the Oxford layout.
inline constexpr int kOxfordMetadataColumns = 11;
inline constexpr int kNavtechEncoderCounts = 5600;  // encoder counts per revolution

struct PolarPngOptions {
  // Metres per range bin. Required (> 0): PNGs do not carry it and it differs per sensor.
  double range_resolution_m = 0.0;
  // Skip shape-based detection and decode with this layout; the image must still have the
  // layout's orientation (check_polar_png_shape).
  std::optional<PolarPngLayout> layout;
  // Oxford layout only: read per-row timestamps and encoder angles. Turn off for sources whose
  // metadata bytes are unreliable (OORD): azimuths become uniform and no times are reported.
  bool use_row_metadata = true;
};

struct DecodedPolarPng {
  PolarImage image;  // A x R, row = azimuth; metadata columns stripped
  PolarPngLayout layout = PolarPngLayout::oxford;
  // Scan time in ns. Oxford layout: the middle azimuth's time (row A/2), the Boreas convention.
  // Other sources name files differently (Oxford RobotCar: the first azimuth's time; MulRan: the
  // LAST azimuth's): loaders that match poses by file name should use the name instead.
  // Native layout: none.
  std::optional<std::int64_t> timestamp_ns;
  // Oxford layout with row metadata: byte 10 of every row (255 = real azimuth, other values =
  // interpolated; Boreas-RT stores the chirp direction there). Empty otherwise.
  std::vector<std::uint8_t> row_flags;
};

// Throws std::runtime_error naming `source` unless a `width` x `height` image can hold `layout`:
// the Oxford layout needs width >= height (azimuth rows) and width > 11 (the metadata bytes), the
// native layout height >= width (range rows); a square image can hold either. A forced layout is
// checked so that a scan of the other layout (or a transposed one) is refused instead of read as
// 3371 azimuths x 400 bins.
void check_polar_png_shape(int width, int height, PolarPngLayout layout, const std::string& source);

// Reads and decodes one polar PNG. Throws std::runtime_error naming the file and what was
// expected when it is missing, undecodable, not 8-bit single channel, too small, or carries
// out-of-range metadata; std::invalid_argument for bad options.
DecodedPolarPng read_polar_png(const std::filesystem::path& path, const PolarPngOptions& options);

// The same decoding on a PNG's pixels already in memory (as decode_png returns them); `source`
// names it in error messages.
DecodedPolarPng decode_polar_png(const ByteImage& raw, const PolarPngOptions& options,
                                 const std::string& source);

// Metres per range bin of the sensors whose bin count identifies them (datasets.md): 200/3360
// for 3360 bins (MulRan's CIR204-H), 0.0432 for 3768 (Oxford's CTS350-X); nullopt for others.
std::optional<double> known_range_resolution(int range_bins);

// Unix-time stamps come as µs (Oxford, Boreas) or ns (MulRan oxford form); both are told apart
// by magnitude. Returns ns, or nullopt when the value is a plausible time in neither unit
// (outside 2000-01-01 .. 2100-01-01).
std::optional<std::int64_t> unix_stamp_to_ns(std::int64_t stamp);

}  // namespace radarpr
