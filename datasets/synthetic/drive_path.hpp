#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "datasets/scan_sequence.hpp"

namespace radarpr::synthetic {

// How the simulated car drives: laps of a rectangular loop of city blocks along the street
// centre lines x = 0 .. route_blocks_x * pitch, y = 0 .. route_blocks_y * pitch (shifted by the
// route origin), starting in
// the middle of the first block's south street. Right-hand traffic: a forward lap
// (counter-clockwise) runs in the outer lane, a reverse lap (clockwise) in the inner one, so
// reverse revisits are 2 * lane_offset apart. Between laps of opposite direction the car turns
// around in an omega-shaped U-turn.
struct DriveParams {
  int route_blocks_x = 2;
  int route_blocks_y = 1;
  // The loop's south-west crossing, in blocks: drives with different origins share only the
  // streets where their loops overlap (multi-session runs with places the database never saw).
  int route_origin_block_x = 0;
  int route_origin_block_y = 0;
  // Repeated: F = forward lap, R = reverse lap, each optionally followed by a lane 0-2 (that
  // many lanes of lane_width_m further right: lateral-offset revisits), e.g. "FF1R".
  std::string lap_pattern = "FFR";
  int lane = 0;  // every lap this many lanes further right (another session)
  double lane_width_m = 3.5;
  double speed_mps = 9.6;  // nominal; 2.4 m between scans at 4 Hz
  double scan_rate_hz = 4.0;
  double lane_offset_m = 2.0;       // lane centre to street centre line
  double corner_radius_m = 9.0;     // street centre line radius at crossings
  double session_offset_m = 1.0;    // sessions >= 1 drive about this far off the lane centre
  double heading_jitter_deg = 0.5;  // std dev of the per-scan yaw noise
};

// Throws std::invalid_argument naming the first bad field.
void validate(const DriveParams& drive, double block_pitch_m);

// Poses of `scan_count` scans, 1/scan_rate_hz apart. Deterministic in (seed, session): session
// changes the lateral lane offset, the speed profile and the heading noise. Spacing stays within
// [0.66, 1.12] x speed / rate (slower at corners and U-turns).
std::vector<Pose2D> plan_drive(const DriveParams& drive, double block_pitch_m, std::uint64_t seed,
                               int session, int scan_count);

}  // namespace radarpr::synthetic
