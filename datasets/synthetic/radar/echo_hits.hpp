#pragma once

#include <cstdint>
#include <vector>

#include "datasets/synthetic/radar/ray_geometry.hpp"
#include "datasets/synthetic/world/synthetic_world.hpp"

namespace radarpr::synthetic {

// Renderer internals: which objects each ray meets, and how strongly they answer.

enum class HitKind : std::uint8_t { wall, pole, foliage };

// One object crossed by the pencil ray of one azimuth.
struct Hit {
  int ray = 0;
  double range_m = 0.0;
  float level = 0.0f;         // echo level at this range before attenuation (units)
  float transmission = 1.0f;  // two-way power fraction passing the object
  float extent_m = 0.0f;      // depth the echo covers along range (0 = point echo)
  HitKind kind = HitKind::wall;
  // Rays between this one and the first side lobe its echo leaks into; -1: no side lobes. Walls
  // and the central ray of a pole have them; crowns (at most ~52 units, and a side lobe is 52
  // below) never rise above the noise floor through one.
  int sidelobe_gap = -1;
};

// Appends the hits of every wall, pole and crown of `world` on the rays of `rays`, unordered.
// `beam_rad` is the beam width: within it a slanted wall covers a stretch of ranges.
void collect_wall_hits(const World& world, const RayGeometry& rays, double beam_rad,
                       std::vector<Hit>& hits);
void collect_pole_hits(const World& world, const RayGeometry& rays, std::vector<Hit>& hits);
void collect_foliage_hits(const World& world, const RayGeometry& rays, std::vector<Hit>& hits);

}  // namespace radarpr::synthetic
