#include "datasets/synthetic/scan_export.hpp"

#include <cmath>
#include <cstdint>
#include <fstream>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <thread>

#include <unistd.h>

#include <fmt/format.h>

#include "datasets/png_codec.hpp"
#include "datasets/polar_png.hpp"

namespace radarpr::synthetic {
namespace {

template <typename T>
void put_little_endian(std::uint8_t* out, T value) {
  auto bits = static_cast<std::uint64_t>(value);
  for (std::size_t b = 0; b < sizeof(T); ++b, bits >>= 8) {
    out[b] = static_cast<std::uint8_t>(bits & 0xFF);
  }
}

// A name no other writer uses at the same time: this process and thread.
std::filesystem::path temporary_beside(const std::filesystem::path& path) {
  const std::size_t thread = std::hash<std::thread::id>{}(std::this_thread::get_id());
  return path.parent_path() /
         fmt::format(".{}.tmp-{}-{:x}", path.filename().string(), ::getpid(), thread);
}

void write_bytes_atomically(const std::filesystem::path& path, const std::uint8_t* data,
                            std::size_t size) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  const std::filesystem::path temporary = temporary_beside(path);
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!out.flush()) {
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
      throw std::runtime_error(fmt::format("{}: cannot write the file", path.string()));
    }
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    const std::string reason = error.message();
    std::filesystem::remove(temporary, error);
    throw std::runtime_error(fmt::format("{}: cannot write the file: {}", path.string(), reason));
  }
}

std::int64_t to_us(std::int64_t ns) {
  // Floor division: the stamps are positive Unix times.
  return ns / 1000;
}

}  // namespace

ByteImage to_oxford_layout(const PolarImage& image) {
  const int azimuths = image.azimuth_count();
  const int bins = image.range_bin_count();
  if (image.power.empty()) {
    throw std::invalid_argument("Oxford layout: the scan must be a non-empty image");
  }
  if (image.azimuth_times_ns.size() != static_cast<std::size_t>(azimuths) ||
      image.azimuths_rad.size() != static_cast<std::size_t>(azimuths)) {
    throw std::invalid_argument(fmt::format(
        "Oxford layout: the scan needs one time and one angle per azimuth row ({}), got {} and {}",
        azimuths, image.azimuth_times_ns.size(), image.azimuths_rad.size()));
  }
  // Every byte of every row is written below.
  ByteImage out = ByteImage::uninitialised(azimuths, kOxfordMetadataColumns + bins);
  for (int a = 0; a < azimuths; ++a) {
    std::uint8_t* row = out.row(a);
    const auto index = static_cast<std::size_t>(a);
    put_little_endian<std::int64_t>(row, to_us(image.azimuth_times_ns[index]));
    const double turns = image.azimuths_rad[index] / (2.0 * std::numbers::pi);
    const auto counts = static_cast<long>(std::lround(turns * kNavtechEncoderCounts));
    const auto encoder = static_cast<std::uint16_t>(
        ((counts % kNavtechEncoderCounts) + kNavtechEncoderCounts) % kNavtechEncoderCounts);
    put_little_endian<std::uint16_t>(row + 8, encoder);
    row[10] = 255;
    std::copy_n(image.power.row(a), bins, row + kOxfordMetadataColumns);
  }
  return out;
}

std::filesystem::path scan_png_path(const std::filesystem::path& folder, const ScanRecord& record) {
  return folder / "scans" / fmt::format("{}.png", to_us(record.timestamp_ns));
}

void write_oxford_png(const std::filesystem::path& path, const PolarImage& image) {
  write_png_atomically(path, to_oxford_layout(image));
}

void write_folder_poses(const std::filesystem::path& folder,
                        const std::vector<ScanRecord>& records) {
  std::string text = "timestamp,x,y,yaw\n";
  for (const ScanRecord& record : records) {
    text += fmt::format("{},{},{},{}\n", to_us(record.timestamp_ns), record.pose.x, record.pose.y,
                        record.pose.yaw);
  }
  write_text_atomically(folder / "poses.csv", text);
}

void write_png_atomically(const std::filesystem::path& path, const ByteImage& image) {
  std::vector<std::uint8_t> bytes;
  try {
    bytes = encode_png(image);
  } catch (const std::exception& error) {
    throw std::runtime_error(
        fmt::format("{}: cannot encode the PNG: {}", path.string(), error.what()));
  }
  write_bytes_atomically(path, bytes.data(), bytes.size());
}

void write_text_atomically(const std::filesystem::path& path, const std::string& text) {
  write_bytes_atomically(path, reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
}

}  // namespace radarpr::synthetic
