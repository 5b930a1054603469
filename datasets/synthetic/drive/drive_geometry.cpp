#include "datasets/synthetic/drive/drive_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace radarpr::synthetic {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kUTurnRadius = 4.0;  // radius of the three arcs of the omega U-turn

}  // namespace

Pose2D PathPiece::at(double u) const {
  if (!arc) {
    return {start.x + u * std::cos(start.yaw), start.y + u * std::sin(start.yaw), start.yaw};
  }
  const double turn = sweep >= 0.0 ? 1.0 : -1.0;
  const double angle = start_angle + turn * u / radius;
  return {centre_x + radius * std::cos(angle), centre_y + radius * std::sin(angle),
          angle + turn * kPi / 2.0};
}

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

double lane_change_length(double shift) {
  const double a = std::acos(1.0 - std::abs(shift) / (2.0 * kLaneChangeRadius));
  return 2.0 * kLaneChangeRadius * std::sin(a);
}

LapPath::LapPath(std::vector<Lap> laps, LoopShape loop,
                 std::function<double(const Lap&)> lane_offset)
    : laps_(std::move(laps)), loop_(loop), lane_offset_(std::move(lane_offset)) {
  const Lap& first = laps_.front();
  const double lane = lane_offset_(first);
  pose_ = {loop_.pitch / 2.0, first.reverse ? lane : -lane, first.reverse ? kPi : 0.0};
}

double LapPath::add_lap() {
  const std::size_t before = pieces_.size();
  const Lap& current = laps_[next_lap_ % laps_.size()];
  double shift = 0.0;
  if (next_lap_ > 0) {
    const Lap& previous = laps_[(next_lap_ - 1) % laps_.size()];
    if (current.reverse != previous.reverse) {
      // The U-turn crosses to the other side: from one lane to the other, to the left.
      u_turn(0.5 * (lane_offset_(previous) + lane_offset_(current)));
    } else {
      shift = lane_offset_(current) - lane_offset_(previous);
    }
  }
  drive_lap(current.reverse, lane_offset_(current), shift);
  ++next_lap_;
  double length = 0.0;
  for (std::size_t i = before; i < pieces_.size(); ++i) length += pieces_[i].length;
  return length;
}

void LapPath::forward(double length) {
  add({false, pose_, 0, 0, 0, 0, 0, length});
}

void LapPath::turn(double radius, double angle) {
  const double side = angle >= 0.0 ? 1.0 : -1.0;  // centre on the left for left turns
  PathPiece piece{true, pose_, 0, 0, radius, 0, angle, radius * std::abs(angle)};
  piece.centre_x = pose_.x - side * radius * std::sin(pose_.yaw);
  piece.centre_y = pose_.y + side * radius * std::cos(pose_.yaw);
  piece.start_angle = pose_.yaw - side * kPi / 2.0;
  add(piece);
}

void LapPath::add(const PathPiece& piece) {
  pieces_.push_back(piece);
  pose_ = piece.at(piece.length);
}

// Counter-clockwise or (reverse) clockwise, `lane` metres right of the centre line; both begin
// and end at the middle of the first block's south street. A lap that starts `shift` metres
// right of where the car is changes lane on its first straight.
void LapPath::drive_lap(bool reverse, double lane, double shift) {
  const double half = loop_.pitch / 2.0;
  const double rc = loop_.corner_radius;
  const double side = reverse ? -1.0 : 1.0;
  const double radius = rc + side * lane;
  const double turn_angle = side * kPi / 2.0;
  const double x_edge = loop_.width - 2.0 * rc;
  const double y_edge = loop_.height - 2.0 * rc;
  double first = reverse ? half - rc : loop_.width - rc - half;
  if (std::abs(shift) > 1e-9) {
    // An S-bend: right then left (or the other way) on arcs of kLaneChangeRadius.
    const double a = std::acos(1.0 - std::abs(shift) / (2.0 * kLaneChangeRadius));
    const double sign = shift > 0.0 ? -1.0 : 1.0;
    turn(kLaneChangeRadius, sign * a);
    turn(kLaneChangeRadius, -sign * a);
    first -= lane_change_length(shift);
  }
  forward(first);
  turn(radius, turn_angle);
  forward(y_edge);
  turn(radius, turn_angle);
  forward(x_edge);
  turn(radius, turn_angle);
  forward(y_edge);
  turn(radius, turn_angle);
  forward(reverse ? loop_.width - rc - half : half - rc);
}

// Omega-shaped U-turn to the opposite lane 2 * lane to the left: right by a, left by pi + 2a,
// right by a, with cos(a) = (lane + r) / (2 r) so the lateral shift comes out exact.
void LapPath::u_turn(double lane) {
  const double r = std::max(kUTurnRadius, lane);
  const double a = std::acos((lane + r) / (2.0 * r));
  turn(r, -a);
  turn(r, kPi + 2.0 * a);
  turn(r, -a);
}

}  // namespace radarpr::synthetic
