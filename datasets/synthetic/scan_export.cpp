#include "datasets/synthetic/scan_export.hpp"

#include <cmath>
#include <cstdint>
#include <fstream>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>
#include <opencv2/imgcodecs.hpp>

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

std::int64_t to_us(std::int64_t ns) {
  // Floor division: the stamps are positive Unix times.
  return ns / 1000;
}

}  // namespace

cv::Mat to_oxford_layout(const PolarImage& image) {
  const int azimuths = image.azimuth_count();
  const int bins = image.range_bin_count();
  if (image.power.empty() || image.power.type() != CV_8UC1) {
    throw std::invalid_argument("Oxford layout: the scan must be a non-empty CV_8UC1 image");
  }
  if (image.azimuth_times_ns.size() != static_cast<std::size_t>(azimuths) ||
      image.azimuths_rad.size() != static_cast<std::size_t>(azimuths)) {
    throw std::invalid_argument(fmt::format(
        "Oxford layout: the scan needs one time and one angle per azimuth row ({}), got {} and {}",
        azimuths, image.azimuth_times_ns.size(), image.azimuths_rad.size()));
  }
  cv::Mat out(azimuths, kOxfordMetadataColumns + bins, CV_8UC1);
  for (int a = 0; a < azimuths; ++a) {
    auto* row = out.ptr<std::uint8_t>(a);
    const auto index = static_cast<std::size_t>(a);
    put_little_endian<std::int64_t>(row, to_us(image.azimuth_times_ns[index]));
    const double turns = image.azimuths_rad[index] / (2.0 * std::numbers::pi);
    const auto counts = static_cast<long>(std::lround(turns * kNavtechEncoderCounts));
    const auto encoder = static_cast<std::uint16_t>(
        ((counts % kNavtechEncoderCounts) + kNavtechEncoderCounts) % kNavtechEncoderCounts);
    put_little_endian<std::uint16_t>(row + 8, encoder);
    row[10] = 255;
    std::copy_n(image.power.ptr<std::uint8_t>(a), bins, row + kOxfordMetadataColumns);
  }
  return out;
}

std::filesystem::path scan_png_path(const std::filesystem::path& folder, const ScanRecord& record) {
  return folder / "scans" / fmt::format("{}.png", to_us(record.timestamp_ns));
}

void write_oxford_png(const std::filesystem::path& path, const PolarImage& image) {
  const cv::Mat encoded = to_oxford_layout(image);
  std::filesystem::create_directories(path.parent_path());
  // Default compression, no extra chunks: the same pixels always give the same bytes.
  if (!cv::imwrite(path.string(), encoded)) {
    throw std::runtime_error(fmt::format("{}: cannot write the PNG", path.string()));
  }
}

void write_folder_poses(const std::filesystem::path& folder,
                        const std::vector<ScanRecord>& records) {
  std::filesystem::create_directories(folder);
  const std::filesystem::path path = folder / "poses.csv";
  std::ofstream out(path, std::ios::binary);
  out << "timestamp,x,y,yaw\n";
  for (const ScanRecord& record : records) {
    out << fmt::format("{},{:.6f},{:.6f},{:.9f}\n", to_us(record.timestamp_ns), record.pose.x,
                       record.pose.y, record.pose.yaw);
  }
  if (!out) throw std::runtime_error(fmt::format("{}: cannot write the poses", path.string()));
}

}  // namespace radarpr::synthetic
