#include "datasets/synthetic/drive_path.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "datasets/synthetic/random.hpp"

namespace radarpr::synthetic {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kUTurnRadius = 4.0;     // radius of the three arcs of the omega U-turn
constexpr double kSlowdownReach = 20.0;  // metres before/after a curve over which the car slows
constexpr double kCurveSpeedFactor = 0.75;
// Relative amplitudes of the two slow speed waves (traffic, driver).
constexpr double kSpeedWave1 = 0.08;
constexpr double kSpeedWave2 = 0.04;
enum Tag : std::uint64_t { kSessionTag = 11, kHeadingTag = 12 };

// A straight line or a circular arc of the driven path.
struct Piece {
  bool arc = false;
  Pose2D start;  // position and heading where the piece begins
  double centre_x = 0.0, centre_y = 0.0, radius = 0.0, start_angle = 0.0, sweep = 0.0;
  double length = 0.0;

  Pose2D at(double u) const {
    if (!arc) {
      return {start.x + u * std::cos(start.yaw), start.y + u * std::sin(start.yaw), start.yaw};
    }
    const double turn = sweep >= 0.0 ? 1.0 : -1.0;
    const double angle = start_angle + turn * u / radius;
    return {centre_x + radius * std::cos(angle), centre_y + radius * std::sin(angle),
            angle + turn * kPi / 2.0};
  }
};

// Builds a path piece by piece from a moving pose, like a turtle.
class Turtle {
 public:
  explicit Turtle(Pose2D pose) : pose_(pose) {}

  void forward(double length) { add({false, pose_, 0, 0, 0, 0, 0, length}); }
  // Turns by `angle` (> 0 left, < 0 right) on a circle of `radius`.
  void turn(double radius, double angle) {
    const double side = angle >= 0.0 ? 1.0 : -1.0;  // centre on the left for left turns
    Piece piece{true, pose_, 0, 0, radius, 0, angle, radius * std::abs(angle)};
    piece.centre_x = pose_.x - side * radius * std::sin(pose_.yaw);
    piece.centre_y = pose_.y + side * radius * std::cos(pose_.yaw);
    piece.start_angle = pose_.yaw - side * kPi / 2.0;
    add(piece);
  }
  const Pose2D& pose() const { return pose_; }
  std::vector<Piece>& pieces() { return pieces_; }

 private:
  void add(const Piece& piece) {
    pieces_.push_back(piece);
    pose_ = piece.at(piece.length);
  }
  Pose2D pose_;
  std::vector<Piece> pieces_;
};

struct Lap {
  bool reverse = false;
  int lane = 0;  // lanes right of the first
};

struct Loop {
  double width, height, pitch, corner_radius;
};

constexpr double kLaneChangeRadius = 25.0;

// Counter-clockwise in the outer lane, or clockwise in the inner one, `lane` metres right of
// the centre line; both begin and end at the middle of the first block's south street. A lap
// that starts `shift` metres right of where the car is changes lane on its first straight.
void drive_lap(Turtle& t, const Loop& loop, bool reverse, double lane, double shift) {
  const double half = loop.pitch / 2.0;
  const double rc = loop.corner_radius;
  const double side = reverse ? -1.0 : 1.0;
  const double radius = rc + side * lane;
  const double turn = side * kPi / 2.0;
  const double x_edge = loop.width - 2.0 * rc;
  const double y_edge = loop.height - 2.0 * rc;
  double first = reverse ? half - rc : loop.width - rc - half;
  if (std::abs(shift) > 1e-9) {
    // An S-bend: right then left (or the other way) on arcs of kLaneChangeRadius.
    const double a = std::acos(1.0 - std::abs(shift) / (2.0 * kLaneChangeRadius));
    const double sign = shift > 0.0 ? -1.0 : 1.0;
    t.turn(kLaneChangeRadius, sign * a);
    t.turn(kLaneChangeRadius, -sign * a);
    first -= 2.0 * kLaneChangeRadius * std::sin(a);
  }
  t.forward(first);
  t.turn(radius, turn);
  t.forward(y_edge);
  t.turn(radius, turn);
  t.forward(x_edge);
  t.turn(radius, turn);
  t.forward(y_edge);
  t.turn(radius, turn);
  t.forward(reverse ? loop.width - rc - half : half - rc);
}

// Omega-shaped U-turn to the opposite lane 2 * lane to the left: right by a, left by pi + 2a,
// right by a, with cos(a) = (lane + r) / (2 r) so the lateral shift comes out exact.
void u_turn(Turtle& t, double lane) {
  const double r = std::max(kUTurnRadius, lane);
  const double a = std::acos((lane + r) / (2.0 * r));
  t.turn(r, -a);
  t.turn(r, kPi + 2.0 * a);
  t.turn(r, -a);
}

double smoothstep(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

void require(bool condition, const char* field, double value, const std::string& expected) {
  if (!condition) {
    throw std::invalid_argument(
        fmt::format("synthetic drive: {} = {} is invalid, expected {}", field, value, expected));
  }
}

// Empty for a malformed pattern.
std::vector<Lap> parse_lap_pattern(const std::string& pattern) {
  std::vector<Lap> laps;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] != 'F' && pattern[i] != 'R') return {};
    Lap lap{pattern[i] == 'R', 0};
    if (i + 1 < pattern.size() && pattern[i + 1] >= '0' && pattern[i + 1] <= '2') {
      lap.lane = pattern[++i] - '0';
    }
    laps.push_back(lap);
  }
  return laps;
}

}  // namespace

void validate(const DriveParams& drive, double block_pitch_m) {
  require(drive.route_blocks_x >= 1, "route_blocks_x", drive.route_blocks_x, ">= 1");
  require(drive.route_blocks_y >= 1, "route_blocks_y", drive.route_blocks_y, ">= 1");
  if (parse_lap_pattern(drive.lap_pattern).empty()) {
    throw std::invalid_argument(fmt::format(
        "synthetic drive: lap_pattern = \"{}\" is invalid, expected a non-empty string of F "
        "(forward lap) and R (reverse lap), each optionally followed by a lane 0-2 (lanes "
        "further right), e.g. \"FFR\" or \"FF1RF2\"",
        drive.lap_pattern));
  }
  require(drive.lane >= 0 && drive.lane <= 2, "lane", drive.lane, "in [0, 2]");
  require(drive.lane_width_m >= 2.5 && drive.lane_width_m <= 4.5, "lane_width_m",
          drive.lane_width_m, "in [2.5, 4.5]");
  require(drive.speed_mps > 0.0 && std::isfinite(drive.speed_mps), "speed_mps", drive.speed_mps,
          "> 0");
  require(drive.scan_rate_hz > 0.0 && std::isfinite(drive.scan_rate_hz), "scan_rate_hz",
          drive.scan_rate_hz, "> 0");
  require(drive.session_offset_m >= 0.0 && std::isfinite(drive.session_offset_m),
          "session_offset_m", drive.session_offset_m, ">= 0");
  // Sessions shift the lane by up to 1.2 x session_offset_m either way; lanes further right
  // turn on tighter (reverse laps) corners.
  int max_lane = 0;
  for (const Lap& lap : parse_lap_pattern(drive.lap_pattern))
    max_lane = std::max(max_lane, lap.lane);
  const double widest_lane = drive.lane_offset_m + 1.2 * drive.session_offset_m +
                             drive.lane_width_m * (max_lane + drive.lane);
  require(drive.lane_offset_m - 1.2 * drive.session_offset_m > 0.0, "lane_offset_m",
          drive.lane_offset_m, "> 1.2 x session_offset_m (lanes stay right of the centre line)");
  require(drive.corner_radius_m > widest_lane && drive.corner_radius_m <= block_pitch_m / 2.0,
          "corner_radius_m", drive.corner_radius_m,
          fmt::format("in ({}, {}] (wider than the widest lane offset, at most half a block)",
                      widest_lane, block_pitch_m / 2.0));
  const double widest_shift = 2.0 * drive.lane_width_m;
  const double lane_change =
      2.0 * kLaneChangeRadius * std::sin(std::acos(1.0 - widest_shift / (2.0 * kLaneChangeRadius)));
  require(block_pitch_m / 2.0 - drive.corner_radius_m >= lane_change, "block_pitch_m",
          block_pitch_m,
          fmt::format(">= 2 x (corner_radius_m + {:.1f}) (room to change lanes)", lane_change));
  require(drive.heading_jitter_deg >= 0.0 && std::isfinite(drive.heading_jitter_deg),
          "heading_jitter_deg", drive.heading_jitter_deg, ">= 0");
}

std::vector<Pose2D> plan_drive(const DriveParams& drive, double block_pitch_m, std::uint64_t seed,
                               int session, int scan_count) {
  validate(drive, block_pitch_m);
  if (scan_count < 0) throw std::invalid_argument("synthetic drive: negative scan count");

  Rng session_rng(hash_key({seed, kSessionTag, static_cast<std::uint64_t>(session)}));
  const double offset = session == 0 ? 0.0
                                     : drive.session_offset_m * (session % 2 == 1 ? 1.0 : -1.0) *
                                           session_rng.uniform(0.8, 1.2);
  const Loop loop{drive.route_blocks_x * block_pitch_m, drive.route_blocks_y * block_pitch_m,
                  block_pitch_m, drive.corner_radius_m};
  const double phase1 = session_rng.uniform(0.0, 2.0 * kPi);
  const double phase2 = session_rng.uniform(0.0, 2.0 * kPi);
  const std::vector<Lap> laps = parse_lap_pattern(drive.lap_pattern);
  auto lane_of = [&](const Lap& lap) {
    return drive.lane_offset_m + offset + drive.lane_width_m * (lap.lane + drive.lane);
  };

  // Lay out laps until the path is long enough for every scan at the fastest speed.
  const double nominal_spacing = drive.speed_mps / drive.scan_rate_hz;
  const double needed = (scan_count + 1) * nominal_spacing * (1.0 + kSpeedWave1 + kSpeedWave2);
  const Lap& first = laps.front();
  Turtle turtle({loop.pitch / 2.0, first.reverse ? lane_of(first) : -lane_of(first),
                 first.reverse ? kPi : 0.0});
  double length = 0.0;
  for (std::size_t lap = 0; length < needed; ++lap) {
    const Lap& current = laps[lap % laps.size()];
    const std::size_t before = turtle.pieces().size();
    double shift = 0.0;
    if (lap > 0) {
      const Lap& previous = laps[(lap - 1) % laps.size()];
      if (current.reverse != previous.reverse) {
        // The U-turn crosses to the other side: from one lane to the other, to the left.
        u_turn(turtle, 0.5 * (lane_of(previous) + lane_of(current)));
      } else {
        shift = lane_of(current) - lane_of(previous);
      }
    }
    drive_lap(turtle, loop, current.reverse, lane_of(current), shift);
    for (std::size_t i = before; i < turtle.pieces().size(); ++i)
      length += turtle.pieces()[i].length;
  }
  const std::vector<Piece>& pieces = turtle.pieces();

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
    const Piece& p = pieces[piece];
    Pose2D pose = p.at(std::min(s - begin[piece], p.length));
    Rng heading_rng(hash_key(
        {seed, kHeadingTag, static_cast<std::uint64_t>(session), static_cast<std::uint64_t>(k)}));
    pose.yaw += heading_rng.normal(0.0, drive.heading_jitter_deg * kPi / 180.0);
    pose.yaw = std::remainder(pose.yaw, 2.0 * kPi);
    pose.x += drive.route_origin_block_x * block_pitch_m;
    pose.y += drive.route_origin_block_y * block_pitch_m;
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
