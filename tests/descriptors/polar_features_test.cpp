#include "descriptors/features/polar_features.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

namespace radarpr {
namespace {

TEST(PolarFeatures, RoundTripsThroughADenseMask) {
  ByteImage mask(3, 8, 0);
  mask(0, 2) = 1;
  mask(0, 7) = 255;  // any non-zero value is a feature
  mask(2, 0) = 1;
  const PolarFeatures features = PolarFeatures::from_mask(mask);
  EXPECT_EQ(features.azimuth_count(), 3);
  EXPECT_EQ(features.range_bin_count(), 8);
  EXPECT_EQ(features.feature_count(), 3u);
  EXPECT_EQ(std::vector<int>(features.azimuth(0).begin(), features.azimuth(0).end()),
            (std::vector<int>{2, 7}));
  EXPECT_TRUE(features.azimuth(1).empty());
  // Per range bin: bin 0 <- row 2, bin 2 <- row 0, bin 7 <- row 0.
  EXPECT_EQ(features.features_per_range_bin(), (std::vector<int>{1, 0, 1, 0, 0, 0, 0, 1}));

  const ByteImage dense = features.to_mask();
  EXPECT_EQ(dense(0, 7), 1);
  EXPECT_EQ(std::count(dense.data(), dense.data() + dense.size(), 1), 3);
  EXPECT_EQ(std::count(dense.data(), dense.data() + dense.size(), 0), 3 * 8 - 3);
  EXPECT_EQ(PolarFeatures::from_mask(dense), features);
}

TEST(PolarFeatures, RejectsBadMasksAndBins) {
  EXPECT_THROW(PolarFeatures::from_mask(ByteImage()), std::invalid_argument);
  EXPECT_THROW(PolarFeatures::from_mask(ByteImage(2, 0)), std::invalid_argument);
  PolarFeatures features(0, 5);
  EXPECT_THROW(features.add_azimuth(std::vector<int>{3, 3}), std::invalid_argument);
  EXPECT_THROW(features.add_azimuth(std::vector<int>{5}), std::invalid_argument);
  EXPECT_THROW(features.add_azimuth(std::vector<int>{-1}), std::invalid_argument);
}

}  // namespace
}  // namespace radarpr
