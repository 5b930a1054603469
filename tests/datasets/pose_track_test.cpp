#include "datasets/pose_track.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <gtest/gtest.h>

namespace radarpr {
namespace {

constexpr std::int64_t kT0 = 1'600'000'000'000'000'000;  // 2020-09-13, ns
constexpr std::int64_t kSecond = 1'000'000'000;
constexpr double kPi = std::numbers::pi;

TEST(PoseTrack, InterpolatesPositionLinearlyAndYawAlongTheShorterArc) {
  const PoseTrack track({{kT0, {0.0, 0.0, 0.0}}, {kT0 + kSecond, {10.0, -4.0, 0.5}}});
  // A quarter of the way: x = 10 / 4, y = -4 / 4, yaw = 0.5 / 4.
  const auto pose = track.at(kT0 + kSecond / 4);
  ASSERT_TRUE(pose.has_value());
  EXPECT_DOUBLE_EQ(pose->x, 2.5);
  EXPECT_DOUBLE_EQ(pose->y, -1.0);
  EXPECT_DOUBLE_EQ(pose->yaw, 0.125);
}

TEST(PoseTrack, YawCrossesPiTheShortWay) {
  // From 3.0 to -2.9 rad the short arc passes pi: the step is -2.9 - 3.0 + 2 pi = 0.3832; half
  // way is 3.0 + 0.1916 = 3.1916, wrapped to 3.1916 - 2 pi = -3.0916. The long way (averaging
  // the numbers) would give 0.05.
  const PoseTrack track({{kT0, {0.0, 0.0, 3.0}}, {kT0 + 2 * kSecond, {0.0, 0.0, -2.9}}});
  const auto pose = track.at(kT0 + kSecond);
  ASSERT_TRUE(pose.has_value());
  EXPECT_NEAR(pose->yaw, 3.0 + (2 * kPi - 5.9) / 2 - 2 * kPi, 1e-12);
  EXPECT_NEAR(interpolate_yaw(-3.0, 3.0, 0.5), kPi, 1e-12);  // step -0.283: -3.1416 = pi
  EXPECT_NEAR(wrap_angle(3 * kPi / 2), -kPi / 2, 1e-12);
  EXPECT_NEAR(wrap_angle(-kPi), kPi, 1e-12);  // (-pi, pi]
}

TEST(PoseTrack, NeverExtrapolatesBeyondOneMicrosecondAtTheEnds) {
  const PoseTrack track({{kT0, {1.0, 2.0, 0.0}}, {kT0 + kSecond, {3.0, 4.0, 0.0}}});
  EXPECT_FALSE(track.at(kT0 - 1001).has_value());
  EXPECT_FALSE(track.at(kT0 + kSecond + 1001).has_value());
  // The ends themselves are samples.
  EXPECT_DOUBLE_EQ(track.at(kT0)->x, 1.0);
  EXPECT_DOUBLE_EQ(track.at(kT0 + kSecond)->y, 4.0);
  // Up to 1 µs outside: clamped to the end sample, not extrapolated (x would be 1 - 2e-6).
  EXPECT_DOUBLE_EQ(track.at(kT0 - 1000)->x, 1.0);
  EXPECT_DOUBLE_EQ(track.at(kT0 + kSecond + 1000)->y, 4.0);
  EXPECT_FALSE(PoseTrack({}).at(kT0).has_value());
  const PoseTrack single(std::vector<PoseSample>{{kT0, {5.0, 6.0, 0.0}}});
  EXPECT_DOUBLE_EQ(single.at(kT0)->x, 5.0);
  EXPECT_DOUBLE_EQ(single.at(kT0 + 1)->x, 5.0);
  EXPECT_FALSE(single.at(kT0 + 1001).has_value());
}

TEST(PoseTrack, ScansNamedInMicrosecondsMatchNanosecondPosesAtTheEnds) {
  // Poses stamped in ns with sub-µs digits (..776081 and ..776081 + 1 s); scans named in µs,
  // 1547131046353776 µs = ..776000 ns: 81 ns before the first pose, which used to drop the scan.
  constexpr std::int64_t kFirstPose = 1'547'131'046'353'776'081;
  const PoseTrack track({{kFirstPose, {10.0, 0.0, 0.0}}, {kFirstPose + kSecond, {11.0, 0.0, 0.0}}});
  const auto first_scan = track.at(1'547'131'046'353'776'000);
  ASSERT_TRUE(first_scan.has_value());
  EXPECT_DOUBLE_EQ(first_scan->x, 10.0);
  // The last scan, 1 s later in µs (..777'353'776'000 ns), is 81 ns before the last pose:
  // inside the track, interpolated to 11 - 81e-9 m.
  EXPECT_NEAR(track.at(1'547'131'047'353'776'000)->x, 11.0 - 81e-9, 1e-9);
}

TEST(PoseTrack, DoesNotBridgeGapsLongerThanTheLimit) {
  // Samples at 0, 1 and 10 s: 1 -> 10 is a 9 s gap.
  const PoseTrack track({{kT0, {0.0, 0.0, 0.0}},
                         {kT0 + kSecond, {1.0, 0.0, 0.0}},
                         {kT0 + 10 * kSecond, {10.0, 0.0, 0.0}}});
  EXPECT_FALSE(track.at(kT0 + 5 * kSecond, 5 * kSecond).has_value());
  ASSERT_TRUE(track.at(kT0 + 5 * kSecond, 9 * kSecond).has_value());   // the limit is inclusive
  EXPECT_DOUBLE_EQ(track.at(kT0 + 5 * kSecond, 9 * kSecond)->x, 5.0);  // 1 + 4/9 * 9
  EXPECT_DOUBLE_EQ(track.at(kT0 + kSecond / 2, 5 * kSecond)->x, 0.5);
  EXPECT_EQ(track.largest_gap_ns(), 9 * kSecond);
  // Only the intervals meeting [0.2 s, 0.8 s]: the first one, 1 s long.
  EXPECT_EQ(track.largest_gap_ns(kT0 + kSecond / 5, kT0 + 4 * kSecond / 5), kSecond);
}

TEST(PoseTrack, SortsSamplesAndKeepsTheFirstOfEachTimestamp) {
  const PoseTrack track({{kT0 + kSecond, {2.0, 0.0, 0.0}},
                         {kT0, {0.0, 0.0, 0.0}},
                         {kT0 + kSecond, {99.0, 0.0, 0.0}}});  // duplicate: dropped
  ASSERT_EQ(track.size(), 2u);
  EXPECT_EQ(track.duplicated_timestamps(), 1u);
  EXPECT_EQ(track.first_ns(), kT0);
  EXPECT_DOUBLE_EQ(track.at(kT0 + kSecond)->x, 2.0);
  EXPECT_DOUBLE_EQ(track.at(kT0 + kSecond / 2)->x, 1.0);
}

TEST(PoseTrack, RejectsNonFinitePoses) {
  using Samples = std::vector<PoseSample>;
  EXPECT_THROW(PoseTrack(Samples{{kT0, {std::nan(""), 0.0, 0.0}}}), std::invalid_argument);
  EXPECT_THROW(PoseTrack(Samples{{kT0, {0.0, 0.0, INFINITY}}}), std::invalid_argument);
}

}  // namespace
}  // namespace radarpr
