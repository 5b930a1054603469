#include "datasets/synthetic/synthetic_sequence.hpp"
#include "descriptors/opencv_image.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

namespace radarpr {
namespace {

constexpr double kPi = std::numbers::pi;

// Short sequences with short range so the tests render quickly.
SyntheticConfig small_config() {
  SyntheticConfig config;
  config.scan_count = 40;
  config.radar.range_bin_count = 500;
  return config;
}

bool same_pixels(const PolarImage& a, const PolarImage& b) {
  return a.power == b.power;
}

double distance(const Pose2D& a, const Pose2D& b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}

double heading_difference(const Pose2D& a, const Pose2D& b) {
  return std::abs(std::remainder(a.yaw - b.yaw, 2.0 * kPi));
}

// ---- Determinism ----

TEST(SyntheticSequence, SameConfigSamePixelsWhateverTheOrder) {
  const SyntheticSequence first(small_config());
  const SyntheticSequence second(small_config());
  const std::vector<std::size_t> forward = {3, 17, 31};
  std::vector<PolarImage> images;
  for (const std::size_t i : forward) images.push_back(first.load_image(i));
  // The other instance loads them backwards, after unrelated scans.
  (void)second.load_image(0);
  (void)second.load_image(39);
  for (std::size_t k = forward.size(); k-- > 0;) {
    EXPECT_TRUE(same_pixels(images[k], second.load_image(forward[k]))) << forward[k];
  }
  // And again from the first instance: loading is not stateful.
  EXPECT_TRUE(same_pixels(images[0], first.load_image(3)));
}

TEST(SyntheticSequence, ThreadsGetTheSamePixels) {
  const SyntheticSequence sequence(small_config());
  std::vector<PolarImage> sequential;
  for (std::size_t i = 0; i < 8; ++i) sequential.push_back(sequence.load_image(i));
  std::vector<PolarImage> parallel(8);
  auto work = [&](std::size_t start) {
    for (std::size_t i = start; i < 8; i += 2) parallel[i] = sequence.load_image(i);
  };
  std::thread other(work, 1);
  work(0);
  other.join();
  for (std::size_t i = 0; i < 8; ++i) EXPECT_TRUE(same_pixels(sequential[i], parallel[i])) << i;
}

TEST(SyntheticSequence, SessionsAndSeedsDiffer) {
  SyntheticConfig config = small_config();
  const SyntheticSequence session0(config);
  config.session = 1;
  const SyntheticSequence session1(config);
  config.session = 0;
  config.seed = 8;
  const SyntheticSequence other_city(config);

  const PolarImage a = session0.load_image(10);
  const PolarImage b = session1.load_image(10);
  const PolarImage c = other_city.load_image(10);
  const int pixels = a.power.rows() * a.power.cols();
  EXPECT_GT(cv::countNonZero(opencv_view(a.power) != opencv_view(b.power)), pixels / 2);
  EXPECT_GT(cv::countNonZero(opencv_view(a.power) != opencv_view(c.power)), pixels / 2);
  EXPECT_GT(distance(session0.records()[10].pose, session1.records()[10].pose), 0.3);
  // Neighbouring scans of one sequence differ too (own noise, moved sensor).
  EXPECT_GT(cv::countNonZero(opencv_view(a.power) != opencv_view(session0.load_image(11).power)),
            pixels / 2);
}

TEST(SyntheticSequence, SessionsShareTheCity) {
  SyntheticConfig config = small_config();
  const SyntheticSequence session0(config);
  config.session = 2;
  const SyntheticSequence session2(config);
  // Both worlds cover the start street; every wall of session 0 within 30 m of the start
  // exists in session 2 as well (the city is a function of the world seed alone).
  auto near_start = [](const synthetic::WallSegment& w) {
    return std::hypot(w.a.x - 40.0, w.a.y) < 30.0;
  };
  std::set<std::vector<double>> walls2;
  for (const auto& w : session2.world().walls) walls2.insert({w.a.x, w.a.y, w.b.x, w.b.y});
  int compared = 0;
  for (const auto& w : session0.world().walls) {
    if (!near_start(w)) continue;
    ++compared;
    EXPECT_TRUE(walls2.count({w.a.x, w.a.y, w.b.x, w.b.y}) == 1);
  }
  EXPECT_GT(compared, 10);
}

// ---- Metadata ----

// A route origin moves the whole drive by whole blocks of the same city: same poses shifted by
// (1 x 80 m, -2 x 80 m) at the default block pitch, so the two drives share no street.
TEST(SyntheticSequence, RouteOriginShiftsTheDriveByWholeBlocks) {
  SyntheticConfig config = small_config();
  const SyntheticSequence base(config);
  config.drive.route_origin_block_x = 1;
  config.drive.route_origin_block_y = -2;
  const SyntheticSequence shifted(config);
  ASSERT_EQ(base.size(), shifted.size());
  for (std::size_t i = 0; i < base.size(); ++i) {
    EXPECT_NEAR(shifted.records()[i].pose.x, base.records()[i].pose.x + 80.0, 1e-9);
    EXPECT_NEAR(shifted.records()[i].pose.y, base.records()[i].pose.y - 160.0, 1e-9);
    EXPECT_EQ(shifted.records()[i].pose.yaw, base.records()[i].pose.yaw);
  }
}

TEST(SyntheticSequence, ImageShapeResolutionAndTimes) {
  const SyntheticSequence sequence(small_config());
  ASSERT_EQ(sequence.size(), 40u);
  const PolarImage image = sequence.load_image(5);
  EXPECT_EQ(image.power.rows(), 400);
  EXPECT_EQ(image.power.cols(), 500);
  EXPECT_EQ(image.range_resolution_m, 0.0595238);
  ASSERT_EQ(image.azimuths_rad.size(), 400u);
  EXPECT_NEAR(image.azimuths_rad[100], kPi / 2, 1e-12);  // 2 pi 100 / 400
  // 4 Hz: scans 250 ms apart from 1.7e18 ns; azimuths 250 ms / 400 = 625 us apart with row
  // 200 at the scan's time.
  const std::int64_t t5 = 1'700'000'000'000'000'000 + 5 * 250'000'000;
  EXPECT_EQ(sequence.records()[5].timestamp_ns, t5);
  ASSERT_EQ(image.azimuth_times_ns.size(), 400u);
  EXPECT_EQ(image.azimuth_times_ns[200], t5);
  EXPECT_EQ(image.azimuth_times_ns[0], t5 - 200 * 625'000);
  EXPECT_EQ(image.azimuth_times_ns[399], t5 + 199 * 625'000);
  EXPECT_EQ(sequence.records()[5].source, "synthetic(seed=7,session=0)#5");
}

TEST(SyntheticSequence, SessionsStartADayApart) {
  SyntheticConfig config = small_config();
  config.session = 2;
  const SyntheticSequence sequence(config);
  EXPECT_EQ(sequence.records()[0].timestamp_ns, 1'700'000'000'000'000'000 + 2 * 86'400'000'000'000);
}

TEST(SyntheticSequence, NameAndFingerprint) {
  SyntheticConfig config = small_config();
  EXPECT_EQ(SyntheticSequence(config).name(), "synthetic(seed=7,session=0)");
  config.seed = 12;
  config.session = 3;
  EXPECT_EQ(SyntheticSequence(config).name(), "synthetic(seed=12,session=3)");

  // Changing any field changes the fingerprint.
  const std::vector<std::function<void(SyntheticConfig&)>> changes = {
      [](SyntheticConfig& c) { c.seed = 8; },
      [](SyntheticConfig& c) { c.session = 1; },
      [](SyntheticConfig& c) { c.scan_count = 41; },
      [](SyntheticConfig& c) { c.start_time_ns += 1000; },
      [](SyntheticConfig& c) { c.radar.azimuth_count = 399; },
      [](SyntheticConfig& c) { c.radar.range_bin_count = 501; },
      [](SyntheticConfig& c) { c.radar.range_resolution_m = 0.05; },
      [](SyntheticConfig& c) { c.radar.beam_width_deg = 2.0; },
      [](SyntheticConfig& c) { c.radar.range_spread_m = 0.3; },
      [](SyntheticConfig& c) { c.radar.noise_floor_near = 17.0; },
      [](SyntheticConfig& c) { c.radar.noise_floor_far = 7.0; },
      [](SyntheticConfig& c) { c.radar.noise_floor_falloff_m = 41.0; },
      [](SyntheticConfig& c) { c.radar.ground_clutter = 12.0; },
      [](SyntheticConfig& c) { c.radar.ground_clutter_falloff_m = 26.0; },
      [](SyntheticConfig& c) { c.radar.range_loss_per_m = 0.13; },
      [](SyntheticConfig& c) { c.radar.speckle = false; },
      [](SyntheticConfig& c) { c.radar.speckle_correlation_m = 0.2; },
      [](SyntheticConfig& c) { c.city.block_pitch_m = 90.0; },
      [](SyntheticConfig& c) { c.city.street.lanes_per_direction = 3; },
      [](SyntheticConfig& c) { c.city.street.lane_width_m = 3.25; },
      [](SyntheticConfig& c) { c.city.street.parking_width_m = 2.2; },
      [](SyntheticConfig& c) { c.city.street.pavement_width_m = 4.0; },
      [](SyntheticConfig& c) { c.city.park_fraction = 0.3; },
      [](SyntheticConfig& c) { c.drive.route_blocks_x = 3; },
      [](SyntheticConfig& c) { c.drive.route_blocks_y = 2; },
      [](SyntheticConfig& c) { c.drive.route_origin_block_x = 1; },
      [](SyntheticConfig& c) { c.drive.route_origin_block_y = -1; },
      [](SyntheticConfig& c) { c.drive.lap_pattern = "FR"; },
      [](SyntheticConfig& c) { c.drive.speed_mps = 9.0; },
      [](SyntheticConfig& c) { c.drive.scan_rate_hz = 5.0; },
      [](SyntheticConfig& c) {
        c.drive.lap_pattern = "F";
        c.drive.lane = 1;
      },
      [](SyntheticConfig& c) { c.world.traffic = 0.5; },
      [](SyntheticConfig& c) { c.drive.corner_radius_m = 10.0; },
      [](SyntheticConfig& c) { c.drive.session_offset_m = 0.5; },
      [](SyntheticConfig& c) { c.drive.heading_jitter_deg = 0.6; },
  };
  std::set<std::string> fingerprints{SyntheticSequence(small_config()).fingerprint()};
  for (const auto& change : changes) {
    SyntheticConfig changed = small_config();
    change(changed);
    fingerprints.insert(SyntheticSequence(changed).fingerprint());
  }
  EXPECT_EQ(fingerprints.size(), changes.size() + 1);
}

TEST(SyntheticSequence, BadIndexThrows) {
  const SyntheticSequence sequence(small_config());
  EXPECT_THROW(sequence.load_image(40), std::out_of_range);
}

// ---- Trajectory (the default drive: 600 scans, laps forward, forward, reverse) ----

class DefaultDrive : public ::testing::Test {
 protected:
  const SyntheticSequence sequence{SyntheticConfig{}};
  const std::vector<ScanRecord>& records = sequence.records();
};

TEST_F(DefaultDrive, ScansAreACarAt4HzApart) {
  ASSERT_EQ(records.size(), 600u);
  // 9.6 m/s at 4 Hz = 2.4 m, slowed to 0.66x at curves, +-12% in between.
  for (std::size_t i = 1; i < records.size(); ++i) {
    const double step = distance(records[i - 1].pose, records[i].pose);
    EXPECT_GE(step, 1.5) << i;
    EXPECT_LE(step, 3.0) << i;
  }
}

TEST_F(DefaultDrive, HeadingFollowsTheRoad) {
  int aligned = 0;
  for (std::size_t i = 1; i < records.size(); ++i) {
    const Pose2D& a = records[i - 1].pose;
    const Pose2D& b = records[i].pose;
    const Pose2D travel{0, 0, std::atan2(b.y - a.y, b.x - a.x)};
    const double off = heading_difference(a, travel);
    EXPECT_LT(off, 25.0 * kPi / 180) << i;  // tight U-turn arcs: chord vs tangent
    if (off < 5.0 * kPi / 180) ++aligned;
  }
  EXPECT_GT(aligned, 540);  // straight driving, 0.5 degree jitter
}

TEST_F(DefaultDrive, RevisitsInTheSameAndTheOppositeDirection) {
  // A lap of the 160 m x 80 m loop is ~480 m = ~200 scans: scans 200-399 retrace scans 0-199
  // in the same lane, scans from ~415 on drive it the other way in the opposite lane, 4 m over.
  int same = 0;
  int opposite = 0;
  for (std::size_t q = 0; q < records.size(); ++q) {
    bool found_same = false;
    bool found_opposite = false;
    for (std::size_t d = 0; d + 100 < q; ++d) {
      const double gap = distance(records[q].pose, records[d].pose);
      const double turn = heading_difference(records[q].pose, records[d].pose);
      found_same |= gap < 3.0 && turn < 20.0 * kPi / 180;
      found_opposite |= gap < 6.0 && turn > 160.0 * kPi / 180;
    }
    same += found_same;
    opposite += found_opposite;
  }
  EXPECT_GT(same, 150);
  EXPECT_GT(opposite, 100);
}

TEST_F(DefaultDrive, OtherSessionsDriveHalfAMetreOrSoAside) {
  SyntheticConfig config;
  config.session = 1;
  const SyntheticSequence session1(config);
  // First lap of session 1 against all of session 0's first lap: nearest scan within the
  // lateral offset (0.48-0.72 m, to the right) plus at most half a scan spacing along the road.
  for (std::size_t q = 0; q < 180; ++q) {
    double nearest = 1e9;
    for (std::size_t d = 0; d < 200; ++d) {
      nearest = std::min(nearest, distance(session1.records()[q].pose, records[d].pose));
    }
    EXPECT_GT(nearest, 0.4) << q;
    EXPECT_LT(nearest, 1.9) << q;
  }
}

TEST_F(DefaultDrive, ScansLookLikeRadar) {
  // Returns (buildings, cars, poles) well above the noise floor, but most of the scan dark.
  const PolarImage image = sequence.load_image(100);
  double high = 0.0;
  cv::minMaxLoc(opencv_view(image.power), nullptr, &high);
  EXPECT_GT(high, 90.0);
  const double pixels = image.power.rows() * image.power.cols();
  const double bright = cv::countNonZero(opencv_view(image.power) > 60) / pixels;
  EXPECT_GT(bright, 0.002);
  EXPECT_LT(bright, 0.15);
  EXPECT_LT(cv::mean(opencv_view(image.power))[0], 30.0);
}

// ---- Config validation ----

void expect_invalid(const std::function<void(SyntheticConfig&)>& change, const std::string& field) {
  SyntheticConfig config = small_config();
  change(config);
  try {
    const SyntheticSequence sequence(config);
    ADD_FAILURE() << "no exception for a bad " << field;
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find(field), std::string::npos) << error.what();
  }
}

TEST(SyntheticConfigValidation, RejectsBadFieldsByName) {
  expect_invalid([](SyntheticConfig& c) { c.scan_count = 0; }, "scan_count");
  expect_invalid([](SyntheticConfig& c) { c.session = -1; }, "session");
  expect_invalid([](SyntheticConfig& c) { c.radar.azimuth_count = 0; }, "azimuth_count");
  expect_invalid([](SyntheticConfig& c) { c.radar.range_bin_count = 0; }, "range_bin_count");
  expect_invalid([](SyntheticConfig& c) { c.radar.range_bin_count = 389; }, "too few");
  expect_invalid([](SyntheticConfig& c) { c.radar.range_resolution_m = 0.0; },
                 "range_resolution_m");
  expect_invalid([](SyntheticConfig& c) { c.radar.beam_width_deg = -1.0; }, "beam_width_deg");
  expect_invalid([](SyntheticConfig& c) { c.radar.speckle_correlation_m = -0.1; },
                 "speckle_correlation_m");
  expect_invalid([](SyntheticConfig& c) { c.city.block_pitch_m = 30.0; }, "block_pitch_m");
  expect_invalid([](SyntheticConfig& c) { c.city.park_fraction = 1.5; }, "park_fraction");
  expect_invalid([](SyntheticConfig& c) { c.city.street.lanes_per_direction = 0; },
                 "lanes_per_direction");
  expect_invalid([](SyntheticConfig& c) { c.drive.route_blocks_x = 0; }, "route_blocks_x");
  expect_invalid([](SyntheticConfig& c) { c.drive.lap_pattern = "FX"; }, "lap_pattern");
  expect_invalid([](SyntheticConfig& c) { c.drive.lap_pattern = ""; }, "lap_pattern");
  expect_invalid([](SyntheticConfig& c) { c.drive.lap_pattern = "FF2"; }, "lap_pattern");
  expect_invalid([](SyntheticConfig& c) { c.drive.speed_mps = 0.0; }, "speed_mps");
  expect_invalid([](SyntheticConfig& c) { c.drive.scan_rate_hz = -4.0; }, "scan_rate_hz");
  expect_invalid([](SyntheticConfig& c) { c.drive.corner_radius_m = 2.5; }, "corner_radius_m");
  expect_invalid([](SyntheticConfig& c) { c.drive.heading_jitter_deg = -1.0; },
                 "heading_jitter_deg");
}

// Values that would eat all memory or overflow the clock are refused before anything is built.
TEST(SyntheticConfigValidation, BoundsWhatCouldEatMemoryOrOverflow) {
  expect_invalid([](SyntheticConfig& c) { c.scan_count = 1'000'001; }, "scan_count");
  expect_invalid([](SyntheticConfig& c) { c.session = 1001; }, "session");
  // 4096 x 4097 pixels > 2^24; 5000 bins of 0.2 m = 1 km of reach > 500 m.
  expect_invalid(
      [](SyntheticConfig& c) {
        c.radar.azimuth_count = 4096;
        c.radar.range_bin_count = 4097;
      },
      "azimuth_count x range_bin_count");
  expect_invalid(
      [](SyntheticConfig& c) {
        c.radar.range_bin_count = 5000;
        c.radar.range_resolution_m = 0.2;
      },
      "range_bin_count x range_resolution_m");
  expect_invalid([](SyntheticConfig& c) { c.radar.range_spread_m = 1e9; }, "range_spread_m");
  expect_invalid([](SyntheticConfig& c) { c.radar.speckle_correlation_m = 1e9; },
                 "speckle_correlation_m");
  expect_invalid([](SyntheticConfig& c) { c.drive.speed_mps = 1e20; }, "speed_mps");
  expect_invalid([](SyntheticConfig& c) { c.drive.scan_rate_hz = 3.0; }, "scan_rate_hz");
  // 1999-12-31, 2100-01-01 and a time between whole microseconds.
  expect_invalid([](SyntheticConfig& c) { c.start_time_ns = 946'684'799'000'000'000; },
                 "start_time_ns");
  expect_invalid([](SyntheticConfig& c) { c.start_time_ns = 4'102'444'800'000'000'000; },
                 "start_time_ns");
  expect_invalid([](SyntheticConfig& c) { c.start_time_ns += 1; }, "start_time_ns");
}

TEST(SyntheticConfigValidation, AcceptsTheDefaults) {
  EXPECT_NO_THROW(validate(SyntheticConfig{}));
}

}  // namespace
}  // namespace radarpr
