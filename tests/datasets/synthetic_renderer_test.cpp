#include "datasets/synthetic/radar/radar_renderer.hpp"

#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "datasets/synthetic/radar/radar_presets.hpp"
#include "datasets/synthetic/world/synthetic_world.hpp"
#include "descriptors/opencv_image.hpp"

namespace radarpr::synthetic {
namespace {

constexpr double kPi = std::numbers::pi;

// A noise-free radar whose pixels can be computed by hand: 64 azimuths (5.625 degrees apart, so
// the 1.8 degree beam does not reach the neighbouring azimuth: exp(-0.5 (5.625 / 0.764)^2) ~
// e^-27), 200 bins of 0.25 m, a flat noise floor of 0 units (linear power 1), no clutter, no
// range loss, no speckle, no side lobes, no multipath.
RadarModel clean_radar() {
  RadarModel radar;
  radar.azimuth_count = 64;
  radar.range_bin_count = 200;
  radar.range_resolution_m = 0.25;
  radar.range_spread_m = 0.25;  // one bin
  radar.noise_floor_near = 0.0;
  radar.noise_floor_far = 0.0;
  radar.ground_clutter = 0.0;
  radar.range_loss_per_m = 0.0;
  radar.speckle = false;
  radar.sidelobe_reach_deg = 0.0;      // main lobe only
  radar.multipath_min_level = 1000.0;  // no ghosts
  return radar;
}

WallSegment smooth_wall(Vec2 a, Vec2 b, float strength = 100.0f) {
  WallSegment wall;
  wall.a = a;
  wall.b = b;
  wall.strength = strength;
  wall.transmission = 0.0f;
  wall.texture_period_m = 0.0f;
  wall.scatter_units = 0.0f;
  return wall;
}

// A wall across the forward direction 20 m ahead, 20 m wide.
World wall_ahead() {
  World world;
  world.walls.push_back(smooth_wall({20.0, -10.0}, {20.0, 10.0}));
  return world;
}

int pixel(const PolarImage& image, int azimuth, int bin) {
  return image.power(azimuth, bin);
}

TEST(SyntheticRenderer, EmptyWorldIsTheNoiseFloor) {
  RadarModel radar = clean_radar();
  radar.noise_floor_near = 20.0;
  radar.noise_floor_far = 20.0;
  const PolarImage image = render_scan(World{}, Pose2D{}, radar, 1);
  ASSERT_EQ(image.power.rows(), 64);
  ASSERT_EQ(image.power.cols(), 200);
  EXPECT_EQ(image.range_resolution_m, 0.25);
  ASSERT_EQ(image.azimuths_rad.size(), 64u);
  EXPECT_NEAR(image.azimuths_rad[16], kPi / 2, 1e-12);  // 2 pi 16 / 64
  EXPECT_TRUE(image.azimuth_times_ns.empty());
  double low = 0.0;
  double high = 0.0;
  cv::minMaxLoc(opencv_view(image.power), &low, &high);
  EXPECT_EQ(low, 20.0);
  EXPECT_EQ(high, 20.0);
}

TEST(SyntheticRenderer, NoiseFloorFallsWithRange) {
  RadarModel radar = clean_radar();
  radar.noise_floor_near = 40.0;
  radar.noise_floor_far = 10.0;
  radar.noise_floor_falloff_m = 10.0;
  const PolarImage image = render_scan(World{}, Pose2D{}, radar, 1);
  // Bin r is at (r + 0.5) * 0.25 m: bin 0 -> 10 + 30 e^-0.0125 = 39.63 -> 40;
  // bin 39 (9.875 m) -> 10 + 30 e^-0.9875 = 21.17 -> 21; bin 199 (49.875 m) -> 10.2 -> 10.
  EXPECT_EQ(pixel(image, 0, 0), 40);
  EXPECT_EQ(pixel(image, 0, 39), 21);
  EXPECT_EQ(pixel(image, 0, 199), 10);
}

TEST(SyntheticRenderer, HeadOnWallEcho) {
  const PolarImage image = render_scan(wall_ahead(), Pose2D{}, clean_radar(), 1);
  // Azimuth 0 meets the wall at 20 m = bin 80, head-on (incidence factor 0.06 + 0.94 = 1):
  // 20 log10(1 + 10^(100/20)) = 100.0001 -> 100. One bin either side the range spread (sigma
  // one bin) gives 100 + 20 log10(e^-0.5) = 95.66 -> 96.
  EXPECT_EQ(pixel(image, 0, 80), 100);
  EXPECT_EQ(pixel(image, 0, 79), 96);
  EXPECT_EQ(pixel(image, 0, 81), 96);
  // Azimuth 4 (22.5 degrees) meets it at 20 / cos 22.5 = 21.65 m, in bin 86 (bin r holds
  // ranges [r, r + 1) x 0.25 m), with incidence factor 0.06 + 0.94 cos^4 22.5 = 0.745:
  // 100 - 2.56 = 97.4 -> 97.
  EXPECT_EQ(pixel(image, 4, 86), 97);
  // Azimuth 5 (28.1 degrees) passes the wall's end (26.6 degrees): floor only.
  EXPECT_EQ(cv::countNonZero(opencv_view(image.power).row(5)), 0);
  // Behind the wall: nothing (floor 0).
  EXPECT_EQ(cv::countNonZero(opencv_view(image.power).row(0).colRange(90, 200)), 0);
}

TEST(SyntheticRenderer, AnEchoLandsInTheBinThatHoldsItsRange) {
  // A pole whose front is 30.2 m away: bin 120 holds [30, 30.25) m. (Rounding to the nearest
  // bin centre would put it in 121.)
  World world;
  world.poles.push_back({{30.25, 0.0}, 0.05f, 90.0f, 0.9f});
  const PolarImage image = render_scan(world, Pose2D{}, clean_radar(), 1);
  EXPECT_EQ(pixel(image, 0, 120), 90);
  EXPECT_EQ(pixel(image, 0, 121), 86);  // one bin of range spread: 90 - 4.34
}

TEST(SyntheticRenderer, PoleBehindAWallIsHidden) {
  // A pole 35 m ahead: front surface 34.8 m = bin 139.2 -> 139, level 90.
  World pole_only;
  pole_only.poles.push_back({{35.0, 0.0}, 0.2f, 90.0f, 0.9f});
  const PolarImage visible = render_scan(pole_only, Pose2D{}, clean_radar(), 1);
  EXPECT_EQ(pixel(visible, 0, 139), 90);

  World hidden = wall_ahead();
  hidden.poles = pole_only.poles;
  const PolarImage occluded = render_scan(hidden, Pose2D{}, clean_radar(), 1);
  EXPECT_EQ(pixel(occluded, 0, 80), 100);  // the wall is there...
  for (int a : {63, 0, 1}) {
    EXPECT_EQ(cv::countNonZero(opencv_view(occluded.power).row(a).colRange(120, 160)), 0)
        << a;  // ...the pole not
  }
}

TEST(SyntheticRenderer, PolesAttenuateLittle) {
  // Two poles in a row: the far one loses the near one's transmission, 20 log10(0.9) = -0.92.
  World world;
  world.poles.push_back({{10.0, 0.0}, 0.2f, 90.0f, 0.9f});
  world.poles.push_back({{30.0, 0.0}, 0.2f, 90.0f, 0.9f});
  const PolarImage image = render_scan(world, Pose2D{}, clean_radar(), 1);
  EXPECT_EQ(pixel(image, 0, 39), 90);   // 9.8 m = bin 39.2
  EXPECT_EQ(pixel(image, 0, 119), 89);  // 29.8 m = bin 119.2; 90 - 0.92 = 89.08
}

TEST(SyntheticRenderer, FoliageAttenuatesAlongItsChord) {
  // A 2 m crown 15 m ahead: chord 4 m, transmission e^(-0.35 * 4) = 0.2466 = -12.16 units, so
  // the pole behind it drops from 90 to 77.84 -> 78. The crown itself returns from 13 m (bin 52).
  World world;
  world.foliage.push_back({{15.0, 0.0}, 2.0f, 50.0f, 0.35f});
  world.poles.push_back({{30.0, 0.0}, 0.2f, 90.0f, 0.9f});
  const PolarImage image = render_scan(world, Pose2D{}, clean_radar(), 1);
  EXPECT_EQ(pixel(image, 0, 119), 78);
  EXPECT_EQ(pixel(image, 0, 52), 50);  // entry of the crown: full level
  // The crown's own return fades over its 17 bins (52..68) by the same e^-1.4: 8 bins in,
  // 50 - 1.4 * 8 / 17 * 8.686 = 44.28 -> 44.
  EXPECT_EQ(pixel(image, 0, 60), 44);
}

TEST(SyntheticRenderer, GroundClutterLightsOnlyTheFreeSpaceInFront) {
  RadarModel radar = clean_radar();
  radar.ground_clutter = 10.0;
  radar.ground_clutter_falloff_m = 1e9;  // flat: 10 units wherever it applies
  const PolarImage image = render_scan(wall_ahead(), Pose2D{}, radar, 1);
  // 20 log10(1 + 10^(10/20)) would only apply where echoes add; free space is the level itself.
  EXPECT_EQ(pixel(image, 0, 40), 10);    // 10 m, in front of the wall
  EXPECT_EQ(pixel(image, 0, 150), 0);    // 37.5 m, in its shadow: darker
  EXPECT_EQ(pixel(image, 32, 150), 10);  // backwards nothing blocks the view
}

TEST(SyntheticRenderer, BeamSpreadsOverNeighbouringAzimuths) {
  // 400 azimuths (0.9 degrees): the 1.8 degree -3 dB beam is a Gaussian of sigma 0.8493 steps.
  // A 1 cm pole 30 m away is itself 0.0212 steps wide (asin(0.01 / 30.01) = 0.019 degrees), so
  // the next azimuth is 0.9788 steps off: exp(-0.5 (0.9788 / 0.8493)^2) = 0.515 = -5.77 units;
  // the one after, 1.9788 steps: 0.0663 = -23.6 units.
  RadarModel radar = clean_radar();
  radar.azimuth_count = 400;
  World world;
  world.poles.push_back({{30.01, 0.0}, 0.01f, 90.0f, 0.9f});  // front at 30 m = bin 120
  const PolarImage image = render_scan(world, Pose2D{}, radar, 1);
  EXPECT_EQ(pixel(image, 0, 120), 90);
  EXPECT_EQ(pixel(image, 1, 120), 84);  // 84.23
  EXPECT_EQ(pixel(image, 399, 120), 84);
  EXPECT_EQ(pixel(image, 2, 120), 66);  // 66.42
  EXPECT_EQ(pixel(image, 5, 120), 0);   // e^-17: far below the floor
}

TEST(SyntheticRenderer, PoseMovesAndTurnsTheSensor) {
  // Sensor at (5, 5) facing +y (yaw 90 degrees); a pole at (5, 35.25) is 30.05 m straight ahead
  // (front), bin 120.
  World world;
  world.poles.push_back({{5.0, 35.25}, 0.2f, 90.0f, 0.9f});
  const PolarImage image = render_scan(world, Pose2D{5.0, 5.0, kPi / 2}, clean_radar(), 1);
  EXPECT_EQ(pixel(image, 0, 120), 90);
  // Facing -x instead, the pole is on the right: azimuths run counter-clockwise, so it sits at
  // -90 degrees = azimuth 48 of 64.
  const PolarImage turned = render_scan(world, Pose2D{5.0, 5.0, kPi}, clean_radar(), 1);
  EXPECT_EQ(pixel(turned, 48, 120), 90);
  EXPECT_EQ(pixel(turned, 0, 120), 0);
}

TEST(SyntheticRenderer, SpeckleIsSeededAndUnbiasedInPower) {
  RadarModel radar = clean_radar();
  radar.noise_floor_near = 50.0;
  radar.noise_floor_far = 50.0;
  radar.speckle = true;
  radar.speckle_correlation_m = 0.0;  // independent per bin
  const PolarImage a = render_scan(World{}, Pose2D{}, radar, 42);
  const PolarImage b = render_scan(World{}, Pose2D{}, radar, 42);
  const PolarImage c = render_scan(World{}, Pose2D{}, radar, 43);
  EXPECT_TRUE(a.power == b.power);
  EXPECT_GT(cv::countNonZero(opencv_view(a.power) != opencv_view(c.power)), 64 * 200 / 2);
  // Exponential speckle multiplies the power by X with E[X] = 1: the mean power is the floor's
  // (12800 independent pixels, std of the mean 1 / sqrt(12800) = 0.009; rounding to whole
  // units adds 0.05 %).
  double power = 0.0;
  for (int row = 0; row < a.power.rows(); ++row) {
    for (int bin = 0; bin < a.power.cols(); ++bin)
      power += std::pow(10.0, pixel(a, row, bin) / 20.0);
  }
  EXPECT_NEAR(power / (64 * 200) / std::pow(10.0, 50.0 / 20.0), 1.0, 0.04);
  // In units it is biased low, by E[20 log10 X] = -20 * 0.5772 / ln 10 = -5.01: the mean pixel
  // is 44.99 (std of the mean ~0.1).
  EXPECT_NEAR(cv::mean(opencv_view(a.power))[0], 44.99, 0.5);
}

TEST(SyntheticRenderer, RejectsBadRadarModels) {
  RadarModel radar = clean_radar();
  radar.azimuth_count = 0;
  EXPECT_THROW(render_scan(World{}, Pose2D{}, radar, 1), std::invalid_argument);
  radar = clean_radar();
  radar.range_resolution_m = -1.0;
  try {
    render_scan(World{}, Pose2D{}, radar, 1);
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("range_resolution_m"), std::string::npos);
  }
  radar = clean_radar();
  radar.beam_width_deg = 0.0;
  EXPECT_THROW(validate(radar), std::invalid_argument);
}

// ---- The sensor model's effects, one at a time ----

// A point `range` metres away at a bearing of 45 degrees (azimuth 50 of 400).
Vec2 at_45_degrees(double range) {
  return {range * std::cos(kPi / 4), range * std::sin(kPi / 4)};
}

// A narrow wall (0.2 m, 0.38 degrees wide: one azimuth of 400) facing the sensor at a bearing
// of 45 degrees and `range` (30.1 m: bin 120 of 0.25 m).
WallSegment narrow_wall_facing_45_degrees(double range, float strength = 100.0f) {
  const Vec2 c = at_45_degrees(range);
  const double d = 0.1 * std::sin(kPi / 4);
  return smooth_wall({c.x + d, c.y - d}, {c.x - d, c.y + d}, strength);
}

World narrow_wall_at_45_degrees() {
  World world;
  world.walls.push_back(narrow_wall_facing_45_degrees(30.1));
  return world;
}

int brightest_bin(const PolarImage& image, int azimuth) {
  cv::Point where;
  cv::minMaxLoc(opencv_view(image.power).row(azimuth), nullptr, nullptr, nullptr, &where);
  return where.x;
}

TEST(SyntheticRenderer, WallAtAKnownRangeAndBearingAndItsShadow) {
  RadarModel radar = clean_radar();
  radar.azimuth_count = 400;
  radar.range_bin_count = 300;  // 75 m
  radar.ground_clutter = 10.0;  // flat 10 units wherever the beam still travels
  radar.ground_clutter_falloff_m = 1e9;
  radar.multipath_min_level = 80.0;  // ghosts on
  // Behind the wall on the same bearing, a pole whose front is 45.1 m away (bin 180).
  World world = narrow_wall_at_45_degrees();
  world.poles.push_back({at_45_degrees(45.3), 0.2f, 90.0f, 0.9f});
  const PolarImage image = render_scan(world, Pose2D{}, radar, 1);
  EXPECT_EQ(brightest_bin(image, 50), 120);
  EXPECT_EQ(pixel(image, 50, 120), 100);  // head-on, no losses
  EXPECT_EQ(pixel(image, 50, 100), 10);   // the ground in front of it
  // Beyond the main lobe (+-2 azimuths at 0.9 degrees) the wall is not seen: ground only.
  EXPECT_EQ(pixel(image, 47, 120), 10);
  EXPECT_EQ(pixel(image, 53, 120), 10);
  // Behind it, in its shadow, every cell is dark (floor 0: no ground, no pole) until the
  // multipath ghost at twice the range: 60.2 m = bin 240, 100 - 30 (multipath_loss) = 70 units.
  EXPECT_EQ(cv::countNonZero(opencv_view(image.power).row(50).colRange(124, 237)), 0);
  EXPECT_EQ(pixel(image, 50, 240), 70);
  // Without the wall the ground and the pole are there.
  World open;
  open.poles = world.poles;
  const PolarImage unshadowed = render_scan(open, Pose2D{}, radar, 1);
  EXPECT_EQ(pixel(unshadowed, 50, 150), 10);
  EXPECT_EQ(pixel(unshadowed, 50, 180), 90);
  // Without ghosts the whole shadow is dark.
  radar.multipath_min_level = 1000.0;
  const PolarImage no_ghost = render_scan(world, Pose2D{}, radar, 1);
  EXPECT_EQ(cv::countNonZero(opencv_view(no_ghost.power).row(50).colRange(124, 300)), 0);
}

TEST(SyntheticRenderer, GhostsLoseWhatTheBeamPassedThroughTwice) {
  // Before the 100-unit wall at 30.1 m, a thin screen at 20.1 m that passes half the power
  // (-6.02 units each round trip) and returns 40 units itself.
  RadarModel radar = clean_radar();
  radar.azimuth_count = 400;
  radar.range_bin_count = 300;
  radar.multipath_min_level = 80.0;
  World world = narrow_wall_at_45_degrees();
  WallSegment screen = narrow_wall_facing_45_degrees(20.1, 40.0f);
  screen.transmission = 0.5f;
  world.walls.push_back(screen);
  const PolarImage image = render_scan(world, Pose2D{}, radar, 1);
  // The wall through the screen: 100 - 6.02 = 93.98 -> 94. Its ghost goes through twice more:
  // 93.98 - 30 - 6.02 = 57.96 -> 58 (70 without the screen).
  EXPECT_EQ(pixel(image, 50, 120), 94);
  EXPECT_EQ(pixel(image, 50, 240), 58);
  // multipath_min_level applies to the echo as it arrives: 93.98 < 95, no ghost.
  radar.multipath_min_level = 95.0;
  EXPECT_EQ(pixel(render_scan(world, Pose2D{}, radar, 1), 50, 240), 0);
  EXPECT_EQ(pixel(render_scan(narrow_wall_at_45_degrees(), Pose2D{}, radar, 1), 50, 240), 70);
}

TEST(SyntheticRenderer, StrongEchoesLeakIntoSideLobes) {
  RadarModel radar = clean_radar();
  radar.azimuth_count = 400;
  radar.sidelobe_reach_deg = 12.0;  // 13 azimuths
  // The 100-unit wall, and a 96-unit pillar 5 cm thin at the same place (front at 30.05 m):
  // both main lobes cover +-2 azimuths.
  World pillar;
  pillar.poles.push_back({at_45_degrees(30.1), 0.05f, 96.0f, 0.9f});
  const PolarImage wall = render_scan(narrow_wall_at_45_degrees(), Pose2D{}, radar, 1);
  const PolarImage pole = render_scan(pillar, Pose2D{}, radar, 1);
  EXPECT_EQ(pixel(pole, 50, 120), 96);
  // First side lobe, 3 azimuths off: 100 - 52 = 48 units (20 log10(1 + 10^(48/20)) = 48.0),
  // and 96 - 52 = 44.
  for (const int a : {47, 53}) {
    EXPECT_EQ(pixel(wall, a, 120), 48);
    EXPECT_EQ(pixel(pole, a, 120), 44);
  }
  // 5 azimuths off (1.8 degrees past the first lobe): -52 - 1.5 x 1.8 = -54.7 units of envelope
  // times the lobe shape 0.1 + 0.9 cos^2(0.9 pi) = 0.914 (-0.78 units): 44.52 -> 45.
  EXPECT_EQ(pixel(wall, 55, 120), 45);
  // Beyond the reach nothing.
  for (const int a : {36, 64}) {
    EXPECT_EQ(pixel(wall, a, 120), 0);
    EXPECT_EQ(pixel(pole, a, 120), 0);
  }
}

TEST(SyntheticRenderer, MotionDuringTheSweepShiftsEachAzimuth) {
  // Driving along +x at 9.6 m/s: 1.2 m either side of the middle pose over one revolution.
  RadarModel radar = clean_radar();
  radar.azimuth_count = 400;
  const SensorSweep sweep{{-1.2, 0.0, 0.0}, {0.0, 0.0, 0.0}, {1.2, 0.0, 0.0}};
  const World world = wall_ahead();  // x = 20, y in [-10, 10]
  const World* layers[] = {&world};
  const PolarImage moving = render_scan(layers, sweep, radar, 1);
  // Row 0 is measured at the start (x = -1.2): 21.2 m, bin 84 (80 when still).
  EXPECT_EQ(brightest_bin(moving, 0), 84);
  // Row 399 almost at the end (x = 1.2 - 2.4 / 400 = 1.194), looking 0.9 degrees right:
  // 18.806 / cos(0.9 deg) = 18.808 m, bin 75.
  EXPECT_EQ(brightest_bin(moving, 399), 75);
  // Row 200 (backwards) at the middle pose: nothing ahead of it.
  EXPECT_EQ(cv::countNonZero(opencv_view(moving.power).row(200)), 0);
  const PolarImage still = render_scan(world, Pose2D{}, radar, 1);
  EXPECT_EQ(brightest_bin(still, 0), 80);
  EXPECT_EQ(brightest_bin(still, 399), 80);
}

TEST(SyntheticRenderer, RainRaisesTheNoiseNearbyAndShortensTheRange) {
  RadarModel clear = clean_radar();
  clear.range_bin_count = 400;  // 100 m
  World world;
  world.poles.push_back({{80.25, 0.0}, 0.2f, 90.0f, 0.9f});  // front at 80.05 m: bin 320
  const RadarModel rain = with_weather(clear, Weather::rain);
  const PolarImage dry = render_scan(world, Pose2D{}, clear, 1);
  const PolarImage wet = render_scan(world, Pose2D{}, rain, 1);
  EXPECT_EQ(pixel(dry, 0, 320), 90);
  // 0.08 units/m over 80.05 m: 6.4 units lost; the rain's floor there (bin centre 80.125 m),
  // 1 - e^(-80.125/40) + 4 e^(-80.125/20) = 0.94 units (1.11 linear), is nothing beside
  // 10^(83.6/20): 83.6 -> 84.
  EXPECT_EQ(pixel(wet, 0, 320), 84);
  // Near the sensor the rain's backscatter: at bin 4 (centre 1.125 m) the floor (far 1 unit,
  // near 0, falling over 40 m) plus 4 e^(-1.125/20): 1 - 0.9723 + 4 x 0.9453 = 3.81 -> 4.
  EXPECT_EQ(pixel(dry, 10, 4), 0);
  EXPECT_EQ(pixel(wet, 10, 4), 4);
}

TEST(SyntheticWorld, BoxHasFourClosedSides) {
  World world;
  add_box(world, {10.0, 5.0}, 4.0, 2.0, kPi / 2, {});
  ASSERT_EQ(world.walls.size(), 4u);
  // Rotated 90 degrees: 4 m along y, 2 m along x -> corners (9..11, 3..7).
  for (std::size_t i = 0; i < 4; ++i) {
    const WallSegment& w = world.walls[i];
    const WallSegment& next = world.walls[(i + 1) % 4];
    EXPECT_NEAR(w.b.x, next.a.x, 1e-12);
    EXPECT_NEAR(w.b.y, next.a.y, 1e-12);
    EXPECT_NEAR(std::abs(w.a.x - 10.0), 1.0, 1e-9);
    EXPECT_NEAR(std::abs(w.a.y - 5.0), 2.0, 1e-9);
  }
}

}  // namespace
}  // namespace radarpr::synthetic
