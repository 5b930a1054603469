#pragma once

#include <cstdint>

#include "datasets/synthetic/world/synthetic_world.hpp"
#include "datasets/synthetic/world/world_params.hpp"

namespace radarpr::synthetic {

// Every reflector of the blocks and streets that intersect [min, max] (world metres) of the
// world of `seed` as session `session` finds it (parked cars, foliage). Deterministic.
World generate_world(std::uint64_t seed, int session, const CityLayout& layout,
                     const WorldParams& params, Vec2 min, Vec2 max);

}  // namespace radarpr::synthetic
