#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "datasets/scan_sequence.hpp"
#include "datasets/synthetic/world/world_params.hpp"

namespace radarpr::synthetic {

// How the simulated car drives: laps of a rectangular loop of city blocks along the street
// centre lines x = 0 .. route_blocks_x * pitch, y = 0 .. route_blocks_y * pitch (shifted by the
// route origin), starting in the middle of the first block's south street. Right-hand traffic
// in the lanes of the world's streets (StreetProfile): lane 0 is the inner lane, lane n the
// n-th further right. A forward lap runs counter-clockwise, a reverse lap clockwise on the other
// side of the road, so reverse revisits in lane 0 are one lane width apart. Between laps of
// opposite direction the car turns around in an omega-shaped U-turn; between laps in different
// lanes it changes lane on the first straight.
struct DriveParams {
  int route_blocks_x = 2;
  int route_blocks_y = 1;
  // The loop's south-west crossing, in blocks: drives with different origins share only the
  // streets where their loops overlap (multi-session runs with places the database never saw).
  int route_origin_block_x = 0;
  int route_origin_block_y = 0;
  // Repeated: F = forward lap, R = reverse lap, each optionally followed by a lane 0-2 (that
  // many lanes further right: lateral-offset revisits), e.g. "FF1R".
  std::string lap_pattern = "FFR";
  int lane = 0;            // every lap this many lanes further right (another session)
  double speed_mps = 9.6;  // nominal; 2.4 m between scans at 4 Hz
  double scan_rate_hz = 4.0;
  double corner_radius_m = 9.0;     // street centre line radius at crossings
  double session_offset_m = 0.6;    // sessions >= 1 drive about this far off the lane centre
  double heading_jitter_deg = 0.5;  // std dev of the per-scan yaw noise
};

// Half the width of the simulated car (and of the vehicles around it), mirrors included.
inline constexpr double kVehicleHalfWidthM = 0.95;

// Throws std::invalid_argument naming the first bad field: among others when `scan_count`
// scans would need more than 10^4 laps, and when a lap of the pattern in its lane (plus the
// largest session offset and half a vehicle) would leave the lanes of `layout`'s streets for
// the parking lane or the kerb, on a straight, at a corner or in a U-turn. `world` names the
// world in that message ("city"; empty when unknown).
void validate(const DriveParams& drive, const CityLayout& layout, int scan_count,
              std::string_view world);

// Poses of `scan_count` scans, 1/scan_rate_hz apart. Deterministic in (seed, session): session
// changes the lateral lane offset, the speed profile and the heading noise. Spacing stays within
// [0.66, 1.12] x speed / rate (slower at corners and U-turns).
std::vector<Pose2D> plan_drive(const DriveParams& drive, const CityLayout& layout,
                               std::uint64_t seed, int session, int scan_count);

}  // namespace radarpr::synthetic
