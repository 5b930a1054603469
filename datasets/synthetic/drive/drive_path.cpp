#include "datasets/synthetic/drive/drive_path.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "datasets/synthetic/drive/drive_geometry.hpp"
#include "datasets/synthetic/random.hpp"

namespace radarpr::synthetic {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kSlowdownReach = 20.0;  // metres before/after a curve over which the car slows
constexpr double kCurveSpeedFactor = 0.75;
// Relative amplitudes of the two slow speed waves (traffic, driver).
constexpr double kSpeedWave1 = 0.08;
constexpr double kSpeedWave2 = 0.04;
enum Tag : std::uint64_t { kSessionTag = 11, kHeadingTag = 12 };

double smoothstep(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

}  // namespace

std::vector<Pose2D> plan_drive(const DriveParams& drive, const CityLayout& layout,
                               std::uint64_t seed, int session, int scan_count) {
  validate(drive, layout, scan_count, "");

  Rng session_rng(hash_key({seed, kSessionTag, static_cast<std::uint64_t>(session)}));
  // Sessions drive off the lane centre, alternately right and left of it.
  const double offset = session == 0 ? 0.0
                                     : drive.session_offset_m * (session % 2 == 1 ? 1.0 : -1.0) *
                                           session_rng.uniform(0.8, 1.2);
  const double phase1 = session_rng.uniform(0.0, 2.0 * kPi);
  const double phase2 = session_rng.uniform(0.0, 2.0 * kPi);
  const double pitch = layout.block_pitch_m;
  LapPath path(
      parse_lap_pattern(drive.lap_pattern),
      {drive.route_blocks_x * pitch, drive.route_blocks_y * pitch, pitch, drive.corner_radius_m},
      [&](const Lap& lap) { return layout.street.lane_centre_m(lap.lane + drive.lane) + offset; });

  // Lay out laps until the path is long enough for every scan at the fastest speed.
  const double nominal_spacing = drive.speed_mps / drive.scan_rate_hz;
  const double needed = (scan_count + 1) * nominal_spacing * (1.0 + kSpeedWave1 + kSpeedWave2);
  for (double length = 0.0; length < needed;) length += path.add_lap();
  const std::vector<PathPiece>& pieces = path.pieces();

  // Arc-length bookkeeping: where each piece starts and the nearest curve on either side.
  const std::size_t n = pieces.size();
  std::vector<double> begin(n + 1, 0.0);
  for (std::size_t i = 0; i < n; ++i) begin[i + 1] = begin[i] + pieces[i].length;
  constexpr double kFar = std::numeric_limits<double>::infinity();
  std::vector<double> previous_curve_end(n, -kFar);
  std::vector<double> next_curve_begin(n, kFar);
  for (std::size_t i = 1; i < n; ++i) {
    previous_curve_end[i] = pieces[i - 1].arc ? begin[i] : previous_curve_end[i - 1];
  }
  for (std::size_t i = n - 1; i-- > 0;) {
    next_curve_begin[i] = pieces[i + 1].arc ? begin[i + 1] : next_curve_begin[i + 1];
  }

  std::vector<Pose2D> poses;
  poses.reserve(static_cast<std::size_t>(scan_count));
  std::size_t piece = 0;
  double s = 0.0;
  for (int k = 0; k < scan_count; ++k) {
    while (piece + 1 < n && s >= begin[piece + 1]) ++piece;
    const PathPiece& p = pieces[piece];
    Pose2D pose = p.at(std::min(s - begin[piece], p.length));
    Rng heading_rng(hash_key(
        {seed, kHeadingTag, static_cast<std::uint64_t>(session), static_cast<std::uint64_t>(k)}));
    pose.yaw += heading_rng.normal(0.0, drive.heading_jitter_deg * kPi / 180.0);
    pose.yaw = std::remainder(pose.yaw, 2.0 * kPi);
    pose.x += drive.route_origin_block_x * pitch;
    pose.y += drive.route_origin_block_y * pitch;
    poses.push_back(pose);

    // Next scan: slower near curves (corners, U-turns), slow waves elsewhere.
    const double to_curve =
        p.arc ? 0.0 : std::min(s - previous_curve_end[piece], next_curve_begin[piece] - s);
    const double slowdown =
        kCurveSpeedFactor + (1.0 - kCurveSpeedFactor) * smoothstep(to_curve / kSlowdownReach);
    const double wave = 1.0 + kSpeedWave1 * std::sin(2.0 * kPi * s / 173.0 + phase1) +
                        kSpeedWave2 * std::sin(2.0 * kPi * s / 61.0 + phase2);
    s += nominal_spacing * slowdown * wave;
  }
  return poses;
}

}  // namespace radarpr::synthetic
