// The MulRan loader on a temporary sequence folder filled with the real KAIST03 scans (native and
// Oxford form) and a synthetic global_pose.csv (the sample ships no poses).
#include "datasets/real/mulran_dataset.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "tests/datasets/dataset_tree.hpp"

namespace radarpr {
namespace {

using test::real_data;
using test::TempTree;
namespace fs = std::filesystem;

constexpr const char* kSample = "referee_mulran_kaist03";
// MulRan names files by the last azimuth's time (SOURCE.md: frames 000000 and 000001 of KAIST03;
// the Oxford-form 000010 ends at 1567410204060174848).
constexpr std::int64_t kScan0 = 1'567'410'201'812'840'928;
constexpr std::int64_t kScan1 = 1'567'410'202'062'436'262;
constexpr std::int64_t kScan10 = 1'567'410'204'060'174'848;
constexpr std::int64_t kPoseStart = 1'567'410'201'000'000'000;

// Synthetic poses every 0.1 s from kPoseStart for `seconds`: x = 100 + 5 t, y = 200 - 2 t,
// rotation 0.1 rad about z; linear in time, so interpolation reproduces the formula exactly.
std::string global_pose_csv(int seconds) {
  std::string text;
  const double c = std::cos(0.1), s = std::sin(0.1);
  for (int i = 0; i <= 10 * seconds; ++i) {
    const double t = i / 10.0;
    text += fmt::format("{},{},{},0,{},{},{},0,{},0,0,1,0\n",
                        kPoseStart + std::int64_t{i} * 100'000'000, c, -s, 100 + 5 * t, s, c,
                        200 - 2 * t);
  }
  return text;
}

// root/KAIST03/sensor_data/radar/{polar,polar_oxford_form}/ + global_pose.csv.
void make_sequence(const TempTree& tree, bool native, bool oxford_form, int pose_seconds = 4) {
  const fs::path sample = real_data(kSample);
  const std::string radar = "KAIST03/sensor_data/radar/";
  if (native) {
    tree.copy(sample / "native/000000.png", radar + fmt::format("polar/{}.png", kScan0));
    tree.copy(sample / "native/000001.png", radar + fmt::format("polar/{}.png", kScan1));
  }
  if (oxford_form) {
    tree.copy(sample / "oxford_form/000000.png",
              radar + fmt::format("polar_oxford_form/{}.png", kScan0));
    tree.copy(sample / "oxford_form/000001.png",
              radar + fmt::format("polar_oxford_form/{}.png", kScan1));
    tree.copy(sample / "oxford_form/000010.png",
              radar + fmt::format("polar_oxford_form/{}.png", kScan10));
  }
  tree.write("KAIST03/global_pose.csv", global_pose_csv(pose_seconds));
}

MulranOptions options(const TempTree& tree, MulranPolarFolder folder) {
  MulranOptions o;
  o.common.root = tree.root();
  o.common.sequence = "KAIST03";
  o.folder = folder;
  return o;
}

double seconds_since_pose_start(std::int64_t t) {
  return static_cast<double>(t - kPoseStart) * 1e-9;
}

TEST(MulranDataset, NativePolarIsPreferredTransposedAndPosedFromGlobalPose) {
  RADARPR_SKIP_WITHOUT(real_data(kSample), "MulRan KAIST03 sample");
  TempTree tree;
  make_sequence(tree, /*native=*/true, /*oxford_form=*/true);
  const auto sequence = open_mulran(options(tree, MulranPolarFolder::automatic));
  ASSERT_EQ(sequence->size(), 2u);
  EXPECT_EQ(sequence->position_frame(), PositionFrame::global);
  const DatasetReport report = sequence->describe();
  EXPECT_NE(report.layout.find("sensor_data/radar/polar/"), std::string::npos) << report.layout;
  EXPECT_NE(report.layout.find("mulran_native"), std::string::npos) << report.layout;
  EXPECT_FALSE(report.invalid_azimuth_rows.has_value());  // no flag bytes in native images
  EXPECT_EQ(report.scan_time_reference, "the last azimuth of the sweep (MulRan names files by it)");
  EXPECT_TRUE(report.warnings.empty());  // 3360 range bins, as the CIR204-H gives

  // ns names are kept as they are.
  EXPECT_EQ(sequence->records()[0].timestamp_ns, kScan0);
  EXPECT_EQ(sequence->records()[1].timestamp_ns, kScan1);
  // Pose at the file name's time: x = 100 + 5 t, y = 200 - 2 t, yaw = atan2(R10, R00) = 0.1.
  for (const ScanRecord& record : sequence->records()) {
    const double t = seconds_since_pose_start(record.timestamp_ns);
    EXPECT_NEAR(record.pose.x, 100 + 5 * t, 1e-9);
    EXPECT_NEAR(record.pose.y, 200 - 2 * t, 1e-9);
    EXPECT_NEAR(record.pose.yaw, 0.1, 1e-12);
  }

  const PolarImage image = sequence->load_image(0);
  EXPECT_EQ(image.azimuth_count(), 400);
  EXPECT_EQ(image.range_bin_count(), 3360);
  EXPECT_DOUBLE_EQ(image.range_resolution_m, 200.0 / 3360.0);
  EXPECT_NEAR(image.azimuths_rad[100], std::numbers::pi / 2, 1e-12);  // uniform: 2 pi 100 / 400
  EXPECT_TRUE(image.azimuth_times_ns.empty());
}

TEST(MulranDataset, OxfordFormHoldsTheSamePixelsWithAzimuthTimesAndEncoderAngles) {
  RADARPR_SKIP_WITHOUT(real_data(kSample), "MulRan KAIST03 sample");
  TempTree tree;
  make_sequence(tree, /*native=*/true, /*oxford_form=*/true);
  const auto native = open_mulran(options(tree, MulranPolarFolder::polar));
  const auto oxford = open_mulran(options(tree, MulranPolarFolder::polar_oxford_form));
  ASSERT_EQ(oxford->size(), 3u);
  const PolarImage a = native->load_image(0);
  const PolarImage b = oxford->load_image(0);
  ASSERT_EQ(b.azimuth_count(), 400);
  ASSERT_EQ(b.range_bin_count(), 3360);
  EXPECT_TRUE(a.power == b.power);  // README: the same pixels
  // The Oxford form stores ns per azimuth; the name is the last azimuth's time (32 ns of MATLAB
  // rounding apart, SOURCE.md).
  EXPECT_EQ(b.azimuth_times_ns.back(), 1'567'410'201'812'840'960);
  EXPECT_NEAR(static_cast<double>(b.azimuth_times_ns.back() - oxford->records()[0].timestamp_ns),
              0.0, 100.0);
  // Encoder 7 of 5600 on row 0 (MulRan's Oxford form starts half a step in).
  EXPECT_NEAR(b.azimuths_rad[0], 2 * std::numbers::pi * 7 / 5600, 1e-12);
  const DatasetReport report = oxford->describe();
  ASSERT_TRUE(report.invalid_azimuth_rows.has_value());
  EXPECT_EQ(*report.invalid_azimuth_rows, 0);
}

TEST(MulranDataset, FallsBackToTheOxfordFormAndWindowsByIndex) {
  RADARPR_SKIP_WITHOUT(real_data(kSample), "MulRan KAIST03 sample");
  TempTree tree;
  make_sequence(tree, /*native=*/false, /*oxford_form=*/true);
  auto o = options(tree, MulranPolarFolder::automatic);
  o.common.window.every_nth = 2;  // scans 0 and 2 of 3
  const auto sequence = open_mulran(o);
  ASSERT_EQ(sequence->size(), 2u);
  EXPECT_EQ(sequence->records()[0].timestamp_ns, kScan0);
  EXPECT_EQ(sequence->records()[1].timestamp_ns, kScan10);
  EXPECT_NE(sequence->describe().layout.find("polar_oxford_form"), std::string::npos);
  EXPECT_EQ(sequence->describe().window, "[0, end) every 2nd");
}

TEST(MulranDataset, ScansOutsideThePoseTrackAreCountedAndSkipped) {
  RADARPR_SKIP_WITHOUT(real_data(kSample), "MulRan KAIST03 sample");
  TempTree tree;
  // Poses for 2 s from kPoseStart: the scan at +3.06 s is past the track's end.
  make_sequence(tree, /*native=*/false, /*oxford_form=*/true, /*pose_seconds=*/2);
  const auto sequence = open_mulran(options(tree, MulranPolarFolder::automatic));
  EXPECT_EQ(sequence->size(), 2u);
  const DatasetReport report = sequence->describe();
  EXPECT_EQ(report.scans_selected, 3u);
  EXPECT_EQ(report.posed_scans, 2u);
  EXPECT_EQ(report.scans_without_pose, 1u);
  ASSERT_FALSE(report.warnings.empty());
  EXPECT_NE(report.warnings[0].find("1 of 3 scans have no pose"), std::string::npos);
}

// Oxford-form scans copied into polar/ (where the native layout is expected) used to be read as
// 3371 azimuths x 400 range bins; the forced layout now checks the orientation.
TEST(MulranDataset, OxfordFormScansInTheNativeFolderAreRefused) {
  RADARPR_SKIP_WITHOUT(real_data(kSample), "MulRan KAIST03 sample");
  TempTree tree;
  make_sequence(tree, /*native=*/false, /*oxford_form=*/false);
  const fs::path misplaced =
      tree.copy(real_data(kSample) / "oxford_form/000000.png",
                fmt::format("KAIST03/sensor_data/radar/polar/{}.png", kScan0));
  test::expect_error<std::runtime_error>(
      [&] { open_mulran(options(tree, MulranPolarFolder::polar)); },
      {misplaced.string(), "3371 wide x 400 high", "expected the range x azimuth layout"});
  // And native scans in polar_oxford_form/ are not read as 400 azimuths of metadata.
  const fs::path native =
      tree.copy(real_data(kSample) / "native/000000.png",
                fmt::format("KAIST03/sensor_data/radar/polar_oxford_form/{}.png", kScan0));
  test::expect_error<std::runtime_error>(
      [&] { open_mulran(options(tree, MulranPolarFolder::polar_oxford_form)); },
      {native.string(), "400 wide x 3360 high", "expected the Oxford layout"});
}

}  // namespace
}  // namespace radarpr
