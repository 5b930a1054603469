// Synthetic scans written in the Oxford layout: byte-identical for the same seed, the sweep's
// timestamps and encoder values in every row, and read back by the `folder` loader.
#include "datasets/synthetic/scan_export.hpp"

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "datasets/real/folder_dataset.hpp"
#include "datasets/synthetic/synthetic_sequence.hpp"
#include "descriptors/opencv_image.hpp"
#include "tests/datasets/dataset_tree.hpp"

namespace radarpr {
namespace {

using test::TempTree;

// Eight scans of the tiny radar (120 x 420) in the city: quick to render.
SyntheticConfig tiny_config() {
  SyntheticConfig config;
  config.scan_count = 8;
  config.radar = synthetic::radar_preset("tiny");
  config.world.traffic = 0.5;
  return config;
}

void export_to(const SyntheticSequence& sequence, const std::filesystem::path& folder) {
  synthetic::write_folder_poses(folder, sequence.records());
  for (std::size_t i = 0; i < sequence.size(); ++i) {
    synthetic::write_oxford_png(synthetic::scan_png_path(folder, sequence.records()[i]),
                                sequence.load_image(i));
  }
}

std::string bytes_of(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

TEST(SyntheticExport, SameSeedGivesByteIdenticalFiles) {
  TempTree tree;
  export_to(SyntheticSequence(tiny_config()), tree.path("a"));
  export_to(SyntheticSequence(tiny_config()), tree.path("b"));
  int compared = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(tree.path("a"))) {
    if (!entry.is_regular_file()) continue;
    const auto twin = tree.path("b") / std::filesystem::relative(entry.path(), tree.path("a"));
    ASSERT_TRUE(std::filesystem::exists(twin)) << twin;
    EXPECT_EQ(bytes_of(entry.path()), bytes_of(twin)) << entry.path();
    ++compared;
  }
  EXPECT_EQ(compared, 8 + 1);  // the scans and poses.csv
  // Another seed gives other pixels.
  SyntheticConfig other = tiny_config();
  other.seed = 8;
  export_to(SyntheticSequence(other), tree.path("c"));
  const SyntheticSequence sequence(tiny_config());
  const auto name = synthetic::scan_png_path("", sequence.records()[3]);
  EXPECT_NE(bytes_of(tree.path("a") / name), bytes_of(tree.path("c") / name));
}

TEST(SyntheticExport, RowsCarryTheSweepTimesAndEncoderCounts) {
  TempTree tree;
  const SyntheticSequence sequence(tiny_config());
  export_to(sequence, tree.root());
  // Scan 2 at 1.7e18 ns + 2 x 250 ms, named by its µs time.
  const ScanRecord& record = sequence.records()[2];
  const auto path = tree.path("scans/1700000000500000.png");
  ASSERT_EQ(synthetic::scan_png_path(tree.root(), record), path);
  const cv::Mat raw = cv::imread(path.string(), cv::IMREAD_UNCHANGED);
  ASSERT_EQ(raw.rows, 120);
  ASSERT_EQ(raw.cols, 11 + 420);
  ASSERT_EQ(raw.type(), CV_8UC1);
  for (const int a : {0, 1, 59, 60, 119}) {
    const auto* row = raw.ptr<std::uint8_t>(a);
    std::int64_t stamp = 0;
    std::memcpy(&stamp, row, 8);  // little-endian on every platform we build for
    std::uint16_t encoder = 0;
    std::memcpy(&encoder, row + 8, 2);
    // 120 azimuths over 250 ms: 2083333 ns apart (integer division of the period), row 60 at
    // the scan's time; µs truncated. Encoder: 5600 counts per turn, a * 5600 / 120 rounded.
    const std::int64_t ns = 1'700'000'000'500'000'000 + (a - 60) * (250'000'000 / 120);
    EXPECT_EQ(stamp, ns / 1000) << a;
    EXPECT_EQ(encoder, static_cast<std::uint16_t>(std::lround(a * 5600.0 / 120.0))) << a;
    EXPECT_EQ(row[10], 255) << a;
  }
  // The pixels are the rendered scan's.
  const PolarImage image = sequence.load_image(2);
  EXPECT_EQ(cv::norm(raw.colRange(11, 431), opencv_view(image.power), cv::NORM_INF), 0.0);
}

TEST(SyntheticExport, TheFolderLoaderReadsItBack) {
  TempTree tree;
  const SyntheticSequence sequence(tiny_config());
  export_to(sequence, tree.path("drive"));
  FolderOptions options;
  options.common.root = tree.root();
  options.common.sequence = "drive";
  options.common.range_resolution_m = 0.238;
  const auto loaded = open_folder(options);
  ASSERT_EQ(loaded->size(), sequence.size());
  for (std::size_t i = 0; i < sequence.size(); ++i) {
    const ScanRecord& want = sequence.records()[i];
    const ScanRecord& got = loaded->records()[i];
    EXPECT_EQ(got.timestamp_ns, want.timestamp_ns) << i;  // whole µs: no rounding
    EXPECT_NEAR(got.pose.x, want.pose.x, 1e-6) << i;
    EXPECT_NEAR(got.pose.y, want.pose.y, 1e-6) << i;
    EXPECT_NEAR(got.pose.yaw, want.pose.yaw, 1e-8) << i;
  }
  const PolarImage original = sequence.load_image(5);
  const PolarImage read = loaded->load_image(5);
  EXPECT_TRUE(read.power == original.power);
  ASSERT_EQ(read.azimuths_rad.size(), 120u);
  EXPECT_NEAR(read.azimuths_rad[30], 2.0 * 3.14159265358979 * 1400 / 5600, 1e-9);
  ASSERT_EQ(read.azimuth_times_ns.size(), 120u);
  EXPECT_EQ(read.azimuth_times_ns[60], sequence.records()[5].timestamp_ns);
}

TEST(SyntheticExport, RefusesAScanWithoutTimes) {
  PolarImage image;
  image.power = ByteImage(4, 10);
  image.azimuths_rad = uniform_azimuths(4);
  EXPECT_THROW(synthetic::to_oxford_layout(image), std::invalid_argument);
}

}  // namespace
}  // namespace radarpr
