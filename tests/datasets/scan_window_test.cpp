#include "datasets/real/scan_window.hpp"

#include <cstdint>
#include <stdexcept>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "datasets/real/azimuth_resampling.hpp"

namespace radarpr {
namespace {

using Indices = std::vector<std::size_t>;

TEST(ScanWindow, StartEndAreIndicesAppliedBeforeEveryNth) {
  EXPECT_EQ(select_scans({}, 4, "x"), (Indices{0, 1, 2, 3}));
  // [1, 8) of 10, every 3rd: 1, 4, 7.
  EXPECT_EQ(select_scans({.start = 1, .end = 8, .every_nth = 3}, 10, "x"), (Indices{1, 4, 7}));
  EXPECT_EQ(select_scans({.start = 8, .every_nth = 5}, 10, "x"), (Indices{8}));
  EXPECT_EQ(describe(ScanWindow{}), "all");
  EXPECT_EQ(describe(ScanWindow{.start = 1, .end = 8, .every_nth = 3}), "[1, 8) every 3rd");
  EXPECT_EQ(describe(ScanWindow{.start = 5}), "[5, end)");
}

TEST(ScanWindow, RejectsEmptyOrOversizedWindowsNamingTheSource) {
  EXPECT_THROW(select_scans({.every_nth = 0}, 10, "x"), std::invalid_argument);
  EXPECT_THROW(select_scans({.start = 10}, 10, "x"), std::invalid_argument);
  EXPECT_THROW(select_scans({.start = 3, .end = 3}, 10, "x"), std::invalid_argument);
  try {
    select_scans({.end = 11}, 10, "/data/KAIST03");
    ADD_FAILURE();
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("/data/KAIST03: end = 11 is beyond the 10 scans"),
              std::string::npos)
        << error.what();
  }
}

cv::Mat column(std::initializer_list<int> values) {
  cv::Mat image(static_cast<int>(values.size()), 1, CV_8UC1);
  int row = 0;
  for (int v : values) image.at<std::uint8_t>(row++, 0) = static_cast<std::uint8_t>(v);
  return image;
}

std::vector<int> rows_of(const cv::Mat& image) {
  std::vector<int> values;
  for (int r = 0; r < image.rows; ++r) values.push_back(image.at<std::uint8_t>(r, 0));
  return values;
}

TEST(AzimuthResampling, LinearBetweenNeighbouringRowsWrappingAround) {
  // 3 rows -> 6: positions a * 3 / 6 = 0, 0.5, 1, 1.5, 2, 2.5; 2.5 lies between the last row
  // (60) and the first (0): 30.
  EXPECT_EQ(rows_of(resample_azimuth_rows(column({0, 30, 60}), 6)),
            (std::vector<int>{0, 15, 30, 45, 60, 30}));
  // 4 rows -> 2: positions 0 and 2.
  EXPECT_EQ(rows_of(resample_azimuth_rows(column({0, 40, 80, 120}), 2)), (std::vector<int>{0, 80}));
  // 4 rows -> 3: positions 0, 4/3, 8/3: 10 + (20 - 10) / 3 = 13.33 -> 13;
  // 20 + (30 - 20) * 2/3 = 26.67 -> 27.
  EXPECT_EQ(rows_of(resample_azimuth_rows(column({0, 10, 20, 30}), 3)),
            (std::vector<int>{0, 13, 27}));
  EXPECT_EQ(rows_of(resample_azimuth_rows(column({7, 8}), 2)), (std::vector<int>{7, 8}));
  EXPECT_THROW(resample_azimuth_rows(cv::Mat(), 4), std::invalid_argument);
  EXPECT_THROW(resample_azimuth_rows(column({1}), 0), std::invalid_argument);
}

}  // namespace
}  // namespace radarpr
