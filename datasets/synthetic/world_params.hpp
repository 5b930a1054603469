#pragma once

#include <string>
#include <string_view>

namespace radarpr::synthetic {

// An endless Manhattan grid: street centre lines at x = i*pitch and y = j*pitch, blocks between
// them. Each block and each street stretch is generated from (seed, its grid index) alone, so
// any region of the same world is identical whatever else was generated.
struct CityLayout {
  double block_pitch_m = 80.0;   // distance between parallel street centre lines
  double street_width_m = 18.0;  // road + pavements; building lots start at +-width/2
  double park_fraction = 0.2;    // share of city blocks that are parks (trees, fences, open space)
};

// Throws std::invalid_argument naming the first bad field.
void validate(const CityLayout& layout);

// What fills the blocks of the street grid.
enum class WorldKind {
  city,       // urban blocks: buildings, walls, car parks, parks, parked cars, poles
  suburban,   // detached houses in gardens, hedges, fences, street trees, driveway cars
  campus,     // few large buildings in open lawns with many trees, lamp-lined paths
  riverside,  // a river through every block of row 0, crossed by identical bridges; repetitive
              // slab blocks and tree-lined promenades (MulRan Riverside's perceptual aliasing)
  offroad,    // tracks through open terrain: sparse rocks, bushes, ridges, the odd hut (OORD)
};

std::string_view to_string(WorldKind kind);
// Throws std::invalid_argument listing the known names.
WorldKind world_kind_from(std::string_view name);

// The world's contents beyond its layout, and what changes between sessions of the same seed.
struct WorldParams {
  WorldKind kind = WorldKind::city;
  double parked_cars = 0.55;      // share of parking places taken
  double parked_car_churn = 0.0;  // share of places redrawn in each session (0: same cars)
  double foliage = 1.0;           // crown size factor: 1 in leaf, ~0.6 bare (another season)
  double traffic = 0.0;           // moving vehicles per street stretch and direction
  double river_width_m = 40.0;    // riverside only
};

// Throws std::invalid_argument naming the first bad field.
void validate(const WorldParams& params, double block_pitch_m, double street_width_m);

}  // namespace radarpr::synthetic
