// Revisit counts of generated trajectories: same direction in the same lane, one or two lanes
// over, and in reverse.
#include "datasets/synthetic/drive_path.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

namespace radarpr::synthetic {
namespace {

constexpr double kPi = std::numbers::pi;

struct RevisitCounts {
  int same_lane = 0;  // within 1.5 m across, same direction
  int one_lane = 0;   // 2.5 - 4.5 m across, same direction
  int two_lanes = 0;  // 6 - 8 m across, same direction
  int reverse = 0;    // opposite direction, within 10 m
};

// For every scan, the nearest scan at least 100 scans older: how far across the road (in that
// older scan's frame) and in which direction.
RevisitCounts count_revisits(const std::vector<Pose2D>& poses) {
  RevisitCounts counts;
  for (std::size_t q = 100; q < poses.size(); ++q) {
    double best = 10.0;
    std::size_t match = poses.size();
    for (std::size_t d = 0; d + 100 <= q; ++d) {
      const double gap = std::hypot(poses[q].x - poses[d].x, poses[q].y - poses[d].y);
      if (gap < best) {
        best = gap;
        match = d;
      }
    }
    if (match == poses.size()) continue;
    const Pose2D& p = poses[match];
    const double across =
        std::abs(-std::sin(p.yaw) * (poses[q].x - p.x) + std::cos(p.yaw) * (poses[q].y - p.y));
    const double turn = std::abs(std::remainder(poses[q].yaw - p.yaw, 2.0 * kPi));
    if (turn > 150.0 * kPi / 180.0) {
      ++counts.reverse;
    } else if (turn < 20.0 * kPi / 180.0) {
      if (across < 1.5) ++counts.same_lane;
      if (across > 2.5 && across < 4.5) ++counts.one_lane;
      if (across > 6.0 && across < 8.0) ++counts.two_lanes;
    }
  }
  return counts;
}

TEST(SyntheticDrive, LapPatternGivesEachKindOfRevisit) {
  // 2 x 1 blocks of 80 m: a lap is ~480 m = ~200 scans at 2.4 m. "FF1R" over 800 scans: lap 2
  // one lane (3.5 m) right of lap 1, lap 3 reverse, lap 4 in lap 1's lane again.
  DriveParams drive;
  drive.lap_pattern = "FF1R";
  const RevisitCounts counts = count_revisits(plan_drive(drive, 80.0, 7, 0, 800));
  EXPECT_GT(counts.one_lane, 150);   // lap 2 (and lap 4 against lap 2)
  EXPECT_GT(counts.reverse, 150);    // lap 3
  EXPECT_GT(counts.same_lane, 100);  // lap 4 against lap 1
  EXPECT_EQ(counts.two_lanes, 0);
}

TEST(SyntheticDrive, TwoLanesOver) {
  DriveParams drive;
  drive.lap_pattern = "FF2";
  drive.corner_radius_m = 13.0;
  const RevisitCounts counts = count_revisits(plan_drive(drive, 120.0, 33, 0, 600));
  // Lap 1 is ~ 2 x (240 + 120) = 720 m = 300 scans; lap 2 runs 7 m to its right.
  EXPECT_GT(counts.two_lanes, 200);
  EXPECT_LT(counts.same_lane, 30);  // only where lap 2 starts, before its S-bend
  EXPECT_EQ(counts.reverse, 0);
}

TEST(SyntheticDrive, LaneChangesAreSmooth) {
  DriveParams drive;
  drive.lap_pattern = "FF1F2R1";
  drive.corner_radius_m = 13.0;
  const std::vector<Pose2D> poses = plan_drive(drive, 80.0, 7, 0, 1000);
  for (std::size_t i = 1; i < poses.size(); ++i) {
    const double step = std::hypot(poses[i].x - poses[i - 1].x, poses[i].y - poses[i - 1].y);
    EXPECT_GT(step, 1.5) << i;
    EXPECT_LT(step, 3.0) << i;
  }
}

TEST(SyntheticDrive, RefusesBadPatternsAndLanes) {
  DriveParams drive;
  drive.lap_pattern = "F3";
  EXPECT_THROW(validate(drive, 80.0), std::invalid_argument);
  drive.lap_pattern = "F2";  // two lanes over needs a wider corner than 9 m
  EXPECT_THROW(validate(drive, 80.0), std::invalid_argument);
  drive.corner_radius_m = 13.0;
  EXPECT_NO_THROW(validate(drive, 80.0));
  drive.lane = 3;
  EXPECT_THROW(validate(drive, 80.0), std::invalid_argument);
}

}  // namespace
}  // namespace radarpr::synthetic
