#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include <opencv2/core.hpp>

#include "descriptors/resampling/matlab_imresize.hpp"
#include "descriptors/resampling/pillow_resize.hpp"

namespace radarpr {
namespace {

cv::Mat uint8_matrix(int rows, int cols, const std::vector<int>& values) {
  cv::Mat m(rows, cols, CV_8UC1);
  for (int i = 0; i < rows * cols; ++i)
    m.at<unsigned char>(i / cols, i % cols) =
        static_cast<unsigned char>(values[static_cast<std::size_t>(i)]);
  return m;
}

std::vector<int> as_ints(const cv::Mat& m) {
  std::vector<int> values;
  for (int r = 0; r < m.rows; ++r) {
    for (int c = 0; c < m.cols; ++c) values.push_back(m.at<unsigned char>(r, c));
  }
  return values;
}

// An 8 x 10 uint8 image and MATLAB's own imresize results for it, as recorded (with the input)
// among the tests of GNU Octave's image package 2.14 (imresize.m), which compares against them.
const std::vector<int> kMatlabInput = {
    116, 227, 153, 69,  146, 194, 59,  130, 139, 106, 2,   47,  137, 249, 90,  75,
    16,  24,  158, 44,  155, 68,  46,  84,  166, 156, 69,  204, 32,  152, 71,  221,
    137, 230, 210, 153, 192, 115, 30,  118, 107, 143, 108, 52,  51,  73,  101, 21,
    175, 90,  54,  158, 143, 77,  26,  168, 113, 229, 165, 225, 9,   47,  133, 135,
    130, 207, 236, 43,  19,  73,  129, 60,  59,  243, 64,  181, 249, 56,  32,  86};

TEST(MatlabImresize, HalvingTapsAreTheStretchedCubicRenormalised) {
  // 4 -> 2 at scale 0.5: output 1 sits at u = 1.5 (1-based), the kernel 0.5 cubic(0.5 x) spans
  // |x| < 4; by hand, cubic(0.25) = 0.8671875, cubic(0.75) = 0.2265625, cubic(1.25) =
  // -0.0703125, cubic(1.75) = -0.0234375, and the weights sum to 1 before renormalising.
  // Inputs -2 .. 5 (1-based) mirror onto 3 2 1 1 2 3 4 4 (1-based), i.e. 2 1 0 0 1 2 3 3.
  const ResamplingAxis axis = matlab_imresize_axis(4, 2, 0.5);
  ASSERT_EQ(axis.size(), 2u);
  const std::vector<int> indices = {2, 1, 0, 0, 1, 2, 3, 3};
  const std::vector<double> weights = {-0.01171875, -0.03515625, 0.11328125,  0.43359375,
                                       0.43359375,  0.11328125,  -0.03515625, -0.01171875};
  EXPECT_EQ(axis[0].indices, indices);
  ASSERT_EQ(axis[0].weights.size(), weights.size());
  for (std::size_t k = 0; k < weights.size(); ++k) {
    EXPECT_DOUBLE_EQ(axis[0].weights[k], weights[k]) << k;
  }
}

TEST(MatlabImresize, EnlargingTwoSamplesToThreeMatchesMatlab) {
  // imresize([10 6], [1 3]): 10.2777..., 8, 5.7222... (MATLAB's values, same source as above).
  cv::Mat row = (cv::Mat_<double>(1, 2) << 10.0, 6.0);
  const cv::Mat out = matlab_imresize(row, 1, 3);
  ASSERT_EQ(out.cols, 3);
  EXPECT_NEAR(out.at<double>(0, 0), 10.27777777777777, 1e-13);
  EXPECT_NEAR(out.at<double>(0, 1), 8.0, 1e-13);
  EXPECT_NEAR(out.at<double>(0, 2), 5.72222222222222, 1e-13);
}

TEST(MatlabImresize, Uint8HalvingWithAntiAliasingMatchesMatlabExactly) {
  const cv::Mat in = uint8_matrix(8, 10, kMatlabInput);
  const cv::Mat out = matlab_imresize_scale(in, 0.5);
  ASSERT_EQ(out.type(), CV_8UC1);
  ASSERT_EQ(out.rows, 4);
  ASSERT_EQ(out.cols, 5);
  const std::vector<int> matlab = {105, 140, 126, 81,  109, 110, 134, 153, 114, 93,
                                   108, 108, 94,  127, 146, 67,  126, 162, 149, 62};
  EXPECT_EQ(as_ints(out), matlab);
}

TEST(MatlabImresize, Uint8ThirdWithRoundedUpSizeMatchesMatlabExactly) {
  // 8 x 10 at 1/3 -> ceil(2.67) x ceil(3.33) = 3 x 4; the last outputs reach past the border,
  // where symmetric padding matters.
  const cv::Mat out = matlab_imresize_scale(uint8_matrix(8, 10, kMatlabInput), 1.0 / 3.0);
  ASSERT_EQ(out.rows, 3);
  ASSERT_EQ(out.cols, 4);
  const std::vector<int> matlab = {115, 135, 97, 101, 113, 119, 124, 125, 81, 157, 118, 64};
  EXPECT_EQ(as_ints(out), matlab);
}

// Enlarging, MATLAB's recorded output differs from this implementation by one grey level in 2 of
// 180 cells, (1, 6) and (12, 6), where the two passes' rounding falls differently (the exact
// double-precision values there are 61.49 and 237.49; the shrinking cases above match exactly).
TEST(MatlabImresize, Uint8EnlargingMatchesMatlabWithinOneGreyLevel) {
  const cv::Mat out = matlab_imresize_scale(uint8_matrix(8, 10, kMatlabInput), 1.5);
  ASSERT_EQ(out.rows, 12);
  ASSERT_EQ(out.cols, 15);
  const std::vector<int> matlab = {
      116, 187, 237, 171, 94,  61,  135, 191, 187, 75,  91,  142, 140, 124, 108, 43,  92,  143,
      149, 164, 163, 119, 123, 118, 44,  38,  80,  151, 118, 62,  13,  21,  47,  107, 195, 228,
      115, 81,  70,  24,  19,  56,  137, 105, 48,  146, 98,  49,  49,  71,  107, 148, 159, 132,
      58,  124, 176, 61,  85,  146, 118, 139, 144, 92,  116, 168, 201, 188, 159, 140, 167, 158,
      27,  69,  153, 61,  151, 218, 145, 174, 219, 201, 164, 146, 187, 148, 84,  48,  76,  115,
      102, 132, 151, 119, 90,  72,  72,  72,  83,  114, 60,  31,  144, 130, 80,  81,  121, 154,
      133, 87,  41,  19,  67,  116, 95,  108, 140, 183, 180, 163, 37,  95,  152, 150, 117, 73,
      35,  108, 179, 130, 174, 214, 153, 176, 219, 3,   29,  73,  131, 136, 120, 116, 162, 214,
      229, 147, 54,  35,  62,  96,  67,  54,  51,  83,  153, 187, 111, 141, 210, 255, 149, 22,
      13,  42,  74,  142, 99,  53,  43,  164, 237, 77,  103, 197, 254, 159, 42,  31,  59,  91};
  const std::vector<int> values = as_ints(out);
  ASSERT_EQ(values.size(), matlab.size());
  std::vector<std::size_t> differing;
  for (std::size_t i = 0; i < values.size(); ++i) {
    EXPECT_LE(std::abs(values[i] - matlab[i]), 1) << i;
    if (values[i] != matlab[i]) differing.push_back(i);
  }
  EXPECT_EQ(differing, (std::vector<std::size_t>{5, 170}));
}

TEST(MatlabImresize, ConstantStaysConstantAtEveryBorder) {
  const cv::Mat constant(37, 23, CV_64FC1, cv::Scalar(3.25));
  for (const auto& [rows, cols] : std::vector<std::pair<int, int>>{{5, 7}, {40, 3}, {100, 60}}) {
    const cv::Mat out = matlab_imresize(constant, rows, cols);
    double low = 0.0;
    double high = 0.0;
    cv::minMaxLoc(out, &low, &high);
    EXPECT_NEAR(low, 3.25, 1e-12);
    EXPECT_NEAR(high, 3.25, 1e-12);
  }
}

TEST(MatlabImresize, SameSizeIsTheIdentity) {
  cv::Mat in(6, 9, CV_64FC1);
  cv::randu(in, -5.0, 5.0);
  const cv::Mat out = matlab_imresize(in, 6, 9);
  EXPECT_LE(cv::norm(out, in, cv::NORM_INF), 1e-12);
}

TEST(MatlabImresize, RefusesBadInput) {
  EXPECT_THROW(matlab_imresize(cv::Mat(), 2, 2), std::invalid_argument);
  EXPECT_THROW(matlab_imresize(cv::Mat(3, 3, CV_16UC1, cv::Scalar(1)), 2, 2),
               std::invalid_argument);
  EXPECT_THROW(matlab_imresize(cv::Mat(3, 3, CV_64FC1, cv::Scalar(1)), 0, 2),
               std::invalid_argument);
  EXPECT_THROW(matlab_imresize_scale(cv::Mat(3, 3, CV_64FC1, cv::Scalar(1)), -1.0),
               std::invalid_argument);
  EXPECT_THROW(matlab_imresize_axis(3, 2, 0.0), std::invalid_argument);
}

TEST(PillowResize, HalvingTapsByHand) {
  // 4 -> 2: scale 2, support 4; output 0 is centred at 1, reads inputs trunc(1 - 4 + 0.5) -> 0
  // .. trunc(5.5) -> clipped to 4, with weights bicubic((i + 0.5 - 1) / 2) = bicubic(-0.25),
  // bicubic(0.25), bicubic(0.75), bicubic(1.25) = 0.8671875, 0.8671875, 0.2265625, -0.0703125,
  // sum 1.890625 (the missing left taps are not padded, only renormalised away).
  const ResamplingAxis axis = pillow_bicubic_axis(4, 2);
  ASSERT_EQ(axis.size(), 2u);
  EXPECT_EQ(axis[0].indices, (std::vector<int>{0, 1, 2, 3}));
  const double sum = 1.890625;
  const std::vector<double> weights = {0.8671875 / sum, 0.8671875 / sum, 0.2265625 / sum,
                                       -0.0703125 / sum};
  for (std::size_t k = 0; k < weights.size(); ++k) {
    EXPECT_DOUBLE_EQ(axis[0].weights[k], weights[k]) << k;
  }
  // Output 1 mirrors output 0.
  EXPECT_EQ(axis[1].indices, (std::vector<int>{0, 1, 2, 3}));
  for (std::size_t k = 0; k < weights.size(); ++k) {
    EXPECT_DOUBLE_EQ(axis[1].weights[k], weights[weights.size() - 1 - k]) << k;
  }
}

TEST(PillowResize, EnlargingUsesTheUnstretchedKernel) {
  // 2 -> 4: scale 0.5, support 2; output 1 is centred at 0.75: inputs 0 and 1 at distances
  // 0.25 and 0.75 -> bicubic 0.8671875 and 0.2265625, renormalised.
  cv::Mat row = (cv::Mat_<float>(1, 2) << 10.0F, 6.0F);
  const cv::Mat out = pillow_resize(row, 1, 4);
  ASSERT_EQ(out.cols, 4);
  const double expected = (10.0 * 0.8671875 + 6.0 * 0.2265625) / (0.8671875 + 0.2265625);
  EXPECT_FLOAT_EQ(out.at<float>(0, 1), static_cast<float>(expected));
  EXPECT_FLOAT_EQ(out.at<float>(0, 2), static_cast<float>(16.0 - expected));
}

TEST(PillowResize, ConstantStaysConstantAndUnchangedAxesAreLeftAlone) {
  const cv::Mat constant(11, 29, CV_32FC1, cv::Scalar(0.75));
  const cv::Mat out = pillow_resize(constant, 11, 8);
  ASSERT_EQ(out.rows, 11);
  double low = 0.0;
  double high = 0.0;
  cv::minMaxLoc(out, &low, &high);
  EXPECT_NEAR(low, 0.75, 1e-7);
  EXPECT_NEAR(high, 0.75, 1e-7);
  cv::Mat random(5, 7, CV_32FC1);
  cv::randu(random, 0.0F, 1.0F);
  EXPECT_EQ(cv::norm(pillow_resize(random, 5, 7), random, cv::NORM_INF), 0.0);
}

TEST(PillowResize, RefusesBadInput) {
  EXPECT_THROW(pillow_resize(cv::Mat(), 2, 2), std::invalid_argument);
  EXPECT_THROW(pillow_resize(cv::Mat(3, 3, CV_8UC1, cv::Scalar(1)), 2, 2), std::invalid_argument);
  EXPECT_THROW(pillow_resize(cv::Mat(3, 3, CV_32FC1, cv::Scalar(1)), 2, 0), std::invalid_argument);
  EXPECT_THROW(pillow_bicubic_axis(0, 2), std::invalid_argument);
}

}  // namespace
}  // namespace radarpr
