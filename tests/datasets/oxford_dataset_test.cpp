// The Oxford Radar RobotCar loader on a temporary run folder filled with the real tiny sample
// (11 consecutive scans, gps.csv, gt/radar_odometry.csv).
#include "datasets/real/oxford_dataset.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "tests/datasets/dataset_tree.hpp"

namespace radarpr {
namespace {

using test::expect_error;
using test::real_data;
using test::TempTree;
namespace fs = std::filesystem;

constexpr const char* kTiny = "oxford_radar_robotcar_tiny_radarslampy";
constexpr const char* kRun = "2019-01-10-14-36-48-radar-oxford-10k-partial";

// root/<kRun>/ laid out like an Oxford run: radar/, radar.timestamps, gps/gps.csv,
// gt/radar_odometry.csv.
void make_run(const TempTree& tree) {
  const fs::path sample = real_data(kTiny);
  for (const auto& entry : fs::directory_iterator(sample / "radar")) {
    tree.copy(entry.path(), std::string(kRun) + "/radar/" + entry.path().filename().string());
  }
  tree.copy(sample / "radar.timestamps", std::string(kRun) + "/radar.timestamps");
  tree.copy(sample / "gps" / "gps.csv", std::string(kRun) + "/gps/gps.csv");
  tree.copy(sample / "gt" / "radar_odometry.csv", std::string(kRun) + "/gt/radar_odometry.csv");
}

OxfordOptions options(const TempTree& tree, OxfordPoseSource poses) {
  OxfordOptions o;
  o.common.root = tree.root();
  o.common.sequence = kRun;
  o.poses = poses;
  return o;
}

struct GpsRow {
  std::int64_t t_us;
  double northing;
  double easting;
};

// gps.csv read independently of the loader: timestamp is column 0, northing 8, easting 9.
std::vector<GpsRow> read_gps_by_hand(const fs::path& path) {
  std::ifstream file(path);
  std::string line;
  std::getline(file, line);  // header
  std::vector<GpsRow> rows;
  while (std::getline(file, line)) {
    std::vector<std::string> fields;
    std::stringstream stream(line);
    for (std::string field; std::getline(stream, field, ',');) fields.push_back(field);
    rows.push_back({std::stoll(fields[0]), std::stod(fields[8]), std::stod(fields[9])});
  }
  return rows;
}

TEST(OxfordDataset, ScansShapesTimesAndAzimuthsOfTheRealSample) {
  RADARPR_SKIP_WITHOUT(real_data(kTiny), "Oxford tiny sample");
  TempTree tree;
  make_run(tree);
  const auto sequence = open_oxford(options(tree, OxfordPoseSource::automatic));
  EXPECT_EQ(sequence->name(), std::string("oxford(") + kRun + ")");
  ASSERT_EQ(sequence->size(), 11u);
  // File names are µs: 1547131046353776 µs -> ns.
  EXPECT_EQ(sequence->records().front().timestamp_ns, 1'547'131'046'353'776'000);
  EXPECT_EQ(sequence->records().back().timestamp_ns, 1'547'131'048'845'472'000);

  const PolarImage image = sequence->load_image(0);
  EXPECT_EQ(image.azimuth_count(), 400);
  EXPECT_EQ(image.range_bin_count(), 3768);  // 3779 - 11 metadata columns
  EXPECT_DOUBLE_EQ(image.range_resolution_m, 0.0432);
  // Oxford names a scan by its first azimuth's time.
  EXPECT_EQ(image.azimuth_times_ns.front(), sequence->records().front().timestamp_ns);
  // Azimuth 0 from the encoder bytes 8-9 of row 0, read here from the raw PNG.
  const cv::Mat raw = cv::imread(sequence->records().front().source, cv::IMREAD_UNCHANGED);
  const int encoder = raw.at<std::uint8_t>(0, 8) | (raw.at<std::uint8_t>(0, 9) << 8);
  EXPECT_DOUBLE_EQ(image.azimuths_rad[0], 2.0 * std::numbers::pi * encoder / 5600.0);
  EXPECT_EQ(image.power(17, 100), raw.at<std::uint8_t>(17, 111));

  const DatasetReport report = sequence->describe();
  EXPECT_EQ(report.azimuths, 400);
  EXPECT_EQ(report.range_bins, 3768);
  EXPECT_EQ(report.scan_files, 11u);
  EXPECT_EQ(report.posed_scans, 11u);
  EXPECT_EQ(report.scans_without_pose, 0u);
  ASSERT_TRUE(report.invalid_azimuth_rows.has_value());
  EXPECT_EQ(*report.invalid_azimuth_rows, 0);
  EXPECT_TRUE(report.warnings.empty()) << report.warnings.front();
}

TEST(OxfordDataset, GpsPositionsAreInterpolatedAtEachScanTime) {
  RADARPR_SKIP_WITHOUT(real_data(kTiny), "Oxford tiny sample");
  TempTree tree;
  make_run(tree);
  const auto sequence = open_oxford(options(tree, OxfordPoseSource::automatic));
  EXPECT_EQ(sequence->position_frame(), PositionFrame::global);  // no ins.csv: gps.csv
  EXPECT_NE(sequence->describe().pose_source.find("gps/gps.csv"), std::string::npos);
  const auto gps = read_gps_by_hand(real_data(kTiny) / "gps" / "gps.csv");
  for (const ScanRecord& record : sequence->records()) {
    const std::int64_t t_us = record.timestamp_ns / 1000;
    std::size_t i = 0;
    while (gps[i + 1].t_us <= t_us) ++i;  // gps[i] <= t < gps[i + 1]
    const double f = static_cast<double>(t_us - gps[i].t_us) /
                     static_cast<double>(gps[i + 1].t_us - gps[i].t_us);
    EXPECT_NEAR(record.pose.x, gps[i].easting + f * (gps[i + 1].easting - gps[i].easting), 1e-6);
    EXPECT_NEAR(record.pose.y, gps[i].northing + f * (gps[i + 1].northing - gps[i].northing), 1e-6);
  }
}

// Best rigid 2-D fit of `from` onto `to` (rotation + translation); returns the largest residual.
double largest_residual_after_alignment(const std::vector<Pose2D>& from,
                                        const std::vector<Pose2D>& to) {
  const double n = static_cast<double>(from.size());
  double fx = 0, fy = 0, tx = 0, ty = 0;
  for (std::size_t i = 0; i < from.size(); ++i) {
    fx += from[i].x / n, fy += from[i].y / n, tx += to[i].x / n, ty += to[i].y / n;
  }
  double dot = 0, cross = 0;
  for (std::size_t i = 0; i < from.size(); ++i) {
    const double ax = from[i].x - fx, ay = from[i].y - fy, bx = to[i].x - tx, by = to[i].y - ty;
    dot += ax * bx + ay * by;
    cross += ax * by - ay * bx;
  }
  const double angle = std::atan2(cross, dot);
  double largest = 0;
  for (std::size_t i = 0; i < from.size(); ++i) {
    const double ax = from[i].x - fx, ay = from[i].y - fy;
    const double x = std::cos(angle) * ax - std::sin(angle) * ay + tx;
    const double y = std::sin(angle) * ax + std::cos(angle) * ay + ty;
    largest = std::max(largest, std::hypot(x - to[i].x, y - to[i].y));
  }
  return largest;
}

double path_length(const std::vector<Pose2D>& poses) {
  double length = 0;
  for (std::size_t i = 1; i < poses.size(); ++i) {
    length += std::hypot(poses[i].x - poses[i - 1].x, poses[i].y - poses[i - 1].y);
  }
  return length;
}

TEST(OxfordDataset, GpsAndIntegratedOdometryAgreeWithinAFewMetres) {
  RADARPR_SKIP_WITHOUT(real_data(kTiny), "Oxford tiny sample");
  TempTree tree;
  make_run(tree);
  const auto by_gps = open_oxford(options(tree, OxfordPoseSource::gps));
  const auto by_odometry = open_oxford(options(tree, OxfordPoseSource::odometry));
  EXPECT_EQ(by_gps->position_frame(), PositionFrame::global);
  EXPECT_EQ(by_odometry->position_frame(), PositionFrame::local);
  ASSERT_EQ(by_gps->size(), 11u);
  ASSERT_EQ(by_odometry->size(), 11u);
  std::vector<Pose2D> gps, odometry;
  for (std::size_t i = 0; i < 11; ++i) {
    EXPECT_EQ(by_gps->records()[i].timestamp_ns, by_odometry->records()[i].timestamp_ns);
    gps.push_back(by_gps->records()[i].pose);
    odometry.push_back(by_odometry->records()[i].pose);
  }
  const double residual = largest_residual_after_alignment(odometry, gps);
  const double gps_length = path_length(gps);
  const double odometry_length = path_length(odometry);
  std::printf(
      "[ measured ] Oxford tiny: path %.2f m by GPS, %.2f m by odometry; largest "
      "residual after rigid alignment %.2f m\n",
      gps_length, odometry_length, residual);
  EXPECT_GT(gps_length, 15.0);  // a real drive, not a standstill
  EXPECT_LT(residual, 3.0);
  EXPECT_NEAR(gps_length, odometry_length, 3.0);
}

TEST(OxfordDataset, InsIsPreferredAndItsHeadingBecomesYaw) {
  RADARPR_SKIP_WITHOUT(real_data(kTiny), "Oxford tiny sample");
  TempTree tree;
  make_run(tree);
  // Synthetic INS (the sample has none) around the scans: heading 0 = north, so yaw = pi / 2;
  // easting 1000 -> 1004 over 4 s.
  tree.write(std::string(kRun) + "/gps/ins.csv",
             "timestamp,ins_status,latitude,longitude,altitude,northing,easting,down,utm_zone,"
             "velocity_north,velocity_east,velocity_down,roll,pitch,yaw\n"
             "1547131045000000,INS_SOLUTION_GOOD,0,0,0,5000,1000,0,30U,0,0,0,0,0,0\n"
             "1547131049000000,INS_SOLUTION_GOOD,0,0,0,5000,1004,0,30U,0,0,0,0,0,0\n");
  const auto sequence = open_oxford(options(tree, OxfordPoseSource::automatic));
  EXPECT_NE(sequence->describe().pose_source.find("gps/ins.csv"), std::string::npos);
  ASSERT_EQ(sequence->size(), 11u);
  const ScanRecord& first = sequence->records().front();
  // 1547131046.353776 s is 1.353776 s after the first INS row: easting 1001.353776.
  EXPECT_NEAR(first.pose.x, 1001.353776, 1e-6);
  EXPECT_NEAR(first.pose.y, 5000.0, 1e-9);
  EXPECT_NEAR(first.pose.yaw, std::numbers::pi / 2, 1e-12);
}

TEST(OxfordDataset, LaterScansOfTheSameRunAreMatchedAndTheTimestampListIsCrossChecked) {
  RADARPR_SKIP_WITHOUT(real_data(kTiny), "Oxford tiny sample");
  RADARPR_SKIP_WITHOUT(real_data("oxford_radar_robotcar_extra_evanflash"), "Oxford extra scans");
  TempTree tree;
  make_run(tree);
  // Two scans ~2 s after the 11, not listed in radar.timestamps.
  for (const char* name : {"1547131050856549.png", "1547131051108813.png"}) {
    tree.copy(real_data("oxford_radar_robotcar_extra_evanflash") / name,
              std::string(kRun) + "/radar/" + name);
  }
  auto o = options(tree, OxfordPoseSource::odometry);
  o.common.window.start = 11;  // indices into the 13 scans in time order
  const auto sequence = open_oxford(o);
  ASSERT_EQ(sequence->size(), 2u);
  EXPECT_EQ(sequence->records()[0].timestamp_ns, 1'547'131'050'856'549'000);
  const DatasetReport report = sequence->describe();
  EXPECT_EQ(report.scan_files, 13u);
  EXPECT_EQ(report.window, "[11, end)");
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_NE(report.warnings[0].find("radar.timestamps lists 11 scans and radar/ holds 13 PNGs"),
            std::string::npos)
      << report.warnings[0];
  // The odometry's radar timestamps are the file names, so both scans sit exactly on chained
  // poses: their distance is the step of the row linking them (line 148 of radar_odometry.csv:
  // x = 0.864929, y = 0.004842, the car braking).
  const Pose2D& a = sequence->records()[0].pose;
  const Pose2D& b = sequence->records()[1].pose;
  EXPECT_NEAR(std::hypot(b.x - a.x, b.y - a.y), std::hypot(0.864929, 0.004842), 1e-9);
}

constexpr const char* kOdometryHeader =
    "source_timestamp,destination_timestamp,x,y,z,roll,pitch,yaw,source_radar_timestamp,"
    "destination_radar_timestamp\n";
// Three steps of 1 m forward, the second one ending with a left turn by pi / 2.
constexpr const char* kThreeSteps =
    "0,0,1,0,0,0,0,0,1547131000250000,1547131000000000\n"
    "0,0,1,0,0,0,0,1.5707963267948966,1547131000500000,1547131000250000\n"
    "0,0,1,0,0,0,0,0,1547131000750000,1547131000500000\n";

TEST(OxfordDataset, IntegratesOdometrySourceInDestinationFrame) {
  TempTree tree;
  const auto path = tree.write("radar_odometry.csv", std::string(kOdometryHeader) + kThreeSteps);
  const PoseTrack track = integrate_oxford_radar_odometry(path);
  // By hand: origin -> (1, 0) -> (2, 0) now facing +y -> 1 m along +y: (2, 1).
  ASSERT_EQ(track.size(), 4u);
  EXPECT_EQ(track.first_ns(), 1'547'131'000'000'000'000);
  EXPECT_NEAR(track.samples()[1].pose.x, 1.0, 1e-12);
  EXPECT_NEAR(track.samples()[2].pose.x, 2.0, 1e-12);
  EXPECT_NEAR(track.samples()[2].pose.yaw, std::numbers::pi / 2, 1e-12);
  EXPECT_NEAR(track.samples()[3].pose.x, 2.0, 1e-12);
  EXPECT_NEAR(track.samples()[3].pose.y, 1.0, 1e-12);
}

TEST(OxfordDataset, AnOdometryChainWithAHoleNamesTheLine) {
  TempTree tree;
  // Row 4 (line 5) starts from 1547131001000000, which no earlier row reached.
  const auto path =
      tree.write("radar_odometry.csv", std::string(kOdometryHeader) + kThreeSteps +
                                           "0,0,1,0,0,0,0,0,1547131001250000,1547131001000000\n");
  expect_error<std::runtime_error>([&] { integrate_oxford_radar_odometry(path); },
                                   {path.string() + ":5:", "chain is broken"});
}

}  // namespace
}  // namespace radarpr
