#include "benchmarks/bench_scans.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <system_error>

#include <fmt/format.h>

#include "datasets/real/mulran_dataset.hpp"
#include "datasets/real/oxford_dataset.hpp"
#include "datasets/synthetic/scan_export.hpp"
#include "datasets/synthetic/synthetic_sequence.hpp"

namespace radarpr::bench {
namespace {

// 2023-11-14T22:13:20Z in µs: any plausible Unix time does.
constexpr std::int64_t kSyntheticStartUs = 1'700'000'000'000'000;

struct ScanGeometrySpec {
  std::string label;
  std::string radar;
  int range_bins = 0;
  double range_resolution_m = 0.0;
  PolarPngLayout layout = PolarPngLayout::oxford;
};

std::filesystem::path first_png(const std::filesystem::path& folder) {
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error)) return {};
  std::vector<std::filesystem::path> pngs;
  for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
    if (entry.path().extension() == ".png") pngs.push_back(entry.path());
  }
  if (pngs.empty()) return {};
  return *std::min_element(pngs.begin(), pngs.end());
}

BenchScan decoded(BenchScan scan) {
  scan.png_bytes = std::filesystem::file_size(scan.png);
  scan.image = read_polar_png(scan.png, scan.options).image;
  return scan;
}

BenchScan bench_scan(const ScanGeometrySpec& spec, const std::filesystem::path& real_png,
                     const std::filesystem::path& scratch_folder, const std::string& real_source) {
  BenchScan scan;
  scan.label = spec.label;
  scan.radar = spec.radar;
  scan.options.range_resolution_m = spec.range_resolution_m;
  scan.options.layout = spec.layout;
  std::error_code error;
  if (!real_png.empty() && std::filesystem::is_regular_file(real_png, error)) {
    scan.real = true;
    scan.png = real_png;
    scan.source = real_source;
    BenchScan result = decoded(scan);
    if (result.image.range_bin_count() == spec.range_bins) return result;
  }
  std::filesystem::create_directories(scratch_folder);
  scan.real = false;
  scan.png = scratch_folder / (spec.label + ".png");
  scan.source = fmt::format(
      "synthetic: the synthetic town's first scan at {} bins of {} m, written as a {} PNG",
      spec.range_bins, spec.range_resolution_m, to_string(spec.layout));
  write_polar_png(synthetic_bench_image(spec.range_bins, spec.range_resolution_m), spec.layout,
                  scan.png, kSyntheticStartUs);
  return decoded(scan);
}

void put_little_endian(std::uint64_t value, int bytes, unsigned char* out) {
  for (int i = 0; i < bytes; ++i) out[i] = static_cast<unsigned char>(value >> (8 * i));
}

}  // namespace

PolarImage synthetic_bench_image(int range_bins, double range_resolution_m) {
  SyntheticConfig config;
  config.scan_count = 1;
  config.radar.range_bin_count = range_bins;
  config.radar.range_resolution_m = range_resolution_m;
  return SyntheticSequence(config).load_image(0);
}

void write_polar_png(const PolarImage& image, PolarPngLayout layout,
                     const std::filesystem::path& path, std::int64_t start_time_us) {
  ByteImage raw;
  if (layout == PolarPngLayout::mulran_native) {
    raw = transposed(image.power);
  } else {
    const int azimuths = image.azimuth_count();
    const int bins = image.range_bin_count();
    // Every byte of every row is written below.
    raw = ByteImage::uninitialised(azimuths, kOxfordMetadataColumns + bins);
    // One revolution at 4 Hz: 250 ms over the azimuths.
    const std::int64_t step_us = 250'000 / std::max(1, azimuths);
    for (int a = 0; a < azimuths; ++a) {
      unsigned char* row = raw.row(a);
      put_little_endian(static_cast<std::uint64_t>(start_time_us + a * step_us), 8, row);
      const auto encoder = static_cast<std::uint64_t>(a) * kNavtechEncoderCounts / azimuths;
      put_little_endian(encoder, 2, row + 8);
      row[10] = 255;  // a real (not interpolated) azimuth
      std::copy_n(image.power.row(a), bins, row + kOxfordMetadataColumns);
    }
  }
  synthetic::write_png_atomically(path, raw);
}

std::vector<BenchScan> prepare_bench_scans(const std::filesystem::path& real_data_root,
                                           const std::filesystem::path& scratch_folder) {
  const ScanGeometrySpec mulran{"400x3360", "Navtech CIR204-H (MulRan)", 3360,
                                kMulranRangeResolution, PolarPngLayout::mulran_native};
  const ScanGeometrySpec oxford{"400x3768", "Navtech CTS350-X (Oxford)", 3768,
                                kOxfordRangeResolution, PolarPngLayout::oxford};
  const std::filesystem::path mulran_png =
      real_data_root / "referee_mulran_kaist03" / "native" / "000000.png";
  const std::filesystem::path oxford_png =
      first_png(real_data_root / "oxford_radar_robotcar_tiny_radarslampy" / "radar");
  // Moved in, not listed in braces: an initializer list would copy each scan's pixels.
  std::vector<BenchScan> scans;
  scans.push_back(bench_scan(
      mulran, mulran_png, scratch_folder,
      "real: MulRan KAIST03 native polar PNG (referee_mulran_kaist03/native/000000.png)"));
  scans.push_back(bench_scan(oxford, oxford_png, scratch_folder,
                             "real: Oxford Radar RobotCar PNG "
                             "(oxford_radar_robotcar_tiny_radarslampy/radar/" +
                                 oxford_png.filename().string() + ")"));
  return scans;
}

}  // namespace radarpr::bench
