#pragma once

#include <vector>

namespace radarpr::synthetic {

// A 2-D world of radar reflectors, in metres, in a fixed world frame (x east, y north).
//
// Echo strengths are in the output image's units (uint8 power, about 0.5 dB per unit, the
// Navtech convention) for a target at 0 m seen head-on; the renderer subtracts range and
// incidence losses. Transmissions are the two-way power fraction that passes an object.

struct Vec2 {
  double x = 0.0;
  double y = 0.0;
};

// A straight reflecting surface: building facade, fence, car side.
struct WallSegment {
  Vec2 a;
  Vec2 b;
  float strength = 100.0f;
  float transmission = 0.0f;  // 0 = opaque (buildings): hides everything behind it
  // Facades are not uniform: pillars and window frames every `texture_period_m` metres return
  // brighter spots (0 = uniform surface).
  float texture_period_m = 0.0f;
  // Fixed blotchiness: the level varies by up to +- this many units per 0.8 m of wall, the
  // same from every viewpoint (0 = smooth, for hand-computed tests).
  float scatter_units = 6.0f;
};

// A thin vertical cylinder: lamp post, sign, tree trunk. Seen by every azimuth within its beam.
struct Pole {
  Vec2 centre;
  float radius_m = 0.1f;
  float strength = 80.0f;
  float transmission = 0.9f;  // poles attenuate little
};

// A volume scatterer: tree crown, bush, hedge. Returns from its whole depth and attenuates the
// beam exponentially along the chord it crosses.
struct Foliage {
  Vec2 centre;
  float radius_m = 2.0f;
  float strength = 50.0f;
  float attenuation_per_m = 0.35f;  // two-way power attenuation: exp(-attenuation * chord)
};

struct World {
  std::vector<WallSegment> walls;
  std::vector<Pole> poles;
  std::vector<Foliage> foliage;

  std::size_t element_count() const { return walls.size() + poles.size() + foliage.size(); }
};

// Surface properties shared by the four sides of a box.
struct WallMaterial {
  float strength = 100.0f;
  float transmission = 0.0f;
  float texture_period_m = 0.0f;
  float scatter_units = 6.0f;
};

// Adds the wall from a to b made of `material`.
void add_wall(World& world, Vec2 a, Vec2 b, const WallMaterial& material);
// Adds the four sides of a rectangle centred at `centre`, `length` along heading `yaw_rad`.
void add_box(World& world, Vec2 centre, double length_m, double width_m, double yaw_rad,
             const WallMaterial& material);
// Adds the four sides of the axis-aligned rectangle [x0, x1] x [y0, y1].
void add_axis_box(World& world, double x0, double y0, double x1, double y1,
                  const WallMaterial& material);

}  // namespace radarpr::synthetic
