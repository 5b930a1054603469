// The Boreas loader on a temporary sequence folder holding the real Boreas-RT frame and synthetic
// applanix poses (the sample's scan has no pose file).
#include "datasets/real/boreas_dataset.hpp"

#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "tests/datasets/dataset_tree.hpp"

namespace radarpr {
namespace {

using test::real_data;
using test::TempTree;

constexpr const char* kFrame = "boreas_rt_single_frame/test_frame.png";
// Boreas names a scan by its middle azimuth's time: row 200 of the frame, in µs.
constexpr std::int64_t kFrameUs = 1'733'239'501'984'460;
constexpr const char* kHeader =
    "GPSTime,easting,northing,altitude,vel_east,vel_north,vel_up,roll,pitch,heading,angvel_z,"
    "angvel_y,angvel_x\n";

// Three poses 0.25 s apart around the scan, east at 4 m/s, heading 0.3 rad.
std::string radar_poses(bool nanoseconds) {
  std::string text = kHeader;
  for (int i = -1; i <= 1; ++i) {
    const std::int64_t us = kFrameUs + i * 250'000;
    text += fmt::format("{},{},4848820.5,150,4,0,0,0,0,0.3,0,0,0\n", nanoseconds ? us * 1000 : us,
                        623425.0 + i * 1.0);
  }
  return text;
}

BoreasOptions options(const TempTree& tree) {
  BoreasOptions o;
  o.common.root = tree.root();
  o.common.sequence = "boreas-2024-12-03-15-25";
  return o;
}

TEST(BoreasDataset, MiddleAzimuthStampsResolutionByDateAndExactPoses) {
  RADARPR_SKIP_WITHOUT(real_data(kFrame), "Boreas-RT frame");
  for (const bool nanoseconds : {true, false}) {
    SCOPED_TRACE(nanoseconds ? "ns poses" : "µs poses");
    TempTree tree;
    tree.copy(real_data(kFrame), fmt::format("boreas-2024-12-03-15-25/radar/{}.png", kFrameUs));
    tree.write("boreas-2024-12-03-15-25/applanix/radar_poses.csv", radar_poses(nanoseconds));
    const auto sequence = open_boreas(options(tree));
    ASSERT_EQ(sequence->size(), 1u);
    const ScanRecord& record = sequence->records()[0];
    EXPECT_EQ(record.timestamp_ns, kFrameUs * 1000);
    // The middle pose sample has exactly the scan's time.
    EXPECT_DOUBLE_EQ(record.pose.x, 623425.0);
    EXPECT_DOUBLE_EQ(record.pose.y, 4848820.5);
    EXPECT_DOUBLE_EQ(record.pose.yaw, 0.3);

    const PolarImage image = sequence->load_image(0);
    EXPECT_EQ(image.azimuth_count(), 400);
    EXPECT_EQ(image.range_bin_count(), 6848);  // RAS6: 6859 - 11
    EXPECT_EQ(image.azimuth_times_ns[200], record.timestamp_ns);
    // 2024 is after 2021-09-21: 0.04381 m/bin.
    EXPECT_DOUBLE_EQ(image.range_resolution_m, 0.04381);
    const DatasetReport report = sequence->describe();
    EXPECT_NE(report.resolution_source.find("by date"), std::string::npos);
    // Boreas-RT's flag byte alternates chirp up/down: not counted as invalid rows.
    EXPECT_FALSE(report.invalid_azimuth_rows.has_value());
    EXPECT_TRUE(report.warnings.empty()) << report.warnings.front();
  }
}

TEST(BoreasDataset, ResolutionSwitchesOn2021_09_21UnlessConfigured) {
  EXPECT_DOUBLE_EQ(boreas_range_resolution(1'632'182'399'999'999'999), 0.0596);
  EXPECT_DOUBLE_EQ(boreas_range_resolution(1'632'182'400'000'000'000), 0.04381);

  RADARPR_SKIP_WITHOUT(real_data(kFrame), "Boreas-RT frame");
  TempTree tree;
  tree.copy(real_data(kFrame), fmt::format("boreas-2024-12-03-15-25/radar/{}.png", kFrameUs));
  tree.write("boreas-2024-12-03-15-25/applanix/radar_poses.csv", radar_poses(false));
  auto o = options(tree);
  o.common.range_resolution_m = 0.0438;
  const auto sequence = open_boreas(o);
  EXPECT_DOUBLE_EQ(sequence->load_image(0).range_resolution_m, 0.0438);
  EXPECT_EQ(sequence->describe().resolution_source, "configured");
}

// A real pose file from another drive (2021) beside the 2024 frame: the clocks do not overlap,
// and the scan gets no pose instead of the nearest far-away one.
TEST(BoreasDataset, APoseClockThatDoesNotOverlapTheScansIsReported) {
  RADARPR_SKIP_WITHOUT(real_data(kFrame), "Boreas-RT frame");
  RADARPR_SKIP_WITHOUT(real_data("poses_only/boreas-2021-09-02-11-42_radar_poses.csv"),
                       "Boreas pose track");
  TempTree tree;
  tree.copy(real_data(kFrame), fmt::format("boreas-2024-12-03-15-25/radar/{}.png", kFrameUs));
  tree.copy(real_data("poses_only/boreas-2021-09-02-11-42_radar_poses.csv"),
            "boreas-2024-12-03-15-25/applanix/radar_poses.csv");
  const auto sequence = open_boreas(options(tree));
  EXPECT_EQ(sequence->size(), 0u);
  const DatasetReport report = sequence->describe();
  EXPECT_EQ(report.scans_without_pose, 1u);
  EXPECT_EQ(report.pose_samples, 4134u);
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_NE(report.warnings[0].find("the pose clock (2021-09-02"), std::string::npos)
      << report.warnings[0];
  EXPECT_NE(report.warnings[0].find("does not overlap the scan clock (2024-12-03"),
            std::string::npos)
      << report.warnings[0];
  EXPECT_EQ(report.azimuths, 400);  // the geometry still comes from the scan
}

}  // namespace
}  // namespace radarpr
