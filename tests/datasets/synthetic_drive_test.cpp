// Revisit counts of generated trajectories: same direction in the same lane, one or two lanes
// over, and in reverse; and which drives fit which streets.
#include "datasets/synthetic/drive/drive_path.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "datasets/synthetic/world/world_presets.hpp"

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

CityLayout streets_of(const char* world) {
  return world_preset(world).layout;
}

// The message of the std::invalid_argument `validate` throws, or "" when it accepts.
// (Patterns are assigned as std::string(...) below: assigning a bare literal over the default
// trips a false -Wrestrict of GCC 12 at -O3.)
std::string refusal(const DriveParams& drive, const char* world, int scans = 600) {
  try {
    validate(drive, streets_of(world), scans, world);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

TEST(SyntheticDrive, LapPatternGivesEachKindOfRevisit) {
  // 2 x 1 blocks of 80 m: a lap is ~480 m = ~200 scans at 2.4 m. "FF1R" over 800 scans: lap 2
  // one lane (3.5 m) right of lap 1, lap 3 reverse, lap 4 in lap 1's lane again.
  DriveParams drive;
  drive.lap_pattern = std::string("FF1R");
  const RevisitCounts counts = count_revisits(plan_drive(drive, streets_of("city"), 7, 0, 800));
  EXPECT_GT(counts.one_lane, 150);   // lap 2 (and lap 4 against lap 2)
  EXPECT_GT(counts.reverse, 150);    // lap 3
  EXPECT_GT(counts.same_lane, 100);  // lap 4 against lap 1
  EXPECT_EQ(counts.two_lanes, 0);
}

TEST(SyntheticDrive, LanesAreTheStreetsLanes) {
  // The city's lanes are 3.5 m wide: lane 0 runs 1.75 m right of the centre line (y = -1.75 on
  // the first, eastbound street), lane 1 5.25 m; a reverse lap runs westbound at y = +1.75.
  DriveParams drive;
  drive.lap_pattern = std::string("F");
  drive.heading_jitter_deg = 0.0;
  EXPECT_NEAR(plan_drive(drive, streets_of("city"), 7, 0, 1)[0].y, -1.75, 1e-9);
  drive.lane = 1;
  EXPECT_NEAR(plan_drive(drive, streets_of("city"), 7, 0, 1)[0].y, -5.25, 1e-9);
  drive.lane = 0;
  drive.lap_pattern = std::string("R");
  const Pose2D reverse = plan_drive(drive, streets_of("city"), 7, 0, 1)[0];
  EXPECT_NEAR(reverse.y, 1.75, 1e-9);
  EXPECT_NEAR(std::abs(reverse.yaw), kPi, 1e-9);
}

TEST(SyntheticDrive, TwoLanesOverOnTheRiversideBoulevards) {
  DriveParams drive;
  drive.lap_pattern = std::string("FF2");
  drive.corner_radius_m = 13.0;
  const RevisitCounts counts =
      count_revisits(plan_drive(drive, streets_of("riverside"), 33, 0, 600));
  // Lap 1 is ~ 2 x (240 + 120) = 720 m = 300 scans; lap 2 runs 7 m to its right.
  EXPECT_GT(counts.two_lanes, 200);
  EXPECT_LT(counts.same_lane, 30);  // only where lap 2 starts, before its S-bend
  EXPECT_EQ(counts.reverse, 0);
}

TEST(SyntheticDrive, LaneChangesAreSmooth) {
  DriveParams drive;
  drive.lap_pattern = std::string("FF1F2R1");
  drive.corner_radius_m = 13.0;
  const std::vector<Pose2D> poses = plan_drive(drive, streets_of("riverside"), 7, 0, 1000);
  for (std::size_t i = 1; i < poses.size(); ++i) {
    const double step = std::hypot(poses[i].x - poses[i - 1].x, poses[i].y - poses[i - 1].y);
    EXPECT_GT(step, 1.5) << i;
    EXPECT_LT(step, 3.0) << i;
  }
}

TEST(SyntheticDrive, RefusesBadPatternsAndLanes) {
  DriveParams drive;
  drive.lap_pattern = std::string("F3");
  EXPECT_NE(refusal(drive, "city"), "");
  drive.lap_pattern = std::string("F2");
  EXPECT_EQ(refusal(drive, "riverside"), "");
  drive.lane = 3;
  EXPECT_NE(refusal(drive, "riverside").find("lane"), std::string::npos);
}

TEST(SyntheticDrive, LanesMustFitTheWorldsStreets) {
  DriveParams drive;
  // Lane 2 is centred 8.75 m from the centre line: + 0.72 m of session offset + 0.95 m of half
  // a car = 10.42 m, past the city's parking line at 7 m (two lanes of 3.5 m), inside the
  // riverside's 10.5 m (three lanes).
  drive.lap_pattern = std::string("FF2");
  const std::string city = refusal(drive, "city");
  for (const char* named : {"lane", "lap_pattern", "FF2", "city", "10.42"}) {
    EXPECT_NE(city.find(named), std::string::npos) << named << " in: " << city;
  }
  EXPECT_EQ(refusal(drive, "riverside"), "");
  // `lane` shifts every lap: lane 1 of a two-lane city fits, lane 1 of a one-lane suburb not.
  drive.lap_pattern = std::string("F");
  drive.lane = 1;
  EXPECT_EQ(refusal(drive, "city"), "");
  EXPECT_NE(refusal(drive, "suburban").find("suburban"), std::string::npos);
  EXPECT_NE(refusal(drive, "offroad").find("offroad"), std::string::npos);
  // A U-turn swings 4 m into the other side of the road: too much for one lane each way
  // (suburban parking line at 3.5 m), fine for two.
  drive.lane = 0;
  drive.lap_pattern = std::string("FR");
  EXPECT_NE(refusal(drive, "suburban").find("U-turn"), std::string::npos);
  EXPECT_EQ(refusal(drive, "city"), "");
  // A reverse lap in lane 1 turns inside the corner 5.25 + 0.72 m in from the centre line's 9 m:
  // a 3 m turn no car makes.
  drive.lap_pattern = std::string("FR1");
  EXPECT_NE(refusal(drive, "city").find("corner_radius_m"), std::string::npos);
  drive.corner_radius_m = 10.0;
  EXPECT_EQ(refusal(drive, "city"), "");
}

TEST(SyntheticDrive, RefusesDrivesThatCannotBeLaidOut) {
  DriveParams drive;
  // 10^6 scans 25 m apart (100 m/s at 4 Hz) need 28 000 km: ~58 000 laps of 480 m.
  drive.speed_mps = 100.0;
  EXPECT_NE(refusal(drive, "city", 1'000'000).find("speed_mps"), std::string::npos);
  EXPECT_EQ(refusal(drive, "city", 600), "");
  drive.speed_mps = 1e20;
  EXPECT_NE(refusal(drive, "city").find("speed_mps"), std::string::npos);
  // Scan periods are whole microseconds: 4 Hz (250 000 us) and 5 Hz yes, 3 Hz (333 333.3) no.
  drive = DriveParams{};
  drive.scan_rate_hz = 5.0;
  EXPECT_EQ(refusal(drive, "city"), "");
  for (const double bad : {3.0, 0.0, -4.0, 1e9}) {
    drive.scan_rate_hz = bad;
    EXPECT_NE(refusal(drive, "city").find("scan_rate_hz"), std::string::npos) << bad;
  }
  drive = DriveParams{};
  drive.route_blocks_x = 51;
  EXPECT_NE(refusal(drive, "city").find("route_blocks_x"), std::string::npos);
}

}  // namespace
}  // namespace radarpr::synthetic
