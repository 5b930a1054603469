#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "datasets/synthetic/random.hpp"
#include "datasets/synthetic/world/synthetic_world.hpp"
#include "datasets/synthetic/world/world_params.hpp"

namespace radarpr::synthetic {

// The building parts every world kind is made of, and the session-dependent draws.

struct Rect {
  double x0, y0, x1, y1;
  double width() const { return x1 - x0; }
  double height() const { return y1 - y0; }
};

// What one generation call knows: the world seed (the layout), the session (what changes between
// drives) and the world's parameters.
struct GenerationContext {
  std::uint64_t seed = 0;
  int session = 0;
  CityLayout layout;
  WorldParams params;

  // Whether parking place `place_key` holds a car in this session: the world seed's draw, redrawn
  // per session for a `parked_car_churn` share of places.
  bool parked(std::uint64_t place_key) const;
};

inline std::uint64_t key_of(long long index) {
  return static_cast<std::uint64_t>(index);
}

// The lot of block (bx, by): the square between its four streets' pavements.
Rect block_lot(const GenerationContext& ctx, long long bx, long long by);
// The square the kerbs of block (bx, by) enclose: the lot and its pavements.
Rect kerb_square(const GenerationContext& ctx, long long bx, long long by);

// The stretch of street between two crossings: along the x axis (vertical = false) on the line
// y = j * pitch from x = i * pitch, or along y on x = i * pitch from y = j * pitch. Lateral
// offsets are from the centre line, positive to the left of `yaw` (the same numbers serve both
// sides with side = -1 or +1).
struct StreetStretch {
  bool vertical = false;
  long long i = 0, j = 0;
  std::uint64_t seed = 0;
  double line = 0.0;          // the centre line's coordinate across
  double lo = 0.0, hi = 0.0;  // usable stretch along, clear of the crossings
  StreetProfile profile;
  double yaw = 0.0;  // direction along

  Vec2 at(double along, double lateral) const {
    return vertical ? Vec2{line + lateral, along} : Vec2{along, line + lateral};
  }
  std::uint64_t key(std::uint64_t tag) const {
    return hash_key({seed, tag, vertical ? 1u : 0u, key_of(i), key_of(j)});
  }
  // The middle of the parking lane.
  double parking_centre() const {
    return profile.carriageway_half_m() + 0.5 * profile.parking_width_m;
  }
  // A place on the pavement `from_kerb` metres beyond the kerb (street furniture, trees).
  double pavement(double from_kerb) const { return profile.kerb_offset_m() + from_kerb; }
};
StreetStretch street_stretch(const GenerationContext& ctx, bool vertical, long long i, long long j);

inline constexpr WallMaterial kCarBody{90.0f, 0.35f, 0.0f, 3.0f};  // low: the radar sees over
inline constexpr WallMaterial kFence{62.0f, 0.5f, 0.0f, 4.0f};
inline constexpr double kCarLength = 4.5;
inline constexpr double kCarWidth = 1.85;

WallMaterial facade(Rng& rng);
void add_lamp(World& world, Vec2 at);
// A tree: a crown (scaled by the session's foliage factor, then at most `max_crown_m`) and a
// trunk.
void add_tree(World& world, Vec2 at, double crown_radius, Rng& rng, const GenerationContext& ctx,
              double max_crown_m = std::numeric_limits<double>::infinity());
// A street tree on side `side` of `street`, `along` it, on the pavement: its crown may overhang
// the parking lane but stays a metre off the parking line, clear of the lanes.
void add_street_tree(World& world, const StreetStretch& street, double side, double along,
                     double crown_radius, Rng& rng, const GenerationContext& ctx);
// A parked car at a parking place: drawn from `rng` whether or not it is there this session, so
// the rest of the block stays the same.
void add_parked_car(World& world, Vec2 at, double yaw, Rng& rng, const GenerationContext& ctx,
                    std::uint64_t place_key);
// Cars along the parking lane on side `side` of `street`, a place every `spacing_m`; `place`
// numbers the places of the street (keys of their session draws).
void add_parking_lane(World& world, const StreetStretch& street, double side, double spacing_m,
                      Rng& rng, const GenerationContext& ctx, std::uint64_t place_tag,
                      std::uint64_t& place);
// A fence from a to b in pieces with gaps (gates, breaks).
void add_fence(World& world, Vec2 a, Vec2 b, Rng& rng);
// Cut [lo, hi] into `parts` pieces of random but comparable lengths.
std::vector<double> split(double lo, double hi, int parts, Rng& rng);

}  // namespace radarpr::synthetic
