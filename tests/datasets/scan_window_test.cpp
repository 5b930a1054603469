#include "datasets/real/scan_window.hpp"

#include <cmath>
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

ByteImage column(std::initializer_list<int> values) {
  ByteImage image(static_cast<int>(values.size()), 1);
  int row = 0;
  for (int v : values) image(row++, 0) = static_cast<std::uint8_t>(v);
  return image;
}

std::vector<int> rows_of(const ByteImage& image) {
  std::vector<int> values;
  for (int r = 0; r < image.rows(); ++r) values.push_back(image(r, 0));
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
  EXPECT_THROW(resample_azimuth_rows(ByteImage(), 4), std::invalid_argument);
  EXPECT_THROW(resample_azimuth_rows(column({1}), 0), std::invalid_argument);
}

// The resampling was cv::addWeighted per output row; the OORD results were made with it. Every
// pair of neighbouring rows here holds every (low, high) byte pair, in rows wide enough for
// OpenCV's vectorised path (the one real scans take), at the fractions of several row counts.
TEST(AzimuthResampling, SameBytesAsOpenCvAddWeightedForEveryPairOfValues) {
  constexpr int kPairs = 256 * 256;
  for (const auto& [rows, azimuths] :
       {std::pair{398, 400}, std::pair{401, 400}, std::pair{7, 400}, std::pair{5, 3}}) {
    // Column c of an even row holds c / 256, of an odd row c % 256: rows i and i + 1 (and the
    // wrap from the last to the first) meet every (low, high) pair.
    const int columns = kPairs;
    ByteImage scan(rows, columns);
    for (int r = 0; r < rows; ++r) {
      for (int c = 0; c < columns; ++c) {
        scan(r, c) = static_cast<std::uint8_t>(r % 2 == 0 ? c / 256 : c % 256);
      }
    }
    const ByteImage ours = resample_azimuth_rows(scan, azimuths);
    const cv::Mat input(rows, columns, CV_8UC1, scan.data());
    cv::Mat expected(azimuths, columns, CV_8UC1);
    for (int a = 0; a < azimuths; ++a) {
      const double position = static_cast<double>(a) * rows / azimuths;
      const int below = static_cast<int>(std::floor(position));
      const double f = position - below;
      cv::Mat target = expected.row(a);
      cv::addWeighted(input.row(below), 1.0 - f, input.row((below + 1) % rows), f, 0.0, target);
    }
    ASSERT_EQ(ours.rows(), azimuths);
    const cv::Mat got(azimuths, columns, CV_8UC1, const_cast<std::uint8_t*>(ours.data()));
    EXPECT_EQ(cv::countNonZero(got != expected), 0) << rows << " rows to " << azimuths;
  }
}

}  // namespace
}  // namespace radarpr
