#include "descriptors/referee/referee.hpp"

#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "descriptors/referee/referee_common.hpp"
#include "tests/descriptors/feature_masks.hpp"

namespace radarpr {
namespace {

using test::features_from_rows;

TEST(SplitEvenly, FirstRemainderBlocksAreOneLonger) {
  EXPECT_EQ(split_evenly(7, 3, "t"), (std::vector<int>{3, 2, 2}));  // 7 = 3 * 2 + 1
  EXPECT_EQ(split_evenly(8, 3, "t"), (std::vector<int>{3, 3, 2}));  // 8 = 3 * 2 + 2
  EXPECT_EQ(split_evenly(10, 10, "t"), std::vector<int>(10, 1));
  EXPECT_EQ(split_evenly(400, 50, "t"), std::vector<int>(50, 8));
  // 403 = 50 * 8 + 3: three blocks of 9, then 47 of 8.
  std::vector<int> expected(50, 8);
  expected[0] = expected[1] = expected[2] = 9;
  EXPECT_EQ(split_evenly(403, 50, "t"), expected);
  EXPECT_THROW(split_evenly(5, 6, "t"), std::invalid_argument);
  EXPECT_THROW(split_evenly(5, 0, "t"), std::invalid_argument);
}

// R = 10. Phi_a = free cells before the farthest feature r*:
// row 0 {2, 5}: r* = 5, cells 0..4 hold one feature (2) -> 4 free
// row 1 {}: 0          row 2 {9}: 9 free before 9      row 3 {0}: nothing before 0 -> 0
// row 4 {1, 2, 3}: r* = 3, cells 0..2 hold two features -> 1
// row 5 {4, 7, 8}: r* = 8, cells 0..7 hold two features -> 6
// row 6 {6}: 6
const std::vector<std::vector<int>> kRows = {{2, 5}, {}, {9}, {0}, {1, 2, 3}, {4, 7, 8}, {6}};

TEST(RefereeFromFeatures, BlockSharesOfFreeCellsBeforeTheFarthestFeature) {
  const std::vector<std::vector<int>> six_rows(kRows.begin(), kRows.begin() + 6);
  const DescriptorValue value = referee_from_features(features_from_rows(10, six_rows), 3);
  EXPECT_EQ(value.rows, 3);
  EXPECT_EQ(value.cols, 1);
  // Blocks of 2 rows: (4 + 0) / (2 * 10), (9 + 0) / 20, (1 + 6) / 20.
  ASSERT_EQ(value.values.size(), 3u);
  EXPECT_FLOAT_EQ(value.values[0], 0.2f);
  EXPECT_FLOAT_EQ(value.values[1], 0.45f);
  EXPECT_FLOAT_EQ(value.values[2], 0.35f);
}

TEST(RefereeFromFeatures, UnevenSplitGivesTheFirstBlocksOneMoreAzimuth) {
  // A = 7, alpha = 3: blocks of 3, 2, 2 rows.
  // (4 + 0 + 9) / (3 * 10) = 13 / 30, (0 + 1) / 20 = 0.05, (6 + 6) / 20 = 0.6.
  const DescriptorValue value = referee_from_features(features_from_rows(10, kRows), 3);
  ASSERT_EQ(value.values.size(), 3u);
  EXPECT_FLOAT_EQ(value.values[0], 13.0f / 30.0f);
  EXPECT_FLOAT_EQ(value.values[1], 0.05f);
  EXPECT_FLOAT_EQ(value.values[2], 0.6f);
}

TEST(RefereeFromFeatures, RejectsFewerAzimuthsThanBlocks) {
  EXPECT_THROW(referee_from_features(features_from_rows(10, kRows), 8), std::invalid_argument);
}

TEST(RefereeDescriptor, ShapeMetadataAndL2Distance) {
  const RefereeDescriptor referee(RefereeParams{});
  EXPECT_FALSE(referee.rotation_invariant());
  // Scan of 400 azimuths x 200 bins: 50 x 1, all zero (constant rows have no feature).
  PolarImage scan;
  scan.power = ByteImage(400, 200, 40);
  const DescriptorValue value = referee.extract(scan);
  EXPECT_EQ(value.rows, 50);
  EXPECT_EQ(value.cols, 1);
  EXPECT_EQ(value.values, std::vector<float>(50, 0.0f));
  EXPECT_EQ(value.payload_bytes(), 200u);  // 50 float32

  const DescriptorValue a{2, 1, {0.0f, 3.0f}};
  const DescriptorValue b{2, 1, {4.0f, 0.0f}};
  EXPECT_DOUBLE_EQ(referee.distance(a, b), 5.0);  // sqrt(4^2 + 3^2)
  EXPECT_THROW(referee.distance(a, DescriptorValue{3, 1, {0.0f, 0.0f, 0.0f}}),
               std::invalid_argument);
}

TEST(RefereeDescriptor, RejectsEmptyNonUint8AndTooShortScans) {
  const RefereeDescriptor referee(RefereeParams{});
  EXPECT_THROW(referee.extract(PolarImage{}), std::invalid_argument);
  PolarImage no_bins;
  no_bins.power = ByteImage(400, 0);
  EXPECT_THROW(referee.extract(no_bins), std::invalid_argument);
  PolarImage few;
  few.power = ByteImage(49, 100, 0);  // 49 azimuths < alpha = 50
  EXPECT_THROW(referee.extract(few), std::invalid_argument);
  RefereeParams bad;
  bad.cen.sigma = -1.0;
  EXPECT_THROW(RefereeDescriptor{bad}, std::invalid_argument);
}

}  // namespace
}  // namespace radarpr
