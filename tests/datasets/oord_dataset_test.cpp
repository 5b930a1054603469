// The OORD loader on a temporary <site>/<date> folder: real CTS350-X scans from the Oxford sample
// (the same sensor; OORD ships no public sample), one with two azimuth rows dropped, and
// synthetic MicrostrainMIP GPS.
#include "datasets/real/oord_dataset.hpp"

#include <numbers>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "descriptors/opencv_image.hpp"
#include "tests/datasets/dataset_tree.hpp"

namespace radarpr {
namespace {

using test::real_data;
using test::TempTree;
namespace fs = std::filesystem;

constexpr const char* kRadar = "oxford_radar_robotcar_tiny_radarslampy/radar";
constexpr const char* kSequence = "bellmouth/2021-11-25-12-31-19";
constexpr std::int64_t kFirstUs = 1'547'131'046'353'776;

TEST(OordDataset, DroppedRowsAreResampledToUniformAzimuths) {
  RADARPR_SKIP_WITHOUT(real_data(kRadar), "Oxford tiny sample");
  TempTree tree;
  const std::string radar = std::string(kSequence) + "/Navtech_CTS350-X_Radar/";
  // The first scan loses rows 100 and 300 (398 rows left); the next two are complete.
  const cv::Mat full = cv::imread((real_data(kRadar) / fmt::format("{}.png", kFirstUs)).string(),
                                  cv::IMREAD_UNCHANGED);
  ASSERT_EQ(full.rows, 400);
  cv::Mat dropped;
  cv::vconcat(
      std::vector<cv::Mat>{full.rowRange(0, 100), full.rowRange(101, 300), full.rowRange(301, 400)},
      dropped);
  tree.folder(radar);
  ASSERT_TRUE(cv::imwrite(tree.path(radar + std::to_string(kFirstUs) + ".png").string(), dropped));
  for (const char* name : {"1547131046606586.png", "1547131046858560.png"}) {
    tree.copy(real_data(kRadar) / name, radar + name);
  }
  // Synthetic GPS (µs), 1 m east per second.
  tree.write(std::string(kSequence) + "/MicrostrainMIP/gps.csv",
             "timestamp,utm_northing,utm_easting,altitude\n"
             "1547131046000000,6300000.0,450000.0,10\n"
             "1547131048000000,6300000.0,450002.0,10\n");

  OordOptions o;
  o.common.root = tree.root();
  o.common.sequence = kSequence;
  const auto sequence = open_oord(o);
  ASSERT_EQ(sequence->size(), 3u);
  EXPECT_EQ(sequence->name(), std::string("oord(") + kSequence + ")");
  // 0.353776 s after the first GPS row: easting + 0.353776.
  EXPECT_NEAR(sequence->records()[0].pose.x, 450000.353776, 1e-6);
  EXPECT_NEAR(sequence->records()[0].pose.y, 6300000.0, 1e-9);

  const PolarImage image = sequence->load_image(0);
  ASSERT_EQ(image.azimuth_count(), 400);
  ASSERT_EQ(image.range_bin_count(), 3768);
  EXPECT_TRUE(image.azimuth_times_ns.empty());  // row metadata is not trusted
  EXPECT_NEAR(image.azimuths_rad[1], 2 * std::numbers::pi / 400, 1e-12);
  // Output row a samples input position a * 398 / 400. Row 0 -> input row 0 (original 0);
  // row 200 -> input 199.0 exactly, which is original row 200 (row 100 was dropped before it).
  const cv::Mat power = full.colRange(11, full.cols);
  EXPECT_EQ(cv::norm(opencv_view(image.power).row(0), power.row(0), cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(opencv_view(image.power).row(200), power.row(200), cv::NORM_INF), 0.0);
  // The complete scans are passed through unchanged.
  const cv::Mat second =
      cv::imread((real_data(kRadar) / "1547131046606586.png").string(), cv::IMREAD_UNCHANGED);
  EXPECT_EQ(cv::norm(opencv_view(sequence->load_image(1).power), second.colRange(11, second.cols),
                     cv::NORM_INF),
            0.0);

  const DatasetReport report = sequence->describe();
  EXPECT_EQ(report.azimuths, 400);
  bool noted = false;
  for (const auto& note : report.notes) {
    noted = noted ||
            note.find("the first scan has 398 azimuth rows, resampled to 400") != std::string::npos;
  }
  EXPECT_TRUE(noted);
}

// An OORD sequence whose first scan is `first` (written as a PNG) followed by two real scans, with
// GPS covering them.
OordOptions sequence_with_first_scan(const TempTree& tree, const cv::Mat& first) {
  const std::string radar = std::string(kSequence) + "/Navtech_CTS350-X_Radar/";
  tree.folder(radar);
  EXPECT_TRUE(cv::imwrite(tree.path(radar + std::to_string(kFirstUs) + ".png").string(), first));
  for (const char* name : {"1547131046606586.png", "1547131046858560.png"}) {
    tree.copy(real_data(kRadar) / name, radar + name);
  }
  tree.write(std::string(kSequence) + "/MicrostrainMIP/gps.csv",
             "timestamp,utm_northing,utm_easting\n"
             "1547131046000000,6300000.0,450000.0\n"
             "1547131048000000,6300000.0,450002.0\n");
  OordOptions o;
  o.common.root = tree.root();
  o.common.sequence = kSequence;
  return o;
}

cv::Mat real_scan() {
  return cv::imread((real_data(kRadar) / fmt::format("{}.png", kFirstUs)).string(),
                    cv::IMREAD_UNCHANGED);
}

// A transposed scan (3779 high x 400 wide) used to be read as azimuth rows of 389 bins.
TEST(OordDataset, ATransposedScanIsRefused) {
  RADARPR_SKIP_WITHOUT(real_data(kRadar), "Oxford tiny sample");
  TempTree tree;
  const cv::Mat transposed = real_scan().t();
  const auto o = sequence_with_first_scan(tree, transposed);
  test::expect_error<std::runtime_error>(
      [&] { open_oord(o); },
      {std::to_string(kFirstUs) + ".png", "400 wide x 3779 high", "expected the Oxford layout"});
}

// Resampling covers a few dropped rows; 401 rows or fewer than 0.8 x 400 = 320 is a wrong file.
TEST(OordDataset, RowCountsOutsideTheConfiguredAzimuthsAreRefusedNamingTheFile) {
  RADARPR_SKIP_WITHOUT(real_data(kRadar), "Oxford tiny sample");
  const cv::Mat full = real_scan();
  {
    TempTree tree;
    cv::Mat extra;
    cv::vconcat(full, full.row(0), extra);  // 401 rows
    const auto o = sequence_with_first_scan(tree, extra);
    test::expect_error<std::runtime_error>(
        [&] { open_oord(o); },
        {std::to_string(kFirstUs) + ".png", "401 azimuth rows, expected 320 to 400"});
  }
  {
    TempTree tree;
    const auto o = sequence_with_first_scan(tree, full.rowRange(0, 319));
    test::expect_error<std::runtime_error>(
        [&] { open_oord(o); },
        {std::to_string(kFirstUs) + ".png", "319 azimuth rows, expected 320 to 400"});
  }
  {
    TempTree tree;  // 320 rows: a fifth dropped is still resampled
    const auto o = sequence_with_first_scan(tree, full.rowRange(0, 320));
    EXPECT_EQ(open_oord(o)->load_image(0).azimuth_count(), 400);
  }
  {
    // A later scan with too few rows is found when the sequence opens, from its PNG header.
    TempTree tree;
    const auto o = sequence_with_first_scan(tree, full);
    const fs::path late =
        tree.path(std::string(kSequence) + "/Navtech_CTS350-X_Radar/1547131046858560.png");
    ASSERT_TRUE(cv::imwrite(late.string(), full.rowRange(0, 100)));
    test::expect_error<std::runtime_error>([&] { open_oord(o); },
                                           {late.string(), "100 azimuth rows, expected 320"});
  }
}

TEST(OordDataset, ARangeBinCountOtherThanTheCts350xIsAWarning) {
  RADARPR_SKIP_WITHOUT(real_data(kRadar), "Oxford tiny sample");
  TempTree tree;
  // 3379 - 11 = 3368 range bins instead of 3768: a cropped copy, say. The other two scans must
  // match it, so all three are cropped.
  const cv::Mat full = real_scan();
  auto o = sequence_with_first_scan(tree, full.colRange(0, 3379));
  for (const char* name : {"1547131046606586.png", "1547131046858560.png"}) {
    const cv::Mat scan =
        cv::imread((real_data(kRadar) / name).string(), cv::IMREAD_UNCHANGED).colRange(0, 3379);
    ASSERT_TRUE(cv::imwrite(
        tree.path(std::string(kSequence) + "/Navtech_CTS350-X_Radar/" + name).string(), scan));
  }
  // The synthetic GPS's 2 s gap gives a warning of its own; only the range bin one matters here.
  const auto range_bin_warnings = [](const DatasetReport& report) {
    std::vector<std::string> found;
    for (const auto& warning : report.warnings) {
      if (warning.find("range bins") != std::string::npos) found.push_back(warning);
    }
    return found;
  };
  const DatasetReport report = open_oord(o)->describe();
  const auto warnings = range_bin_warnings(report);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(
      warnings[0].find("the first scan has 3368 range bins, but the OORD CTS350-X gives 3768"),
      std::string::npos)
      << warnings[0];
  EXPECT_EQ(report.scan_time_reference.find("the file name's time"), 0u);
  // The full scans give no warning.
  TempTree complete;
  EXPECT_TRUE(
      range_bin_warnings(open_oord(sequence_with_first_scan(complete, full))->describe()).empty());
}

}  // namespace
}  // namespace radarpr
