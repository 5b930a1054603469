#pragma once

#include <string>
#include <string_view>

namespace radarpr::synthetic {

// The cross-section of every street of a world, from the centre line out (the same on both
// sides): `lanes_per_direction` lanes of `lane_width_m`, then a parking lane of
// `parking_width_m` (0: none) beyond the parking line, the kerb, and a pavement (or verge) of
// `pavement_width_m` that holds the street furniture, up to the block lots.
struct StreetProfile {
  int lanes_per_direction = 2;
  double lane_width_m = 3.5;
  double parking_width_m = 2.5;
  double pavement_width_m = 3.5;

  // Centre line to the centre of lane `lane` (0 = the inner lane).
  double lane_centre_m(int lane) const { return (lane + 0.5) * lane_width_m; }
  // Centre line to the outer edge of the lanes: the parking line.
  double carriageway_half_m() const { return lanes_per_direction * lane_width_m; }
  // Centre line to the kerb (the outer edge of the parking lane).
  double kerb_offset_m() const { return carriageway_half_m() + parking_width_m; }
  // Centre line to the block lots (the outer edge of the pavement).
  double half_width_m() const { return kerb_offset_m() + pavement_width_m; }
  // A crossing's centre to where its streets' parking lanes and furniture may begin.
  double clear_of_crossing_m() const { return half_width_m() + 1.5; }
};

// An endless Manhattan grid: street centre lines at x = i*pitch and y = j*pitch, blocks between
// them. Each block and each street stretch is generated from (seed, its grid index) alone, so
// any region of the same world is identical whatever else was generated.
struct CityLayout {
  double block_pitch_m = 80.0;  // distance between parallel street centre lines
  StreetProfile street;
  double park_fraction = 0.2;  // share of city blocks that are parks (trees, fences, open space)

  double street_width_m() const { return 2.0 * street.half_width_m(); }
};

// Throws std::invalid_argument naming the first bad field.
void validate(const CityLayout& layout);

// What fills the blocks of the street grid.
enum class WorldKind {
  city,       // urban blocks: buildings, walls, car parks, parks, parked cars, poles
  suburban,   // detached houses in gardens, hedges, fences, street trees, driveway cars
  campus,     // large buildings in lawns with trees, lamp-lined paths, car parks
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
void validate(const WorldParams& params, const CityLayout& layout);

}  // namespace radarpr::synthetic
