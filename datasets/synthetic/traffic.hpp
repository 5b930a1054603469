#pragma once

#include <cstdint>

#include "datasets/synthetic/synthetic_world.hpp"
#include "datasets/synthetic/world_params.hpp"

namespace radarpr::synthetic {

// The vehicles driving along the streets at `time_s` (seconds since the session started):
// params.traffic of them per street stretch and direction on average, in the right-hand lane
// `lane_offset_m` off the centre line, cars, vans and buses at 5-12 m/s. Only those within
// `reach_m` of `centre`, and none within 8 m of it (that is the sensor's own car). Deterministic
// in (seed, session, time).
World moving_vehicles(std::uint64_t seed, int session, const CityLayout& layout,
                      const WorldParams& params, double lane_offset_m, double time_s, Vec2 centre,
                      double reach_m);

}  // namespace radarpr::synthetic
