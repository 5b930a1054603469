#include "descriptors/features/polar_features.hpp"

#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

namespace radarpr {
namespace {

TEST(PolarFeatures, RoundTripsThroughADenseMask) {
  cv::Mat mask = cv::Mat::zeros(3, 8, CV_8UC1);
  mask.at<unsigned char>(0, 2) = 1;
  mask.at<unsigned char>(0, 7) = 255;  // any non-zero value is a feature
  mask.at<unsigned char>(2, 0) = 1;
  const PolarFeatures features = PolarFeatures::from_mask(mask);
  EXPECT_EQ(features.azimuth_count(), 3);
  EXPECT_EQ(features.range_bin_count(), 8);
  EXPECT_EQ(features.feature_count(), 3u);
  EXPECT_EQ(std::vector<int>(features.azimuth(0).begin(), features.azimuth(0).end()),
            (std::vector<int>{2, 7}));
  EXPECT_TRUE(features.azimuth(1).empty());
  // Per range bin: bin 0 <- row 2, bin 2 <- row 0, bin 7 <- row 0.
  EXPECT_EQ(features.features_per_range_bin(), (std::vector<int>{1, 0, 1, 0, 0, 0, 0, 1}));

  const cv::Mat dense = features.to_mask();
  EXPECT_EQ(dense.at<unsigned char>(0, 7), 1);
  EXPECT_EQ(cv::countNonZero(dense), 3);
  EXPECT_EQ(PolarFeatures::from_mask(dense), features);
}

TEST(PolarFeatures, RejectsBadMasksAndBins) {
  EXPECT_THROW(PolarFeatures::from_mask(cv::Mat()), std::invalid_argument);
  EXPECT_THROW(PolarFeatures::from_mask(cv::Mat(2, 2, CV_32FC1, cv::Scalar(0))),
               std::invalid_argument);
  PolarFeatures features(0, 5);
  EXPECT_THROW(features.add_azimuth(std::vector<int>{3, 3}), std::invalid_argument);
  EXPECT_THROW(features.add_azimuth(std::vector<int>{5}), std::invalid_argument);
  EXPECT_THROW(features.add_azimuth(std::vector<int>{-1}), std::invalid_argument);
}

}  // namespace
}  // namespace radarpr
