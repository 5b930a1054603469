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
  EXPECT_EQ(cv::norm(image.power.row(0), power.row(0), cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(image.power.row(200), power.row(200), cv::NORM_INF), 0.0);
  // The complete scans are passed through unchanged.
  const cv::Mat second =
      cv::imread((real_data(kRadar) / "1547131046606586.png").string(), cv::IMREAD_UNCHANGED);
  EXPECT_EQ(cv::norm(sequence->load_image(1).power, second.colRange(11, second.cols), cv::NORM_INF),
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

}  // namespace
}  // namespace radarpr
