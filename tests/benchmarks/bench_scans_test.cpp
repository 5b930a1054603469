// The scans of the extraction benchmarks: real samples when present, synthetic PNGs otherwise.
#include "benchmarks/bench_scans.hpp"

#include <filesystem>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

namespace radarpr::bench {
namespace {

std::filesystem::path fresh_folder(const char* name) {
  const std::filesystem::path folder = std::filesystem::path(::testing::TempDir()) / name;
  std::filesystem::remove_all(folder);
  return folder;
}

PolarImage small_scan() {
  PolarImage scan;
  scan.power = ByteImage(8, 30);
  for (int a = 0; a < 8; ++a) {
    for (int r = 0; r < 30; ++r) scan.power(a, r) = static_cast<unsigned char>(a * 30 + r);
  }
  return scan;
}

TEST(BenchScans, WrittenPngsDecodeToTheSameScanInBothLayouts) {
  const std::filesystem::path folder = fresh_folder("radarpr_bench_scans_layouts");
  std::filesystem::create_directories(folder);
  const PolarImage scan = small_scan();
  for (const PolarPngLayout layout : {PolarPngLayout::mulran_native, PolarPngLayout::oxford}) {
    const std::filesystem::path png = folder / (std::string(to_string(layout)) + ".png");
    write_polar_png(scan, layout, png, 1'700'000'000'000'000);
    PolarPngOptions options;
    options.range_resolution_m = 0.05;
    options.layout = layout;
    const DecodedPolarPng decoded = read_polar_png(png, options);
    EXPECT_EQ(decoded.layout, layout);
    EXPECT_TRUE(decoded.image.power == scan.power) << to_string(layout);
    if (layout == PolarPngLayout::oxford) {
      // Encoder a * 5600 / 8 -> azimuth 2 pi a / 8.
      EXPECT_NEAR(decoded.image.azimuths_rad[2], 2.0 * 3.14159265358979 * 2 / 8, 1e-9);
    }
  }
  std::filesystem::remove_all(folder);
}

TEST(BenchScans, SynthesisesBothGeometriesWithoutRealData) {
  const std::filesystem::path scratch = fresh_folder("radarpr_bench_scans_synthetic");
  const std::vector<BenchScan> scans =
      prepare_bench_scans(scratch / "no such data folder", scratch / "pngs");
  ASSERT_EQ(scans.size(), 2u);
  EXPECT_EQ(scans[0].label, "400x3360");
  EXPECT_EQ(scans[1].label, "400x3768");
  for (const BenchScan& scan : scans) {
    EXPECT_FALSE(scan.real);
    EXPECT_EQ(scan.image.azimuth_count(), 400);
    EXPECT_TRUE(std::filesystem::exists(scan.png)) << scan.png;
    EXPECT_EQ(scan.png_bytes, std::filesystem::file_size(scan.png));
    EXPECT_NE(scan.source.find("synthetic"), std::string::npos);
  }
  EXPECT_EQ(scans[0].image.range_bin_count(), 3360);
  EXPECT_EQ(scans[1].image.range_bin_count(), 3768);
  EXPECT_EQ(scans[0].options.layout, PolarPngLayout::mulran_native);
  EXPECT_EQ(scans[1].options.layout, PolarPngLayout::oxford);
  // The PNG holds the synthetic scan itself.
  const PolarImage rendered = synthetic_bench_image(3360, scans[0].options.range_resolution_m);
  EXPECT_TRUE(scans[0].image.power == rendered.power);
  std::filesystem::remove_all(scratch);
}

TEST(BenchScans, UsesTheRealSamplesWhenPresent) {
  const std::filesystem::path root =
      std::filesystem::path(RADARPR_SOURCE_DIR) / "../shared/data/real";
  const std::filesystem::path mulran = root / "referee_mulran_kaist03/native/000000.png";
  const std::filesystem::path oxford = root / "oxford_radar_robotcar_tiny_radarslampy/radar";
  if (!std::filesystem::exists(mulran)) GTEST_SKIP() << "MulRan sample absent: " << mulran;
  if (!std::filesystem::exists(oxford)) GTEST_SKIP() << "Oxford samples absent: " << oxford;
  const std::filesystem::path scratch = fresh_folder("radarpr_bench_scans_real");
  const std::vector<BenchScan> scans = prepare_bench_scans(root, scratch);
  ASSERT_EQ(scans.size(), 2u);
  EXPECT_TRUE(scans[0].real);
  EXPECT_TRUE(scans[1].real);
  EXPECT_EQ(scans[0].png, mulran);
  EXPECT_EQ(scans[0].image.range_bin_count(), 3360);
  EXPECT_EQ(scans[1].image.range_bin_count(), 3768);
  EXPECT_FALSE(std::filesystem::exists(scratch));  // nothing synthesised
}

}  // namespace
}  // namespace radarpr::bench
