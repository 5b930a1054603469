// validate(DriveParams): the drive's parameters, its length, and whether its laps fit the
// world's streets.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <fmt/format.h>

#include "datasets/synthetic/drive/drive_geometry.hpp"
#include "datasets/synthetic/drive/drive_path.hpp"
#include "datasets/synthetic/require.hpp"

namespace radarpr::synthetic {
namespace {

constexpr std::string_view kSubject = "synthetic drive";
constexpr double kMinTurnRadiusM = 4.0;  // tighter than any car turns
constexpr double kMaxLaps = 1e4;
constexpr int kMaxRouteBlocks = 50;
constexpr double kSampleStepM = 0.5;

// Distance from (u, v) to the quadrant {u' >= a, v' >= b}; minus the depth when inside.
double quadrant_distance(double u, double v, double a, double b) {
  if (u >= a && v >= b) return -std::min(u - a, v - b);
  return std::hypot(std::max(0.0, a - u), std::max(0.0, b - v));
}

// How far (x, y) is from the nearest place a car must not be: a parking lane, a kerb or what
// lies beyond it (negative inside). Around a crossing, in each quadrant: the kerbs' corner and
// the two parking lanes that begin a little way along its streets. The grid repeats, so the
// nearest crossing is enough.
double room_at(double x, double y, const CityLayout& layout) {
  const double pitch = layout.block_pitch_m;
  const double u = x - std::round(x / pitch) * pitch;
  const double v = y - std::round(y / pitch) * pitch;
  const double lanes = layout.street.carriageway_half_m();
  const double kerb = layout.street.kerb_offset_m();
  const double parking = layout.street.clear_of_crossing_m();
  double room = std::numeric_limits<double>::infinity();
  for (const double su : {-1.0, 1.0}) {
    for (const double sv : {-1.0, 1.0}) {
      const double a = su * u;
      const double b = sv * v;
      room = std::min({room, quadrant_distance(a, b, kerb, kerb),
                       quadrant_distance(a, b, parking, lanes),
                       quadrant_distance(a, b, lanes, parking)});
    }
  }
  return room;
}

struct Tightest {
  double room = std::numeric_limits<double>::infinity();
  double x = 0.0, y = 0.0;
};

// The tightest place of two rounds of the pattern (every lap change, the last to the first
// included) with the session offset `offset`.
Tightest tightest_place(const std::vector<Lap>& laps, const LoopShape& loop,
                        const CityLayout& layout, const DriveParams& drive, double offset) {
  LapPath path(laps, loop, [&](const Lap& lap) {
    return layout.street.lane_centre_m(lap.lane + drive.lane) + offset;
  });
  for (std::size_t lap = 0; lap <= 2 * laps.size(); ++lap) path.add_lap();
  Tightest tightest;
  for (const PathPiece& piece : path.pieces()) {
    const int samples = static_cast<int>(std::ceil(piece.length / kSampleStepM));
    for (int k = 0; k <= samples; ++k) {
      const Pose2D at = piece.at(piece.length * k / std::max(1, samples));
      const double room = room_at(at.x, at.y, layout);
      if (room < tightest.room) tightest = {room, at.x, at.y};
    }
  }
  return tightest;
}

std::string world_name(std::string_view world) {
  return world.empty() ? std::string("the world's") : fmt::format("the {} world's", world);
}

void validate_fit(const DriveParams& drive, const std::vector<Lap>& laps, const CityLayout& layout,
                  std::string_view world) {
  const StreetProfile& street = layout.street;
  int widest = 0;
  int widest_reverse = -1;  // none
  for (const Lap& lap : laps) {
    widest = std::max(widest, lap.lane + drive.lane);
    if (lap.reverse) widest_reverse = std::max(widest_reverse, lap.lane + drive.lane);
  }
  const double sway = 1.2 * drive.session_offset_m;
  const std::string streets = fmt::format(
      "{} streets ({} lane(s) of {} m each way: the parking line {} m and the kerb {} m from the "
      "centre line)",
      world_name(world), street.lanes_per_direction, street.lane_width_m,
      street.carriageway_half_m(), street.kerb_offset_m());
  // On the straights: the widest lane, the session's sway and half a car inside the lanes.
  const double outer = street.lane_centre_m(widest) + sway + kVehicleHalfWidthM;
  if (outer > street.carriageway_half_m()) {
    throw std::invalid_argument(fmt::format(
        "{}: lane = {} with lap_pattern = \"{}\" asks for lane {}, which does not fit {}: its "
        "centre {} m + {:.2f} m of session offset + {} m of half a car reach {:.2f} m from the "
        "centre line; use fewer lanes, or a world with wider streets (riverside has three lanes "
        "each way)",
        kSubject, drive.lane, drive.lap_pattern, widest, streets, street.lane_centre_m(widest),
        sway, kVehicleHalfWidthM, outer));
  }
  // Sessions sway about the lane centre; the car stays on its side of the centre line.
  require(street.lane_centre_m(0) - sway > 0.0, kSubject, "session_offset_m",
          drive.session_offset_m,
          fmt::format("below {:.2f} m so that a car in the inner lane keeps right of the centre "
                      "line",
                      street.lane_centre_m(0) / 1.2));
  // Reverse laps turn right, inside the corner: the widest of them turns tightest.
  const double inside = widest_reverse < 0 ? 0.0 : street.lane_centre_m(widest_reverse) + sway;
  const double min_radius = inside + kMinTurnRadiusM;
  require(drive.corner_radius_m >= min_radius && drive.corner_radius_m <= layout.block_pitch_m / 2,
          kSubject, "corner_radius_m", drive.corner_radius_m,
          fmt::format("in [{:.2f}, {}] (reverse laps turn {:.2f} m inside it and no car turns on "
                      "less than {} m; at most half a block)",
                      min_radius, layout.block_pitch_m / 2, inside, kMinTurnRadiusM));
  // Everywhere else (corners, lane changes, U-turns): measured along the path.
  const double pitch = layout.block_pitch_m;
  const LoopShape loop{drive.route_blocks_x * pitch, drive.route_blocks_y * pitch, pitch,
                       drive.corner_radius_m};
  for (const double offset : {-sway, sway}) {
    const Tightest tightest = tightest_place(laps, loop, layout, drive, offset);
    if (tightest.room >= kVehicleHalfWidthM) continue;
    throw std::invalid_argument(fmt::format(
        "{}: lane = {} with lap_pattern = \"{}\" does not fit {}: at ({:.1f}, {:.1f}) on the "
        "loop (a corner or a U-turn; {:+.2f} m of session offset) the car's centre comes within "
        "{:.2f} m of a parking lane or a kerb, less than the {} m of half a car; a U-turn "
        "reaches 4 m into the other side of the road: drive laps in one direction, pick another "
        "corner_radius_m, or a world with wider streets",
        kSubject, drive.lane, drive.lap_pattern, streets, tightest.x, tightest.y, offset,
        tightest.room, kVehicleHalfWidthM));
  }
}

}  // namespace

void validate(const DriveParams& drive, const CityLayout& layout, int scan_count,
              std::string_view world) {
  validate(layout);
  require(drive.route_blocks_x >= 1 && drive.route_blocks_x <= kMaxRouteBlocks, kSubject,
          "route_blocks_x", drive.route_blocks_x, fmt::format("in [1, {}]", kMaxRouteBlocks));
  require(drive.route_blocks_y >= 1 && drive.route_blocks_y <= kMaxRouteBlocks, kSubject,
          "route_blocks_y", drive.route_blocks_y, fmt::format("in [1, {}]", kMaxRouteBlocks));
  require(std::abs(drive.route_origin_block_x) <= 100'000, kSubject, "route_origin_block_x",
          drive.route_origin_block_x, "in [-100000, 100000]");
  require(std::abs(drive.route_origin_block_y) <= 100'000, kSubject, "route_origin_block_y",
          drive.route_origin_block_y, "in [-100000, 100000]");
  const std::vector<Lap> laps = parse_lap_pattern(drive.lap_pattern);
  if (laps.empty()) {
    throw std::invalid_argument(fmt::format(
        "{}: lap_pattern = \"{}\" is invalid, expected a non-empty string of F (forward lap) and "
        "R (reverse lap), each optionally followed by a lane 0-2 (lanes further right), e.g. "
        "\"FFR\" or \"FF1RF2\"",
        kSubject, drive.lap_pattern));
  }
  require(laps.size() <= 100, kSubject, "lap_pattern laps", static_cast<double>(laps.size()),
          "at most 100 (the pattern repeats)");
  require(drive.lane >= 0 && drive.lane <= 2, kSubject, "lane", drive.lane, "in [0, 2]");
  require(drive.speed_mps > 0.0 && drive.speed_mps <= 100.0, kSubject, "speed_mps", drive.speed_mps,
          "in (0, 100]");
  // Real Navtech scans are stamped in whole microseconds, and so are the cache's file names.
  const double period_us = 1e6 / drive.scan_rate_hz;
  require(std::isfinite(period_us) && period_us >= 1000.0 && period_us <= 1e7 &&
              std::abs(period_us - std::round(period_us)) <= 1e-6,
          kSubject, "scan_rate_hz", drive.scan_rate_hz,
          "a rate whose period is a whole number of microseconds between 1 ms and 10 s (4 Hz: "
          "250000 us)");
  require(drive.session_offset_m >= 0.0 && drive.session_offset_m <= 2.0, kSubject,
          "session_offset_m", drive.session_offset_m, "in [0, 2]");
  require(drive.heading_jitter_deg >= 0.0 && drive.heading_jitter_deg <= 10.0, kSubject,
          "heading_jitter_deg", drive.heading_jitter_deg, "in [0, 10]");
  require(std::isfinite(drive.corner_radius_m), kSubject, "corner_radius_m", drive.corner_radius_m,
          "a finite number");
  validate_fit(drive, laps, layout, world);
  const double room = layout.block_pitch_m / 2.0 - drive.corner_radius_m;
  const double lane_change = lane_change_length(2.0 * layout.street.lane_width_m);
  require(room >= lane_change, kSubject, "corner_radius_m", drive.corner_radius_m,
          fmt::format("at most {:.1f} (half a block minus {:.1f} m to change lanes)",
                      layout.block_pitch_m / 2.0 - lane_change, lane_change));
  // The path is laid out lap by lap: refuse drives that would take forever to lay out.
  require(scan_count >= 0, kSubject, "scan_count", scan_count, ">= 0");
  const double pitch = layout.block_pitch_m;
  LapPath one_lap(
      laps,
      {drive.route_blocks_x * pitch, drive.route_blocks_y * pitch, pitch, drive.corner_radius_m},
      [&](const Lap& lap) { return layout.street.lane_centre_m(lap.lane); });
  const double lap_length = one_lap.add_lap();
  const double drive_length = (scan_count + 1.0) * drive.speed_mps / drive.scan_rate_hz * 1.12;
  require(
      drive_length / lap_length <= kMaxLaps, kSubject, "speed_mps", drive.speed_mps,
      fmt::format("low enough that {} scans need at most {} laps of {:.0f} m (they need {:.0f})",
                  scan_count, kMaxLaps, lap_length, drive_length / lap_length));
}

}  // namespace radarpr::synthetic
