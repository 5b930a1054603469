#include "descriptors/referee/referee_a.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "tests/descriptors/feature_masks.hpp"

namespace radarpr {
namespace {

using test::features_from_rows;

TEST(RefereeAFromFeatures, CountsEveryCellBeforeTheFarthestFeature) {
  // R = 10, A = 7, alpha = 3 (blocks of 3, 2, 2). Phi_a = r*_a (cells 0..r*-1, features
  // included): {2, 5} -> 5, {} -> 0, {9} -> 9 | {0} -> 0, {1, 2, 3} -> 3 | {4, 7, 8} -> 8, {6}
  // -> 6. (5 + 0 + 9) / (3 * 10) = 14 / 30, (0 + 3) / 20 = 0.15, (8 + 6) / 20 = 0.7.
  const DescriptorValue value = referee_a_from_features(
      features_from_rows(10, {{2, 5}, {}, {9}, {0}, {1, 2, 3}, {4, 7, 8}, {6}}), 3);
  EXPECT_EQ(value.rows, 3);
  EXPECT_EQ(value.cols, 1);
  ASSERT_EQ(value.values.size(), 3u);
  EXPECT_FLOAT_EQ(value.values[0], 14.0f / 30.0f);
  EXPECT_FLOAT_EQ(value.values[1], 0.15f);
  EXPECT_FLOAT_EQ(value.values[2], 0.7f);
  EXPECT_THROW(referee_a_from_features(features_from_rows(10, {{1}, {2}}), 3),
               std::invalid_argument);
}

TEST(RefereeABestShift, FindsTheRollAligningQueryWithDatabase) {
  const std::vector<float> database{1, 5, 2, 0, 3};
  // query[i] = database[(i + 2) mod 5] -> roll(query, 2)[i] = query[i - 2] = database[i].
  const std::vector<float> query{2, 0, 3, 1, 5};
  EXPECT_EQ(referee_a_best_shift(query, database), 2);
  EXPECT_EQ(referee_a_best_shift(database, database), 0);
  EXPECT_EQ(referee_a_best_shift(std::vector<float>(5, 0.0f), database), std::nullopt);
  // Every dot product below -1: shift 0 gives -3*1 + -2*0 = -3, shift 1 (rolled {-2,-3}) gives -2.
  EXPECT_EQ(referee_a_best_shift(std::vector<float>{-3, -2}, std::vector<float>{1, 0}), 1);
  EXPECT_THROW(referee_a_best_shift(query, std::vector<float>{1, 2}), std::invalid_argument);
}

// A = 12 azimuths, R = 20, alpha = 6 (2 rows per block); one feature per row at distinct bins.
const std::vector<int> kFarthest = {3, 17, 8, 12, 5, 19, 1, 10, 14, 6, 9, 16};

PolarFeatures rows_turned_by(int k) {  // row a holds what database row (a + k) mod 12 holds
  std::vector<std::vector<int>> rows;
  for (int a = 0; a < 12; ++a)
    rows.push_back({kFarthest[static_cast<std::size_t>((a + k + 12) % 12)]});
  return features_from_rows(20, rows);
}

TEST(RefereeADescriptor, YawFromACircularlyShiftedMask) {
  RefereeAParams params;
  params.alpha = 6;
  const RefereeADescriptor descriptor(params);
  EXPECT_FALSE(descriptor.rotation_invariant());
  const DescriptorValue database = referee_a_from_features(rows_turned_by(0), 6);

  // Query row a = database row a + 4: 4 rows = 2 blocks -> s = 2, yaw = 2 pi * 2 / 6 = 2.0944.
  const auto turned_forward =
      descriptor.estimate_yaw(referee_a_from_features(rows_turned_by(4), 6), database);
  ASSERT_TRUE(turned_forward.has_value());
  EXPECT_NEAR(*turned_forward, 2.0 * std::numbers::pi / 3.0, 1e-12);

  // Query row a = database row a - 2: s = 6 - 1 = 5, 2 pi * 5 / 6 wraps to -pi / 3.
  const auto turned_back =
      descriptor.estimate_yaw(referee_a_from_features(rows_turned_by(-2), 6), database);
  ASSERT_TRUE(turned_back.has_value());
  EXPECT_NEAR(*turned_back, -std::numbers::pi / 3.0, 1e-12);

  // Half a turn: s = 3 -> yaw = +pi exactly (the interval is (-pi, pi]).
  const auto half_turn =
      descriptor.estimate_yaw(referee_a_from_features(rows_turned_by(6), 6), database);
  ASSERT_TRUE(half_turn.has_value());
  EXPECT_DOUBLE_EQ(*half_turn, std::numbers::pi);

  EXPECT_EQ(descriptor.estimate_yaw(database, database), 0.0);
  EXPECT_EQ(descriptor.estimate_yaw(DescriptorValue{6, 1, std::vector<float>(6, 0.0f)}, database),
            std::nullopt);
  EXPECT_THROW(descriptor.estimate_yaw(DescriptorValue{2, 1, {1.0f, 2.0f}}, database),
               std::invalid_argument);
}

TEST(RefereeADescriptor, ExtractsFiftyValuesWithL2Distance) {
  const RefereeADescriptor descriptor(RefereeAParams{});
  PolarImage scan;
  scan.power = ByteImage(400, 300, 3);
  const DescriptorValue value = descriptor.extract(scan);
  EXPECT_EQ(value.rows, 50);
  EXPECT_EQ(value.cols, 1);
  EXPECT_EQ(value.values, std::vector<float>(50, 0.0f));  // constant rows: no features
  EXPECT_DOUBLE_EQ(
      descriptor.distance(DescriptorValue{2, 1, {1.0f, 1.0f}}, DescriptorValue{2, 1, {4.0f, 5.0f}}),
      5.0);  // sqrt(3^2 + 4^2)
  PolarImage few;
  few.power = ByteImage(20, 300, 3);
  EXPECT_THROW(descriptor.extract(few), std::invalid_argument);
}

}  // namespace
}  // namespace radarpr
