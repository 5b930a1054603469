#pragma once

#include <cstdint>

#include "datasets/scan_sequence.hpp"
#include "datasets/synthetic/world/synthetic_world.hpp"
#include "datasets/synthetic/world/world_params.hpp"

namespace radarpr::synthetic {

// The vehicles driving along the streets at `time_s` (seconds since the session started):
// params.traffic of them per street stretch and direction on average, each in one of the lanes
// of its direction (right-hand traffic), cars, vans and buses at 5-12 m/s. Only those within
// `reach_m` of the sensor at `ego`, and none that would touch the sensor's own car there (a car
// of kCarLength along ego.yaw) or come within 0.3 m of it. Deterministic in (seed, session,
// time).
World moving_vehicles(std::uint64_t seed, int session, const CityLayout& layout,
                      const WorldParams& params, double time_s, const Pose2D& ego, double reach_m);

}  // namespace radarpr::synthetic
