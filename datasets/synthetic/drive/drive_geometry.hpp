#pragma once

#include <functional>
#include <string>
#include <vector>

#include "datasets/scan_sequence.hpp"

namespace radarpr::synthetic {

// Drive internals: the ideal path of the laps, before speed and noise (drive_path.hpp).

// A straight line or a circular arc of the driven path.
struct PathPiece {
  bool arc = false;
  Pose2D start;  // position and heading where the piece begins
  double centre_x = 0.0, centre_y = 0.0, radius = 0.0, start_angle = 0.0, sweep = 0.0;
  double length = 0.0;

  // The pose `u` metres into the piece.
  Pose2D at(double u) const;
};

struct Lap {
  bool reverse = false;
  int lane = 0;  // lanes right of the first
};

// "FF1R" -> laps; empty for a malformed pattern.
std::vector<Lap> parse_lap_pattern(const std::string& pattern);

// The loop the laps go round: its size and the street grid's pitch, in metres, and the radius of
// the street centre line at its corners.
struct LoopShape {
  double width = 0.0, height = 0.0, pitch = 0.0, corner_radius = 0.0;
};

// Lays out the laps of a pattern one after the other, from the middle of the loop's first
// (south) street: forward laps counter-clockwise, reverse laps clockwise, each `lane_offset(lap)`
// metres right of the street centre line; an omega-shaped U-turn between laps of opposite
// direction, an S-bend on the first straight between laps in different lanes.
class LapPath {
 public:
  LapPath(std::vector<Lap> laps, LoopShape loop, std::function<double(const Lap&)> lane_offset);

  // Appends the next lap of the pattern (repeated) and what leads into it; returns the length
  // added.
  double add_lap();
  const std::vector<PathPiece>& pieces() const { return pieces_; }

 private:
  void forward(double length);
  // Turns by `angle` (> 0 left, < 0 right) on a circle of `radius`.
  void turn(double radius, double angle);
  void drive_lap(bool reverse, double lane, double shift);
  void u_turn(double lane);
  void add(const PathPiece& piece);

  std::vector<Lap> laps_;
  LoopShape loop_;
  std::function<double(const Lap&)> lane_offset_;
  std::size_t next_lap_ = 0;
  Pose2D pose_;
  std::vector<PathPiece> pieces_;
};

// Radius of the arcs of the S-bend that changes lanes, and the distance along the road it
// takes to move `shift` metres across.
inline constexpr double kLaneChangeRadius = 25.0;
double lane_change_length(double shift);

}  // namespace radarpr::synthetic
