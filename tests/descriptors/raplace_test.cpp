// RaPlace (descriptors.md §5): every stage on hand-computed inputs, the descriptor through the
// registry, and real MulRan KAIST03 scans (../shared/data/real/referee_mulran_kaist03).
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "descriptors/descriptor_registry.hpp"
#include "descriptors/raplace/circular_correlation.hpp"
#include "descriptors/raplace/polar_to_cartesian.hpp"
#include "descriptors/raplace/radon_transform.hpp"
#include "descriptors/raplace/raplace.hpp"
#include "descriptors/raplace/sinogram_spectrum.hpp"
#include "tests/descriptors/mulran_frames.hpp"

namespace radarpr {
namespace {

using testing::native_frame;
using testing::read_native;

using raplace::ShiftAxis;

constexpr double kPi = std::numbers::pi;

// A azimuth rows x R range bins of zeros, 1 m per bin, uniform azimuths.
PolarImage blank_scan(int azimuths, int range_bins, double resolution_m = 1.0) {
  PolarImage scan;
  scan.power = ByteImage(azimuths, range_bins, 0);
  scan.azimuths_rad = uniform_azimuths(azimuths);
  scan.range_resolution_m = resolution_m;
  return scan;
}

// Query row a = database row a + rows (mod A): the sensor turned by rows * 2 pi / A.
PolarImage turned_by_rows(const PolarImage& scan, int rows) {
  const int azimuths = scan.azimuth_count();
  PolarImage turned = scan;
  turned.power = ByteImage(scan.power.rows(), scan.power.cols());
  for (int a = 0; a < azimuths; ++a) {
    std::copy_n(scan.power.row(((a + rows) % azimuths + azimuths) % azimuths), scan.power.cols(),
                turned.power.row(a));
  }
  return turned;
}

// An asymmetric made-up scene: 360 azimuths (1 degree each), 500 bins of 0.4 m, a few walls and
// posts of different brightness, none repeating under a half turn.
PolarImage synthetic_scene() {
  PolarImage scan = blank_scan(360, 500, 0.4);
  const auto paint = [&](int a0, int a1, int r0, int r1, int value) {
    for (int a = a0; a < a1; ++a) {
      for (int r = r0; r < r1; ++r) scan.power(a % 360, r) = cv::saturate_cast<std::uint8_t>(value);
    }
  };
  paint(30, 80, 100, 110, 200);   // an arc wall
  paint(150, 154, 50, 300, 150);  // a radial wall
  paint(200, 290, 380, 392, 255);
  paint(300, 306, 200, 214, 120);  // a post
  paint(330, 372, 60, 66, 90);     // an arc across azimuth 0
  return scan;
}

std::vector<float> random_values(std::mt19937& generator, std::size_t count) {
  std::vector<float> values(count);
  // Raw mt19937 output is the same on every platform (distributions are not).
  for (float& value : values) value = static_cast<float>(generator() % 4001) / 1000.0f - 2.0f;
  return values;
}

// ---------------------------------------------------------------------------------------------
// Step 1: polar -> Cartesian.

// 9 x 9 pixels over +-2.25 m: 0.5 m pixels, the sensor at the centre of pixel (4, 4); pixel
// (i, j) at x = (j - 4) * 0.5, y = (4 - i) * 0.5. Four uniform azimuths (0, 90, 180, 270 deg),
// three 1 m bins centred at 0.5, 1.5, 2.5 m.
TEST(RaplacePolarToCartesian, BrightBinsLandAtTheRightPixelsCounterClockwise) {
  PolarImage scan = blank_scan(4, 3);
  scan.power(0, 1) = 100;  // azimuth 0, 1.5 m
  scan.power(1, 1) = 200;  // azimuth 90 deg, 1.5 m
  const cv::Mat image = raplace::polar_to_cartesian(scan, 9, 2.25);
  ASSERT_EQ(image.rows, 9);
  ASSERT_EQ(image.cols, 9);
  ASSERT_EQ(image.type(), CV_32FC1);
  // Azimuth 0 points right: pixel (4, 7) is x = 1.5, y = 0 -> bearing 0, bin 1.5 / 1 - 0.5 = 1.
  EXPECT_NEAR(image.at<float>(4, 7), 100.0, 1e-4);
  // Azimuth 90 deg points up (towards row 0): pixel (1, 4) is x = 0, y = 1.5.
  EXPECT_NEAR(image.at<float>(1, 4), 200.0, 1e-4);
  // Left (180 deg, row 2) and down (270 deg, row 3) are dark: the image is not mirrored.
  EXPECT_EQ(image.at<float>(4, 1), 0.0f);
  EXPECT_EQ(image.at<float>(7, 4), 0.0f);
  // Along range: y = 1.0 m -> bin 0.5 = half of bin 0 (0) and half of bin 1 (200); y = 2.0 m ->
  // bin 1.5 = half of bin 1 and half of bin 2 (0).
  EXPECT_NEAR(image.at<float>(2, 4), 100.0, 1e-4);
  EXPECT_NEAR(image.at<float>(0, 4), 100.0, 1e-4);
  // Bilinear in (azimuth, range): pixel (1, 5) is x = 0.5, y = 1.5: range sqrt(2.5) = 1.581139
  // -> bin 1.081139 (weight 0.081139 on bin 2, which is 0); bearing atan2(1.5, 0.5) = 71.565 deg
  // -> weight 71.565 / 90 = 0.795167 on row 1.
  // (1 - 0.795167) * 0.918861 * 100 + 0.795167 * 0.918861 * 200 = 164.950947.
  EXPECT_NEAR(image.at<float>(1, 5), 164.950947, 1e-3);
  // The sensor pixel: range 0 -> bin 0 (clamped), bearing atan2(0, 0) = 0 -> row 0, bin 0 = 0.
  EXPECT_EQ(image.at<float>(4, 4), 0.0f);
}

TEST(RaplacePolarToCartesian, UnevenAzimuthsInterpolateInAngleAndWrapFromTheLastRowToTheFirst) {
  PolarImage scan = blank_scan(4, 3);
  scan.azimuths_rad = {0.0, 0.5 * kPi, 1.2 * kPi, 1.5 * kPi};
  const int row_values[4] = {200, 70, 140, 100};  // constant along range
  for (int a = 0; a < 4; ++a) {
    std::fill_n(scan.power.row(a), scan.power.cols(), static_cast<std::uint8_t>(row_values[a]));
  }
  const cv::Mat image = raplace::polar_to_cartesian(scan, 9, 2.25);
  // Pixel (4, 1): bearing 180 deg, between row 1 (90) and row 2 (216 deg): weight 90 / 126 = 5/7
  // on row 2 -> 70 * 2/7 + 140 * 5/7 = 20 + 100 = 120.
  EXPECT_NEAR(image.at<float>(4, 1), 120.0, 1e-4);
  // Pixel (7, 7): x = 1.5, y = -1.5, bearing 315 deg, range 2.12 m (bins 1 and 2, both
  // inside). Between row 3 (270) and row 0 one turn later (360): weight 1/2 -> (100 + 200) / 2.
  EXPECT_NEAR(image.at<float>(7, 7), 150.0, 1e-4);
  // Exactly on row 1's azimuth (pixel (2, 4), straight up).
  EXPECT_NEAR(image.at<float>(2, 4), 70.0, 1e-4);
}

TEST(RaplacePolarToCartesian, AzimuthsThatStartAnywhereGiveTheSameImage) {
  // The same scene with its rows listed from azimuth 90 deg on, the last row at azimuth 0:
  // unwrapping the list must recover the same geometry.
  PolarImage scan = blank_scan(4, 3);
  scan.power(0, 1) = 100;
  scan.power(1, 2) = 200;
  scan.power(2, 0) = 50;
  PolarImage rotated_list = turned_by_rows(scan, 1);  // row a holds azimuth a + 1
  rotated_list.azimuths_rad = {0.5 * kPi, kPi, 1.5 * kPi, 0.0};
  const cv::Mat expected = raplace::polar_to_cartesian(scan, 9, 2.25);
  const cv::Mat actual = raplace::polar_to_cartesian(rotated_list, 9, 2.25);
  EXPECT_LT(cv::norm(expected, actual, cv::NORM_INF), 1e-3);
  EXPECT_GT(cv::norm(expected, cv::NORM_INF), 100.0);  // not trivially zero
}

TEST(RaplacePolarToCartesian, RangesBeyondTheLastBinAreZero) {
  PolarImage scan = blank_scan(4, 3);
  scan.power = ByteImage(scan.power.rows(), scan.power.cols(), 80);
  // 9 pixels over +-4.5 m: 1 m pixels at x = j - 4. Pixel (4, 6): 2 m -> bin 1.5, inside.
  // Pixel (4, 7): 3 m -> bin 2.5: half of bin 2 (80), half of the virtual bin 3 (0) = 40.
  // Pixel (4, 8): 4 m -> bin 3.5, beyond R = 3: 0.
  const cv::Mat image = raplace::polar_to_cartesian(scan, 9, 4.5);
  EXPECT_NEAR(image.at<float>(4, 6), 80.0, 1e-4);
  EXPECT_NEAR(image.at<float>(4, 7), 40.0, 1e-4);
  EXPECT_EQ(image.at<float>(4, 8), 0.0f);
  EXPECT_EQ(image.at<float>(0, 0), 0.0f);  // the corner, 5.66 m away
}

TEST(RaplacePolarToCartesian, RejectsUnusableScans) {
  PolarImage scan = blank_scan(4, 3);
  EXPECT_THROW(raplace::polar_to_cartesian(scan, 0, 2.0), std::invalid_argument);
  EXPECT_THROW(raplace::polar_to_cartesian(scan, 9, 0.0), std::invalid_argument);
  PolarImage no_resolution = scan;
  no_resolution.range_resolution_m = 0.0;
  EXPECT_THROW(raplace::polar_to_cartesian(no_resolution, 9, 2.0), std::invalid_argument);
  PolarImage wrong_count = scan;
  wrong_count.azimuths_rad = {0.0, 1.0};
  EXPECT_THROW(raplace::polar_to_cartesian(wrong_count, 9, 2.0), std::invalid_argument);
  PolarImage two_turns = scan;  // decreasing: each step wraps to almost a full turn
  two_turns.azimuths_rad = {3.0, 2.0, 1.0, 0.0};
  EXPECT_THROW(raplace::polar_to_cartesian(two_turns, 9, 2.0), std::invalid_argument);
  PolarImage not_finite = scan;
  not_finite.azimuths_rad[2] = std::nan("");
  EXPECT_THROW(raplace::polar_to_cartesian(not_finite, 9, 2.0), std::invalid_argument);
  PolarImage empty = scan;
  empty.power = ByteImage();
  EXPECT_THROW(raplace::polar_to_cartesian(empty, 9, 2.0), std::invalid_argument);
  PolarImage no_azimuth_list = scan;  // empty list = uniform: allowed
  no_azimuth_list.azimuths_rad.clear();
  EXPECT_NO_THROW(raplace::polar_to_cartesian(no_azimuth_list, 9, 2.0));
}

// ---------------------------------------------------------------------------------------------
// Step 2: Radon transform.

TEST(RaplaceRadon, RhoBinsAreTheCeiledDiagonal) {
  EXPECT_EQ(raplace::radon_rho_bins(280, 280), 396);  // 395.98
  EXPECT_EQ(raplace::radon_rho_bins(4, 4), 6);        // 5.66
  EXPECT_EQ(raplace::radon_rho_bins(3, 4), 5);        // exactly 5
  EXPECT_EQ(raplace::radon_rho_bins(1, 1), 2);        // 1.41
}

// 4 x 4 image: pixel centres at x, y in {-1.5, -0.5, 0.5, 1.5}; n_rho = 6 bins, rho = k - 2.5.
// One pixel of value 2 at row 0, column 3: x = 1.5, y = 1.5, so rho(theta) = 1.5 cos + 1.5 sin.
TEST(RaplaceRadon, OneBrightPixelTracesItsSinusoid) {
  cv::Mat image(4, 4, CV_32FC1, cv::Scalar(0));
  image.at<float>(0, 3) = 2.0f;
  const cv::Mat sinogram = raplace::radon_transform(image);
  ASSERT_EQ(sinogram.rows, 6);
  ASSERT_EQ(sinogram.cols, 180);
  ASSERT_EQ(sinogram.type(), CV_64FC1);
  const auto expect_column = [&](int theta, std::vector<double> expected) {
    for (int k = 0; k < 6; ++k) {
      EXPECT_NEAR(sinogram.at<double>(k, theta), expected[static_cast<std::size_t>(k)], 1e-6)
          << "theta " << theta << " rho bin " << k;
    }
  };
  // theta 0: rho 1.5 -> bin 4 exactly.
  expect_column(0, {0, 0, 0, 0, 2, 0});
  // theta 90: rho 1.5 again.
  expect_column(90, {0, 0, 0, 0, 2, 0});
  // theta 45: rho 2.121320 -> bin 4.621320: 2 * 0.378680 on bin 4, 2 * 0.621320 on bin 5.
  expect_column(45, {0, 0, 0, 0, 0.757359, 1.242641});
  // theta 60: rho 0.75 + 1.299038 = 2.049038 -> bin 4.549038.
  expect_column(60, {0, 0, 0, 0, 0.901924, 1.098076});
  // theta 135: rho -1.060660 + 1.060660 = 0 -> bin 2.5, split evenly.
  expect_column(135, {0, 0, 1, 1, 0, 0});
}

TEST(RaplaceRadon, SinusoidOfAPixelOfTheDefaultImage) {
  // 280 x 280: centre 139.5, n_rho 396, rho = k - 197.5. Pixel (row 139, column 149):
  // x = 9.5, y = 0.5.
  cv::Mat image(280, 280, CV_32FC1, cv::Scalar(0));
  image.at<float>(139, 149) = 1.0f;
  const cv::Mat sinogram = raplace::radon_transform(image);
  ASSERT_EQ(sinogram.rows, 396);
  EXPECT_NEAR(sinogram.at<double>(207, 0), 1.0, 1e-9);   // rho 9.5
  EXPECT_NEAR(sinogram.at<double>(198, 90), 1.0, 1e-9);  // rho 0.5
  // theta 135: rho = (-9.5 + 0.5) / sqrt 2 = -6.363961 -> bin 191.136039.
  EXPECT_NEAR(sinogram.at<double>(191, 135), 0.863961, 1e-6);
  EXPECT_NEAR(sinogram.at<double>(192, 135), 0.136039, 1e-6);
}

TEST(RaplaceRadon, EveryProjectionCarriesTheWholeImage) {
  std::mt19937 generator(7);
  cv::Mat image(12, 12, CV_32FC1);
  for (int i = 0; i < 12; ++i) {
    for (int j = 0; j < 12; ++j) image.at<float>(i, j) = static_cast<float>(generator() % 10);
  }
  const double total = cv::sum(image)[0];
  const cv::Mat sinogram = raplace::radon_transform(image);
  for (int theta = 0; theta < 180; ++theta) {
    EXPECT_NEAR(cv::sum(sinogram.col(theta))[0], total, 1e-9 * total) << "theta " << theta;
  }
}

// The largest difference between the run-by-run sums of a square image (radon_transform) and the
// pixel-by-pixel definition, relative to the largest value.
double segment_radon_difference(const cv::Mat& image) {
  const cv::Mat by_segments = raplace::radon_transform(image);
  const cv::Mat by_pixels = raplace::radon_transform_by_pixels(image);
  double largest = 0.0;
  cv::minMaxLoc(cv::abs(by_pixels), nullptr, &largest);
  return cv::norm(by_segments, by_pixels, cv::NORM_INF) / largest;
}

TEST(RaplaceRadon, RunSumsEqualThePixelByPixelDefinition) {
  std::mt19937 generator(11);
  for (const int size : {1, 2, 5, 12, 37, 40}) {
    cv::Mat image(size, size, CV_32FC1);
    for (int i = 0; i < size; ++i) {
      for (int j = 0; j < size; ++j) {
        // Some zeros, so that columns start and end inside the image.
        const auto draw = generator() % 300;
        image.at<float>(i, j) = draw < 100 ? 0.0f : static_cast<float>(draw) / 7.0f;
      }
    }
    EXPECT_LT(segment_radon_difference(image), 1e-13) << size << " x " << size;
  }
}

TEST(RaplaceRadon, RunSumsEqualThePixelByPixelDefinitionOnMulran) {
  SKIP_WITHOUT_FRAMES("000000");
  const PolarImage scan = read_native("000000");
  const cv::Mat cartesian = raplace::polar_to_cartesian(scan, 280, 3360 * scan.range_resolution_m);
  // Measured 2.0e-14: the cos and sin of the base angle stand for those of the turned angles,
  // and positions advance by a step per pixel, which moves them by a rounding of x cos + y sin.
  EXPECT_LT(segment_radon_difference(cartesian), 5e-14);
}

TEST(RaplaceRadon, RejectsOtherImageTypes) {
  EXPECT_THROW(raplace::radon_transform(cv::Mat()), std::invalid_argument);
  EXPECT_THROW(raplace::radon_transform(cv::Mat(4, 4, CV_8UC1, cv::Scalar(1))),
               std::invalid_argument);
  EXPECT_THROW(raplace::radon_transform(cv::Mat(4, 4, CV_32FC2, cv::Scalar(1, 1))),
               std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// Steps 3 and 4: normalise, shrink, |DFT along rho|, z-score.

TEST(RaplaceSinogramSpectrum, NormalizesByTheMaximumAndLeavesZerosAlone) {
  const cv::Mat sinogram = (cv::Mat_<double>(2, 2) << 1, 2, 4, 0);
  const cv::Mat normalized = raplace::normalize_by_max(sinogram);
  EXPECT_DOUBLE_EQ(normalized.at<double>(0, 0), 0.25);
  EXPECT_DOUBLE_EQ(normalized.at<double>(0, 1), 0.5);
  EXPECT_DOUBLE_EQ(normalized.at<double>(1, 0), 1.0);
  const cv::Mat zeros(3, 3, CV_64FC1, cv::Scalar(0));
  const cv::Mat still_zero = raplace::normalize_by_max(zeros);
  EXPECT_EQ(cv::countNonZero(still_zero), 0);
  EXPECT_TRUE(cv::checkRange(still_zero));  // no NaN
}

TEST(RaplaceSinogramSpectrum, ShrinksByAreaMeans) {
  // 4 x 4 -> 2 x 2: the means of the 2 x 2 blocks.
  const cv::Mat sinogram = (cv::Mat_<double>(4, 4) << 1, 3, 0, 0,  //
                            5, 7, 0, 4,                            //
                            2, 2, 8, 8,                            //
                            2, 2, 8, 0);
  const cv::Mat shrunk = raplace::shrink_sinogram(sinogram, 2, 2);
  EXPECT_NEAR(shrunk.at<double>(0, 0), 4.0, 1e-12);  // (1 + 3 + 5 + 7) / 4
  EXPECT_NEAR(shrunk.at<double>(0, 1), 1.0, 1e-12);
  EXPECT_NEAR(shrunk.at<double>(1, 0), 2.0, 1e-12);
  EXPECT_NEAR(shrunk.at<double>(1, 1), 6.0, 1e-12);
  // 180 theta columns -> 18: column c is the mean of theta 10c .. 10c + 9.
  cv::Mat ramp(1, 180, CV_64FC1);
  for (int t = 0; t < 180; ++t) ramp.at<double>(0, t) = t;
  const cv::Mat theta_means = raplace::shrink_sinogram(ramp, 1, 18);
  // OpenCV keeps the area weights in float (0.1f): relative error ~1.5e-8.
  for (int c = 0; c < 18; ++c) {
    EXPECT_NEAR(theta_means.at<double>(0, c), 10.0 * c + 4.5, 1e-7 * (10.0 * c + 4.5));
  }
  EXPECT_THROW(raplace::shrink_sinogram(sinogram, 5, 2), std::invalid_argument);
  EXPECT_THROW(raplace::shrink_sinogram(sinogram, 2, 0), std::invalid_argument);
}

TEST(RaplaceSinogramSpectrum, KeepsTheFirstHalfOfTheRhoSpectrumMagnitudes) {
  // Columns (4 rho rows each): [1 2 3 4], [1 0 0 0], [1 -1 1 -1], [4 3 2 1].
  // [1 2 3 4]: X0 = 10, X1 = 1 - 2i - 3 + 4i = -2 + 2i, |X1| = 2 sqrt 2 = 2.828427.
  // [1 0 0 0]: flat spectrum 1, 1.  [1 -1 1 -1]: all energy at X2 (dropped): 0, 0.
  // [4 3 2 1] = [1 2 3 4] reversed: the same magnitudes (why theta wraps without rho sign).
  const cv::Mat sinogram = (cv::Mat_<double>(4, 4) << 1, 1, 1, 4,  //
                            2, 0, -1, 3,                           //
                            3, 0, 1, 2,                            //
                            4, 0, -1, 1);
  const cv::Mat magnitude = raplace::rho_spectrum_magnitude(sinogram);
  ASSERT_EQ(magnitude.rows, 2);  // floor(4 / 2)
  ASSERT_EQ(magnitude.cols, 4);
  const double expected[2][4] = {{10, 1, 0, 10}, {2.828427, 1, 0, 2.828427}};
  for (int k = 0; k < 2; ++k) {
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(magnitude.at<double>(k, c), expected[k][c], 1e-6);
  }
  // Odd rho lengths round down: 5 rows -> 2.
  EXPECT_EQ(raplace::rho_spectrum_magnitude(cv::Mat(5, 3, CV_64FC1, cv::Scalar(1))).rows, 2);
  EXPECT_THROW(raplace::rho_spectrum_magnitude(cv::Mat(1, 3, CV_64FC1, cv::Scalar(1))),
               std::invalid_argument);
}

TEST(RaplaceSinogramSpectrum, ZScoresWithTheSampleStandardDeviation) {
  // [1 2; 3 6]: mean 3, squared deviations 4 + 1 + 0 + 9 = 14, std sqrt(14 / 3) = 2.160247.
  const cv::Mat matrix = (cv::Mat_<double>(2, 2) << 1, 2, 3, 6);
  const std::vector<float> scores = raplace::z_score(matrix);
  ASSERT_EQ(scores.size(), 4u);
  EXPECT_NEAR(scores[0], -0.9258201, 1e-6);
  EXPECT_NEAR(scores[1], -0.4629100, 1e-6);
  EXPECT_NEAR(scores[2], 0.0, 1e-6);
  EXPECT_NEAR(scores[3], 1.3887301, 1e-6);
  // Constant or all-zero matrices, and a single element, give zeros rather than NaN.
  for (const cv::Mat& flat :
       {cv::Mat(3, 2, CV_64FC1, cv::Scalar(0.3)), cv::Mat(3, 2, CV_64FC1, cv::Scalar(0.0)),
        cv::Mat(1, 1, CV_64FC1, cv::Scalar(5.0))}) {
    for (const float score : raplace::z_score(flat)) EXPECT_EQ(score, 0.0f);
  }
}

// ---------------------------------------------------------------------------------------------
// Step 5: circular-shift similarity.

// Brute force: max over s of sum over all elements of q shifted by s along the axis times d.
raplace::CorrelationPeak brute_force_peak(const std::vector<float>& q, const std::vector<float>& d,
                                          int rows, int cols, ShiftAxis axis) {
  const int length = axis == ShiftAxis::theta ? cols : rows;
  raplace::CorrelationPeak peak{-1e300, 0};
  for (int s = 0; s < length; ++s) {
    double sum = 0.0;
    for (int i = 0; i < rows; ++i) {
      for (int j = 0; j < cols; ++j) {
        const int qi = axis == ShiftAxis::rho ? ((i - s) % rows + rows) % rows : i;
        const int qj = axis == ShiftAxis::theta ? ((j - s) % cols + cols) % cols : j;
        sum += static_cast<double>(q[static_cast<std::size_t>(qi * cols + qj)]) *
               d[static_cast<std::size_t>(i * cols + j)];
      }
    }
    if (sum > peak.value) peak = {sum, s};
  }
  return peak;
}

TEST(RaplaceCorrelation, TinyShiftByHand) {
  // q = [1 2 3], d = [3 1 2] (q moved one step right). Shifted q . d:
  // s = 0: 1*3 + 2*1 + 3*2 = 11; s = 1: [3 1 2] . d = 9 + 1 + 4 = 14; s = 2: [2 3 1] . d = 11.
  const raplace::CircularCorrelation correlation(1, 3, ShiftAxis::theta);
  const std::vector<float> q = {1, 2, 3};
  const std::vector<float> d = {3, 1, 2};
  const raplace::CorrelationPeak peak =
      correlation.max_correlation(correlation.spectra(q), correlation.spectra(d));
  EXPECT_NEAR(peak.value, 14.0, 1e-12);
  EXPECT_EQ(peak.shift, 1);
  // Along rho, a 3 x 1 column behaves the same.
  const raplace::CircularCorrelation by_rows(3, 1, ShiftAxis::rho);
  const raplace::CorrelationPeak rows_peak =
      by_rows.max_correlation(by_rows.spectra(q), by_rows.spectra(d));
  EXPECT_NEAR(rows_peak.value, 14.0, 1e-12);
  EXPECT_EQ(rows_peak.shift, 1);
}

TEST(RaplaceCorrelation, EqualsBruteForceOnRandomMatrices) {
  std::mt19937 generator(2023);
  // Even and odd shift lengths (Nyquist term or not), 1 and 2 included.
  const std::vector<std::pair<int, int>> shapes = {{20, 18}, {8, 7}, {3, 5},
                                                   {4, 1},   {1, 2}, {6, 4}};
  for (const auto& [rows, cols] : shapes) {
    for (const ShiftAxis axis : {ShiftAxis::theta, ShiftAxis::rho}) {
      const raplace::CircularCorrelation correlation(rows, cols, axis);
      for (int trial = 0; trial < 5; ++trial) {
        const auto count = static_cast<std::size_t>(rows * cols);
        const std::vector<float> q = random_values(generator, count);
        const std::vector<float> d = random_values(generator, count);
        const raplace::CorrelationPeak expected = brute_force_peak(q, d, rows, cols, axis);
        const raplace::CorrelationPeak actual =
            correlation.max_correlation(correlation.spectra(q), correlation.spectra(d));
        EXPECT_NEAR(actual.value, expected.value, 1e-9 * (1.0 + std::abs(expected.value)))
            << rows << " x " << cols << (axis == ShiftAxis::theta ? " theta" : " rho");
        EXPECT_EQ(actual.shift, expected.shift);
      }
    }
  }
}

TEST(RaplaceCorrelation, RejectsMisshapenOrNonFiniteValues) {
  const raplace::CircularCorrelation correlation(2, 3, ShiftAxis::theta);
  EXPECT_THROW(correlation.spectra(std::vector<float>(5, 1.0f)), std::invalid_argument);
  std::vector<float> values(6, 1.0f);
  values[4] = std::nanf("");
  EXPECT_THROW(correlation.spectra(values), std::invalid_argument);
  EXPECT_THROW(raplace::CircularCorrelation(0, 3, ShiftAxis::theta), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// Step 6 and the descriptor.

TEST(RaplaceDistance, FormulaAndItsGuard) {
  // normalized: (10 - 7) / 10; raw: (10 - 7) / 1000.
  EXPECT_DOUBLE_EQ(raplace_distance_from(RaplaceDistance::normalized, 10.0, 7.0, false), 0.3);
  EXPECT_DOUBLE_EQ(raplace_distance_from(RaplaceDistance::raw_over_1000, 10.0, 7.0, false), 0.003);
  // An all-zero query (C(Dq,Dq) = 0): 0 against another all-zero value, 1 against the rest.
  EXPECT_EQ(raplace_distance_from(RaplaceDistance::normalized, 0.0, 0.0, true), 0.0);
  EXPECT_EQ(raplace_distance_from(RaplaceDistance::normalized, 0.0, 0.0, false), 1.0);
  EXPECT_EQ(raplace_distance_from(RaplaceDistance::raw_over_1000, 0.0, 0.0, false), 0.0);
}

TEST(RaplaceDescriptor, RegistryShapesAndDefaults) {
  const DescriptorRegistry& registry = DescriptorRegistry::global();
  const DescriptorInstance paper = registry.create("raplace", nlohmann::json::object());
  EXPECT_EQ(paper.id, "raplace");
  EXPECT_EQ(paper.parameters.integer("cart_size"), 280);
  EXPECT_EQ(paper.parameters.number("cart_range_m"), 0.0);
  EXPECT_EQ(paper.parameters.number("resize"), 0.1);
  EXPECT_EQ(paper.parameters.integer("sinogram_rows"), 0);
  EXPECT_EQ(paper.parameters.integer("sinogram_cols"), 0);
  // auto: as the preset (parity=radarpr) says.
  EXPECT_EQ(paper.parameters.choice("parity"), "radarpr");
  EXPECT_EQ(paper.parameters.choice("shift_axis"), "auto");
  EXPECT_EQ(paper.parameters.choice("distance"), "auto");
  const auto& resolved = dynamic_cast<const RaplaceDescriptor&>(*paper.descriptor).params();
  EXPECT_EQ(resolved.shift_axis, raplace::ShiftAxis::theta);
  EXPECT_EQ(resolved.distance, RaplaceDistance::normalized);
  EXPECT_EQ(resolved.radon, RaplaceRadon::point_per_pixel);
  EXPECT_EQ(resolved.shrink, RaplaceShrink::area);
  EXPECT_FALSE(resolved.cart_uint8);
  EXPECT_TRUE(paper.descriptor->rotation_invariant());
  EXPECT_EQ(paper.descriptor->retrieval_method(), RetrievalMethod::exhaustive);
  // 396 x 180 -> round(39.6) x 18 = 40 x 18 -> half the rows: 20 x 18, 3,008 paper bytes.
  const DescriptorShape paper_shape = paper.descriptor->shape(ScanGeometry{});
  EXPECT_EQ(paper_shape, (DescriptorShape{20, 18}));
  EXPECT_EQ(paper_shape.paper_bytes(), 3008u);

  const DescriptorInstance ds = registry.create_from_id("raplace:sinogram_cols=7,sinogram_rows=16");
  EXPECT_EQ(ds.id, "raplace:sinogram_cols=7,sinogram_rows=16");
  const DescriptorShape ds_shape = ds.descriptor->shape(ScanGeometry{400, 3768, 0.0438});
  EXPECT_EQ(ds_shape, (DescriptorShape{8, 7}));
  EXPECT_EQ(ds_shape.paper_bytes(), 576u);

  EXPECT_FALSE(registry.create_from_id("raplace:shift_axis=rho").descriptor->rotation_invariant());
}

TEST(RaplaceDescriptor, ShapeDependsOnlyOnTheParameters) {
  // Two very different geometries, the same shape as shape() announces.
  for (const char* id : {"raplace", "raplace:sinogram_cols=7,sinogram_rows=16"}) {
    const DescriptorInstance instance = DescriptorRegistry::global().create_from_id(id);
    for (const PolarImage& scan : {synthetic_scene(), blank_scan(37, 90, 0.2)}) {
      PolarImage lit = scan;
      std::fill_n(lit.power.row(3), lit.power.cols(), std::uint8_t{90});
      const DescriptorValue value = instance.descriptor->extract(lit);
      const DescriptorShape shape = instance.descriptor->shape(geometry_of(lit));
      EXPECT_EQ(value.rows, shape.rows) << id;
      EXPECT_EQ(value.cols, shape.cols) << id;
      EXPECT_EQ(value.values.size(), shape.element_count()) << id;
    }
  }
}

TEST(RaplaceDescriptor, RejectsSizesThatLeaveNoDescriptor) {
  const DescriptorRegistry& registry = DescriptorRegistry::global();
  // resize 0.004: round(396 * 0.004) = 2 rho rows but round(180 * 0.004) = 1 column: fine.
  EXPECT_EQ(registry.create_from_id("raplace:resize=0.004").descriptor->shape({}),
            (DescriptorShape{1, 1}));
  // resize 0.001: 0 rho rows.
  EXPECT_THROW(registry.create_from_id("raplace:resize=0.001"), std::invalid_argument);
  EXPECT_THROW(registry.create_from_id("raplace:sinogram_rows=1"), std::invalid_argument);
  EXPECT_THROW(registry.create_from_id("raplace:sinogram_rows=397"), std::invalid_argument);
  EXPECT_THROW(registry.create_from_id("raplace:sinogram_cols=181"), std::invalid_argument);
  EXPECT_THROW(registry.create_from_id("raplace:shift_axis=phi"), std::invalid_argument);
  RaplaceParams params;
  params.cart_range_m = -1.0;
  EXPECT_THROW(RaplaceDescriptor{params}, std::invalid_argument);
}

TEST(RaplaceDescriptor, DistanceToItselfIsZeroAndShapesAreChecked) {
  for (const char* id : {"raplace", "raplace:distance=raw_over_1000", "raplace:shift_axis=rho"}) {
    const DescriptorInstance instance = DescriptorRegistry::global().create_from_id(id);
    const DescriptorValue value = instance.descriptor->extract(synthetic_scene());
    const DescriptorValue copy = value;
    EXPECT_EQ(instance.descriptor->distance(value, copy), 0.0) << id;
    const DescriptorValue other =
        instance.descriptor->extract(turned_by_rows(synthetic_scene(), 45));
    EXPECT_GT(instance.descriptor->distance(value, other), 0.0) << id;
    const DescriptorValue wrong{18, 20, value.values};
    EXPECT_THROW(instance.descriptor->distance(value, wrong), std::invalid_argument) << id;
  }
}

TEST(RaplaceDescriptor, ValuesAreZScored) {
  const RaplaceDescriptor raplace{RaplaceParams{}};
  const DescriptorValue value = raplace.extract(synthetic_scene());
  double sum = 0.0;
  double squares = 0.0;
  for (const float v : value.values) {
    sum += v;
    squares += static_cast<double>(v) * v;
  }
  const double n = static_cast<double>(value.values.size());
  EXPECT_NEAR(sum / n, 0.0, 1e-5);
  EXPECT_NEAR(squares / (n - 1.0), 1.0, 1e-5);  // sample variance 1
  // C(D, D) = sum of squares = n - 1 = 359 at the best (zero) shift.
  const raplace::CorrelationPeak self = raplace.similarity(value, value);
  EXPECT_NEAR(self.value, 359.0, 1e-3);
  EXPECT_EQ(self.shift, 0);
}

TEST(RaplaceDescriptor, AnEmptyScanGivesZerosAndFiniteDistances) {
  const RaplaceDescriptor raplace{RaplaceParams{}};
  const DescriptorValue empty = raplace.extract(blank_scan(400, 300, 0.5));
  ASSERT_EQ(empty.values.size(), 360u);
  for (const float v : empty.values) ASSERT_EQ(v, 0.0f);
  const DescriptorValue scene = raplace.extract(synthetic_scene());
  EXPECT_EQ(raplace.distance(empty, empty), 0.0);
  EXPECT_EQ(raplace.distance(empty, scene), 1.0);  // the guard: C(Dq,Dq) = 0
  EXPECT_EQ(raplace.distance(scene, empty), 1.0);  // (C - 0) / C
}

TEST(RaplaceDescriptor, PreparedDistancesEqualDistanceBitForBit) {
  std::mt19937 generator(11);
  for (const char* id : {"raplace", "raplace:distance=raw_over_1000", "raplace:shift_axis=rho",
                         "raplace:sinogram_cols=7,sinogram_rows=16"}) {
    const DescriptorInstance instance = DescriptorRegistry::global().create_from_id(id);
    const Descriptor& descriptor = *instance.descriptor;
    const DescriptorShape shape = descriptor.shape({});
    const auto random_value = [&] {
      return DescriptorValue{shape.rows, shape.cols,
                             random_values(generator, shape.element_count())};
    };
    std::vector<DescriptorValue> queries = {random_value(), random_value(), random_value()};
    queries.push_back({shape.rows, shape.cols, std::vector<float>(shape.element_count(), 0.0f)});
    std::vector<DescriptorValue> database = {random_value(), queries[1], random_value()};
    database.push_back(queries[3]);  // all zero

    // Two vectors.
    const auto prepared = descriptor.prepare_distances(queries, database);
    for (std::size_t q = 0; q < queries.size(); ++q) {
      for (std::size_t i = 0; i < database.size(); ++i) {
        EXPECT_EQ(prepared->distance(q, i), descriptor.distance(queries[q], database[i]))
            << id << " query " << q << " database " << i;
      }
    }
    EXPECT_EQ(prepared->distance(1, 1), 0.0) << id;  // the same values
    // One vector (single session): the spectra are shared.
    const auto single = descriptor.prepare_distances(queries, queries);
    for (std::size_t q = 0; q < queries.size(); ++q) {
      for (std::size_t i = 0; i < queries.size(); ++i) {
        EXPECT_EQ(single->distance(q, i), descriptor.distance(queries[q], queries[i]))
            << id << " query " << q << " value " << i;
      }
    }
    EXPECT_THROW(prepared->distance(0, database.size()), std::out_of_range);
    std::vector<DescriptorValue> misshapen = {DescriptorValue{1, 1, {0.0f}}};
    EXPECT_THROW(descriptor.prepare_distances(misshapen, database), std::invalid_argument);
  }
}

// Rotating the 360-azimuth scene by whole 10-degree theta columns; the yaw is only defined
// modulo pi, so a turn by 200 degrees reads as 20.
TEST(RaplaceDescriptor, YawIsEstimatedModuloPi) {
  const RaplaceDescriptor raplace{RaplaceParams{}};
  const PolarImage scene = synthetic_scene();
  const DescriptorValue database = raplace.extract(scene);
  const auto yaw_of_turn = [&](int rows) {
    return raplace.yaw_modulo_pi(raplace.extract(turned_by_rows(scene, rows)), database);
  };
  const double degree = kPi / 180.0;
  ASSERT_TRUE(yaw_of_turn(20).has_value());
  EXPECT_NEAR(*yaw_of_turn(20), 20 * degree, 1e-9);
  EXPECT_NEAR(*yaw_of_turn(200), 20 * degree, 1e-9);   // 200 = 20 + 180
  EXPECT_NEAR(*yaw_of_turn(-20), -20 * degree, 1e-9);  // 340 -> 160 -> wrapped to -20
  EXPECT_NEAR(*yaw_of_turn(90), 90 * degree, 1e-9);    // (-pi/2, pi/2]: +90 stays
  EXPECT_NEAR(*yaw_of_turn(0), 0.0, 1e-9);
  // The interface promises (-pi, pi]: not offered.
  EXPECT_FALSE(raplace.estimate_yaw(database, database).has_value());
  RaplaceParams rho;
  rho.shift_axis = ShiftAxis::rho;
  const RaplaceDescriptor by_rho{rho};
  EXPECT_FALSE(by_rho.yaw_modulo_pi(database, database).has_value());
  const DescriptorValue zero{20, 18, std::vector<float>(360, 0.0f)};
  EXPECT_FALSE(raplace.yaw_modulo_pi(zero, database).has_value());
}

// ---------------------------------------------------------------------------------------------
// Real MulRan KAIST03 scans (400 azimuths x 3360 bins, 0.0595 m: Cartesian +-200 m).

// Which azimuth shifts are exact. Turning the scan by k rows turns the sensor by k * 0.9 deg;
// the sinogram then moves by the same angle along theta. The descriptor of the turned scan is
// a whole-column shift of the original (distance 0 up to rounding) only when
//  (a) the angle is a multiple of 90 deg, the only turns that map the square Cartesian pixel
//      grid onto itself (otherwise the backward warp samples other points), and
//  (b) the angle is a multiple of one shrunk theta column, 180 / cols deg (10 deg at the
//      defaults, 25.7 deg for RaPlace-DS); a half turn always is (theta wraps with rho mirrored,
//      which |DFT| ignores).
// With A = 400: k = 100, 200, 300 for 20 x 18; only k = 200 for 8 x 7 (90 deg = 3.5 columns).
// Every other turn is approximate: within 0.4 deg of a column (k = 11, 22, 33, ... 89) only the
// Cartesian resampling differs (measured <= 3.5e-5); between columns each shrunk column averages
// another 10-deg window and no whole shift matches, worst at half a column (k = 5, 50, 150;
// measured 8.1e-4, and up to 1.05e-3 for 8 x 7). The bounds below leave ~3x margin.
TEST(RaplaceOnMulran, TurnedScansAreNearlyTheSamePlace) {
  SKIP_WITHOUT_FRAMES("000000");
  const PolarImage scan = read_native("000000");
  ASSERT_EQ(scan.azimuth_count(), 400);
  const DescriptorInstance paper = DescriptorRegistry::global().create_from_id("raplace");
  const Descriptor& raplace = *paper.descriptor;
  const DescriptorValue original = raplace.extract(scan);
  const auto distance_after_turn = [&](const Descriptor& descriptor, const DescriptorValue& base,
                                       int rows) {
    return descriptor.distance(descriptor.extract(turned_by_rows(scan, rows)), base);
  };
  for (const int rows : {100, 200, 300}) {
    EXPECT_LT(distance_after_turn(raplace, original, rows), 1e-7) << rows << " rows (exact)";
  }
  for (const int rows : {11, 22, 56, 89}) {
    EXPECT_LT(distance_after_turn(raplace, original, rows), 1e-4) << rows << " rows (on a column)";
  }
  for (const int rows : {5, 50, 150, 233}) {
    EXPECT_LT(distance_after_turn(raplace, original, rows), 2.5e-3) << rows << " rows (between)";
  }

  const DescriptorInstance ds =
      DescriptorRegistry::global().create_from_id("raplace:sinogram_cols=7,sinogram_rows=16");
  const DescriptorValue ds_original = ds.descriptor->extract(scan);
  EXPECT_LT(distance_after_turn(*ds.descriptor, ds_original, 200), 1e-7) << "8 x 7, half turn";
  for (const int rows : {44, 100, 300}) {
    EXPECT_LT(distance_after_turn(*ds.descriptor, ds_original, rows), 3e-3) << "8 x 7, " << rows;
  }
}

TEST(RaplaceOnMulran, ShiftingAlongThetaIsWhatMakesItRotationInvariant) {
  SKIP_WITHOUT_FRAMES("000000");
  const PolarImage scan = read_native("000000");
  const PolarImage turned = turned_by_rows(scan, 22);  // 19.8 deg, nearly two columns
  const auto& registry = DescriptorRegistry::global();
  const DescriptorInstance theta = registry.create_from_id("raplace");
  const DescriptorInstance rho = registry.create_from_id("raplace:shift_axis=rho");
  const double by_theta = theta.descriptor->distance(theta.descriptor->extract(turned),
                                                     theta.descriptor->extract(scan));
  const double by_rho =
      rho.descriptor->distance(rho.descriptor->extract(turned), rho.descriptor->extract(scan));
  // Measured 2.6e-5 and 4.0e-3: the rho shift cannot undo a turn.
  EXPECT_LT(by_theta * 20.0, by_rho);
}

TEST(RaplaceOnMulran, YawOfAQuarterTurnModuloPi) {
  SKIP_WITHOUT_FRAMES("000000");
  const PolarImage scan = read_native("000000");
  const RaplaceDescriptor raplace{RaplaceParams{}};
  const DescriptorValue original = raplace.extract(scan);
  // +90 deg and -90 deg (= 270) are the same modulo pi: both read pi / 2.
  for (const int rows : {100, 300}) {
    const auto yaw = raplace.yaw_modulo_pi(raplace.extract(turned_by_rows(scan, rows)), original);
    ASSERT_TRUE(yaw.has_value());
    EXPECT_NEAR(*yaw, kPi / 2.0, 1e-9) << rows;
  }
}

TEST(RaplaceOnMulran, TheNextFrameIsCloserThanTheTenth) {
  SKIP_WITHOUT_FRAMES("000000", "000001", "000010");
  for (const char* id : {"raplace", "raplace:sinogram_cols=7,sinogram_rows=16"}) {
    const DescriptorInstance instance = DescriptorRegistry::global().create_from_id(id);
    const Descriptor& raplace = *instance.descriptor;
    const DescriptorValue first = raplace.extract(read_native("000000"));
    const DescriptorValue next = raplace.extract(read_native("000001"));
    const DescriptorValue tenth = raplace.extract(read_native("000010"));
    // 0.25 s vs 2.25 s apart while driving (measured 3.2e-5 vs 5.7e-5 for 20 x 18).
    EXPECT_LT(raplace.distance(first, next), raplace.distance(first, tenth)) << id;
    // And through the prepared path, single session.
    const std::vector<DescriptorValue> session = {first, next, tenth};
    const auto prepared = raplace.prepare_distances(session, session);
    EXPECT_LT(prepared->distance(0, 1), prepared->distance(0, 2)) << id;
    EXPECT_EQ(prepared->distance(0, 1), raplace.distance(first, next)) << id;
  }
}

}  // namespace
}  // namespace radarpr
