#pragma once

#include <cstdint>

#include "datasets/synthetic/synthetic_world.hpp"

namespace radarpr::synthetic {

// An endless Manhattan grid: street centre lines at x = i*pitch and y = j*pitch, city blocks
// between them. Each block and each street stretch is generated from (seed, its grid index)
// alone, so any region of the same city is identical whatever else was generated.
struct CityLayout {
  double block_pitch_m = 80.0;   // distance between parallel street centre lines
  double street_width_m = 18.0;  // road + pavements; building lots start at +-width/2
  double park_fraction = 0.2;    // share of blocks that are parks (trees, fences, open space)
};

// Throws std::invalid_argument naming the first bad field.
void validate(const CityLayout& layout);

// Every reflector of the blocks and streets that intersect [min, max] (world metres).
World generate_city(std::uint64_t seed, const CityLayout& layout, Vec2 min, Vec2 max);

}  // namespace radarpr::synthetic
