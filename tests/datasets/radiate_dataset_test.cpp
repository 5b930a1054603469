// The RADIATE loader on a temporary sequence folder filled with the real tiny_foggy sample:
// 18 polar scans, their times, and a GPS clock that does not overlap the radar's.
#include "datasets/real/radiate_dataset.hpp"

#include <numbers>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "tests/datasets/dataset_tree.hpp"

namespace radarpr {
namespace {

using test::real_data;
using test::TempTree;
namespace fs = std::filesystem;

constexpr const char* kSample = "radiate_tiny_foggy";

void make_sequence(const TempTree& tree, bool with_gps_times) {
  const fs::path sample = real_data(kSample);
  for (const auto& entry : fs::directory_iterator(sample / "Navtech_Polar")) {
    tree.copy(entry.path(), "fog_6_0/Navtech_Polar/" + entry.path().filename().string());
  }
  tree.copy(sample / "Navtech_Polar.txt", "fog_6_0/Navtech_Polar.txt");
  if (with_gps_times) tree.copy(sample / "GPS_IMU_Twist.txt", "fog_6_0/GPS_IMU_Twist.txt");
}

RadiateOptions options(const TempTree& tree) {
  RadiateOptions o;
  o.common.root = tree.root();
  o.common.sequence = "fog_6_0";
  return o;
}

TEST(RadiateDataset, ScansWithoutPosesTimesFromTheFrameList) {
  RADARPR_SKIP_WITHOUT(real_data(kSample), "RADIATE tiny_foggy sample");
  TempTree tree;
  make_sequence(tree, /*with_gps_times=*/false);
  const auto sequence = open_radiate(options(tree));
  EXPECT_EQ(sequence->position_frame(), PositionFrame::none);
  ASSERT_EQ(sequence->size(), 18u);  // every scan is listed, with a zero pose
  // "Frame: 000001 Time: 1574859771.744660272", to the nanosecond.
  EXPECT_EQ(sequence->records()[0].timestamp_ns, 1'574'859'771'744'660'272);
  EXPECT_EQ(sequence->records()[0].pose.x, 0.0);
  EXPECT_NE(sequence->records()[17].source.find("000018.png"), std::string::npos);

  const PolarImage image = sequence->load_image(3);
  EXPECT_EQ(image.azimuth_count(), 400);
  EXPECT_EQ(image.range_bin_count(), 576);
  EXPECT_DOUBLE_EQ(image.range_resolution_m, 0.173611);
  EXPECT_NEAR(image.azimuths_rad[200], std::numbers::pi, 1e-12);
  // Range rows x azimuth columns on disk, transposed to azimuth rows.
  const cv::Mat raw = cv::imread(sequence->records()[3].source, cv::IMREAD_UNCHANGED);
  ASSERT_EQ(raw.rows, 576);
  EXPECT_EQ(image.power(123, 45), raw.at<std::uint8_t>(45, 123));

  const DatasetReport report = sequence->describe();
  EXPECT_EQ(report.position_frame, PositionFrame::none);
  EXPECT_TRUE(report.warnings.empty());
}

TEST(RadiateDataset, TheGpsClockThatDoesNotOverlapTheRadarIsReported) {
  RADARPR_SKIP_WITHOUT(real_data(kSample), "RADIATE tiny_foggy sample");
  TempTree tree;
  make_sequence(tree, /*with_gps_times=*/true);
  const DatasetReport report = open_radiate(options(tree))->describe();
  ASSERT_EQ(report.warnings.size(), 1u);
  const std::string& warning = report.warnings[0];
  EXPECT_NE(warning.find("GPS_IMU_Twist.txt"), std::string::npos) << warning;
  EXPECT_NE(warning.find("does not overlap the radar clock"), std::string::npos) << warning;
  // Radar 1574859771.74 .. 1574859775.93 s, GPS from 1574859835.75 s: 59.8 s after the last scan.
  EXPECT_NE(warning.find("59.8 s after"), std::string::npos) << warning;
}

TEST(RadiateDataset, AnOverlappingGpsClockIsOnlyNoted) {
  RADARPR_SKIP_WITHOUT(real_data(kSample), "RADIATE tiny_foggy sample");
  TempTree tree;
  make_sequence(tree, /*with_gps_times=*/false);
  tree.write("fog_6_0/GPS_IMU_Twist.txt",
             "Frame: 000001 Time: 1574859772.0\nFrame: 000002 Time: 1574859773.0\n");
  const DatasetReport report = open_radiate(options(tree))->describe();
  EXPECT_TRUE(report.warnings.empty());
  bool noted = false;
  for (const auto& note : report.notes) noted = noted || note.find("overlaps") != std::string::npos;
  EXPECT_TRUE(noted);
}

// GPS_IMU_Twist.txt only feeds the clock check: a malformed one is a warning, the scans open.
TEST(RadiateDataset, AMalformedGpsFileIsAWarningNotAnError) {
  RADARPR_SKIP_WITHOUT(real_data(kSample), "RADIATE tiny_foggy sample");
  TempTree tree;
  make_sequence(tree, /*with_gps_times=*/false);
  const fs::path gps = tree.write("fog_6_0/GPS_IMU_Twist.txt",
                                  "Frame: 000001 Time: 1574859772.0\nFrame: two Time: soon\n");
  std::unique_ptr<ScanSequence> sequence;
  ASSERT_NO_THROW(sequence = open_radiate(options(tree)));
  EXPECT_EQ(sequence->size(), 18u);
  const DatasetReport report = sequence->describe();
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_NE(report.warnings[0].find("GPS clock is not checked"), std::string::npos)
      << report.warnings[0];
  EXPECT_NE(report.warnings[0].find(gps.string() + ":2"), std::string::npos) << report.warnings[0];
}

}  // namespace
}  // namespace radarpr
