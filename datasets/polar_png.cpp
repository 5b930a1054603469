#include "datasets/polar_png.hpp"

#include <cstdint>
#include <cstring>
#include <exception>
#include <numbers>
#include <optional>
#include <span>
#include <stdexcept>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "datasets/png_codec.hpp"
#include "datasets/png_header.hpp"

namespace radarpr {
namespace {

// A PNG file larger than this is refused unread: the largest accepted image (kMaxPngPixels, at
// 8 bytes a pixel) stored uncompressed, with room for chunk overhead.
constexpr std::uintmax_t kMaxPngFileBytes = kMaxPngPixels * 8 + (std::uintmax_t{1} << 20);

// Plausible Unix times: 2000-01-01 .. 2100-01-01 in seconds. The µs and ns ranges this spans
// do not overlap, which is what lets the unit be told from the magnitude.
constexpr std::int64_t kEarliestUnixS = 946'684'800;
constexpr std::int64_t kLatestUnixS = 4'102'444'800;

enum class StampUnit { none, microseconds, nanoseconds };

StampUnit stamp_unit(std::int64_t stamp) {
  if (stamp >= kEarliestUnixS * 1'000'000 && stamp < kLatestUnixS * 1'000'000) {
    return StampUnit::microseconds;
  }
  if (stamp >= kEarliestUnixS * 1'000'000'000 && stamp < kLatestUnixS * 1'000'000'000) {
    return StampUnit::nanoseconds;
  }
  return StampUnit::none;
}

// Assembled byte by byte so the result does not depend on the host's endianness.
template <typename T>
T read_little_endian(const std::uint8_t* bytes) {
  std::uint64_t value = 0;
  for (std::size_t i = 0; i < sizeof(T); ++i) value |= std::uint64_t{bytes[i]} << (8 * i);
  return static_cast<T>(value);
}

// What a PNG that is not 8-bit greyscale holds, for the error: 16-bit samples are told apart,
// narrower ones were widened to 8 bits by the decoder.
std::string describe_png_format(const PngFormat& format) {
  return fmt::format("{} with {} channel{}", format.bit_depth == 16 ? "16-bit" : "8-bit",
                     format.channels, format.channels == 1 ? "" : "s");
}

PolarPngLayout detect_layout(int width, int height, const std::string& source) {
  if (width > height) return PolarPngLayout::oxford;
  if (height > width) return PolarPngLayout::mulran_native;
  throw std::runtime_error(fmt::format(
      "{}: cannot tell the polar layout of a square {}x{} image (expected width > height for "
      "the Oxford layout, azimuth rows, or height > width for the MulRan native layout, range "
      "rows); name the layout: radarpr extract --layout oxford|mulran_native, or \"layout\" in "
      "a folder dataset's config",
      source, width, height));
}

// Turns a PNG's rows, as they are decoded, into a scan with one row per azimuth: an Oxford
// layout's rows lose their metadata bytes (read on the way), a native layout's strips are
// transposed into their azimuth columns. No whole copy of the PNG's image is made. A fault is
// kept and the decode stopped; finish() throws it.
class PolarScanBuilder final : public PngRowSink {
 public:
  PolarScanBuilder(const PolarPngOptions& options, const std::string& source, DecodedPolarPng& out)
      : options_(options), source_(source), out_(out) {}

  bool start(int width, int height) override {
    return keep_failure([&] { begin(width, height); });
  }

  bool take_rows(int first, int count, const std::uint8_t* rows) override {
    return keep_failure([&] {
      if (out_.layout == PolarPngLayout::oxford) {
        for (int i = 0; i < count; ++i) {
          oxford_row(first + i, rows + static_cast<std::size_t>(i) * width_);
        }
      } else {
        transpose_into(rows, count, static_cast<int>(width_), out_.image.power, first);
      }
    });
  }

  // Throws the fault that stopped the decode, if one did.
  void finish() {
    if (failure_) std::rethrow_exception(failure_);
    if (out_.layout == PolarPngLayout::oxford && options_.use_row_metadata) {
      out_.timestamp_ns =
          out_.image.azimuth_times_ns[static_cast<std::size_t>(out_.image.azimuth_count() / 2)];
    }
  }

 private:
  template <typename Step>
  bool keep_failure(Step step) {
    try {
      step();
      return true;
    } catch (...) {
      failure_ = std::current_exception();
      return false;
    }
  }

  void begin(int width, int height) {
    if (width == 0 || height == 0)
      throw std::runtime_error(fmt::format("{}: empty image", source_));
    width_ = static_cast<std::size_t>(width);
    out_.layout = options_.layout ? *options_.layout : detect_layout(width, height, source_);
    if (options_.layout) check_polar_png_shape(width, height, out_.layout, source_);
    if (out_.layout == PolarPngLayout::mulran_native) {
      // Native rows are range bins and columns azimuths: transposed to azimuth rows.
      out_.image.power = ByteImage::uninitialised(width, height);
      out_.image.azimuths_rad = uniform_azimuths(width);
      return;
    }
    if (width <= kOxfordMetadataColumns) {
      throw std::runtime_error(fmt::format(
          "{}: image too small for the Oxford layout: {} columns, expected more than {} (8 bytes "
          "time, 2 bytes encoder, 1 byte flag, then range bins)",
          source_, width, kOxfordMetadataColumns));
    }
    out_.image.power = ByteImage::uninitialised(height, width - kOxfordMetadataColumns);
    if (!options_.use_row_metadata) {
      out_.image.azimuths_rad = uniform_azimuths(height);
      return;
    }
    const auto azimuths = static_cast<std::size_t>(height);
    out_.image.azimuths_rad.resize(azimuths);
    out_.image.azimuth_times_ns.resize(azimuths);
    out_.row_flags.resize(azimuths);
  }

  void oxford_row(int a, const std::uint8_t* row) {
    std::memcpy(out_.image.power.row(a), row + kOxfordMetadataColumns,
                width_ - kOxfordMetadataColumns);
    if (!options_.use_row_metadata) return;
    const auto stamp = read_little_endian<std::int64_t>(row);
    const auto encoder = read_little_endian<std::uint16_t>(row + 8);
    if (encoder >= kNavtechEncoderCounts) {
      throw std::runtime_error(fmt::format(
          "{}: row {} has encoder value {}, expected 0..{} (is this really an Oxford-layout polar "
          "PNG?)",
          source_, a, encoder, kNavtechEncoderCounts - 1));
    }
    const StampUnit unit = stamp_unit(stamp);
    if (unit == StampUnit::none) {
      throw std::runtime_error(fmt::format(
          "{}: row {} has timestamp {}, expected a Unix time in µs or ns between 2000 and 2100 "
          "(bytes 0-7 of each row, little-endian)",
          source_, a, stamp));
    }
    if (a == 0) {
      scan_unit_ = unit;
    } else if (unit != scan_unit_) {
      throw std::runtime_error(
          fmt::format("{}: row {} has timestamp {} in a different unit (µs vs ns) from row 0's",
                      source_, a, stamp));
    }
    const auto index = static_cast<std::size_t>(a);
    out_.image.azimuth_times_ns[index] = unit == StampUnit::microseconds ? stamp * 1000 : stamp;
    out_.image.azimuths_rad[index] =
        2.0 * std::numbers::pi * static_cast<double>(encoder) / kNavtechEncoderCounts;
    out_.row_flags[index] = row[10];
  }

  const PolarPngOptions& options_;
  const std::string& source_;
  DecodedPolarPng& out_;
  std::size_t width_ = 0;
  StampUnit scan_unit_ = StampUnit::none;
  std::exception_ptr failure_;
};

// A file whose bytes CheckedPngFile refused: the message is complete, the decoder's failure
// message around it is not added.
class RefusedPngFile : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

void check_range_resolution(const PolarPngOptions& options, const std::string& source) {
  if (!(options.range_resolution_m > 0.0)) {
    throw std::invalid_argument(
        fmt::format("{}: range resolution must be a positive number of metres per bin, got {}",
                    source, options.range_resolution_m));
  }
}

}  // namespace

std::string_view to_string(PolarPngLayout layout) {
  switch (layout) {
    case PolarPngLayout::oxford:
      return "oxford";
    case PolarPngLayout::mulran_native:
      return "mulran_native";
  }
  return "unknown";
}

void check_polar_png_shape(int width, int height, PolarPngLayout layout,
                           const std::string& source) {
  // A square image passes either check: its layout cannot be seen, only named.
  if (layout == PolarPngLayout::oxford && (width < height || width <= kOxfordMetadataColumns)) {
    throw std::runtime_error(fmt::format(
        "{}: {} wide x {} high, expected the Oxford layout: one row per azimuth, not higher than "
        "wide and wider than {} (8 bytes time, 2 bytes encoder, 1 byte flag, then range bins); a "
        "range x azimuth image or a transposed scan is not one",
        source, width, height, kOxfordMetadataColumns));
  }
  if (layout == PolarPngLayout::mulran_native && height < width) {
    throw std::runtime_error(fmt::format(
        "{}: {} wide x {} high, expected the range x azimuth layout (MulRan polar/, RADIATE): "
        "one row per range bin, one column per azimuth, not wider than high; an Oxford-layout "
        "scan (azimuth rows) or a transposed one is not one",
        source, width, height));
  }
}

std::optional<double> known_range_resolution(int range_bins) {
  if (range_bins == 3360) return 200.0 / 3360.0;
  if (range_bins == 3768) return 0.0432;
  return std::nullopt;
}

std::optional<std::int64_t> unix_stamp_to_ns(std::int64_t stamp) {
  switch (stamp_unit(stamp)) {
    case StampUnit::microseconds:
      return stamp * 1000;
    case StampUnit::nanoseconds:
      return stamp;
    case StampUnit::none:
      break;
  }
  return std::nullopt;
}

DecodedPolarPng decode_polar_png(const ByteImage& raw, const PolarPngOptions& options,
                                 const std::string& source) {
  check_range_resolution(options, source);
  DecodedPolarPng out;
  PolarScanBuilder builder(options, source, out);
  if (builder.start(raw.cols(), raw.rows())) builder.take_rows(0, raw.rows(), raw.data());
  builder.finish();
  out.image.range_resolution_m = options.range_resolution_m;
  return out;
}

DecodedPolarPng read_polar_png(const std::filesystem::path& path, const PolarPngOptions& options) {
  const std::string source = path.string();
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    throw std::runtime_error(fmt::format(
        "{}: {}, expected a polar radar PNG file", source,
        std::filesystem::exists(path, error) ? "not a regular file" : "file not found"));
  }
  // A header or chunk length that the file cannot back is refused with the file's name before
  // the decoder allocates what it claims, and a damaged chunk before the decoder sees its bytes
  // (CheckedPngFile), without the whole file in memory.
  const auto size = std::filesystem::file_size(path, error);
  if (error || size > kMaxPngFileBytes) {
    throw std::runtime_error(
        fmt::format("{}: {}, expected a polar radar PNG file of at most {} bytes", source,
                    error ? "cannot be read" : fmt::format("{} bytes", size), kMaxPngFileBytes));
  }
  auto not_decodable = [](const std::runtime_error& failure) {
    return RefusedPngFile(
        fmt::format("{} (could not decode the image), expected an 8-bit grayscale polar radar PNG",
                    failure.what()));
  };
  std::optional<CheckedPngFile> file;
  try {
    file.emplace(path);
  } catch (const std::runtime_error& failure) {
    throw not_decodable(failure);
  }
  check_range_resolution(options, source);
  DecodedPolarPng out;
  PolarScanBuilder builder(options, source, out);
  const PngByteSource read = [&](std::uint8_t* into, std::size_t count) {
    try {
      file->read(into, count);
    } catch (const std::runtime_error& failure) {
      throw not_decodable(failure);
    }
  };
  PngFormat format;
  try {
    format = decode_png_rows(read, builder, source, /*checksums_verified=*/true);
  } catch (const RefusedPngFile&) {
    throw;  // said in full where the file's bytes were refused
  } catch (const std::runtime_error& failure) {
    throw std::runtime_error(
        fmt::format("{}, expected an 8-bit grayscale polar radar PNG", failure.what()));
  }
  if (!format.decoded) {
    throw std::runtime_error(
        fmt::format("{}: image is {}, expected 8-bit single-channel (grayscale) polar power",
                    source, describe_png_format(format)));
  }
  builder.finish();
  out.image.range_resolution_m = options.range_resolution_m;
  return out;
}

}  // namespace radarpr
