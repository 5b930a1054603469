#pragma once

#include "datasets/synthetic/world/synthetic_world.hpp"
#include "datasets/synthetic/world/world_parts.hpp"

namespace radarpr::synthetic {

// What each world kind puts in a block (bx, by) and along a street stretch. Each is a function
// of (seed, the grid index) and the session's changes only: a street's filler draws from `rng`,
// the stretch's own stream (world_generator.cpp).

void city_block(World& world, const GenerationContext& ctx, long long bx, long long by);
void city_street(World& world, const GenerationContext& ctx, const StreetStretch& street, Rng& rng);
// Traffic lights at half the crossings (city, suburban, campus).
void crossing_lights(World& world, const GenerationContext& ctx, long long i, long long j);

void suburban_block(World& world, const GenerationContext& ctx, long long bx, long long by);
void suburban_street(World& world, const GenerationContext& ctx, const StreetStretch& street,
                     Rng& rng);

void campus_block(World& world, const GenerationContext& ctx, long long bx, long long by);
void campus_street(World& world, const GenerationContext& ctx, const StreetStretch& street,
                   Rng& rng);

// The river runs along block row 0 (y = pitch / 2); every vertical street crosses it on a
// bridge of the same structure.
void riverside_block(World& world, const GenerationContext& ctx, long long bx, long long by);
void riverside_street(World& world, const GenerationContext& ctx, const StreetStretch& street,
                      Rng& rng);

void offroad_block(World& world, const GenerationContext& ctx, long long bx, long long by);
void offroad_street(World& world, const GenerationContext& ctx, const StreetStretch& street,
                    Rng& rng);

}  // namespace radarpr::synthetic
