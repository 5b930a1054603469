#include "datasets/synthetic/radar/echo_hits.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "datasets/synthetic/random.hpp"

namespace radarpr::synthetic {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kMaxGrazingExtentM = 6.0;  // longest streak a grazing wall leaves along range
constexpr double kScatterCellM = 0.8;       // facade scatter varies per cell of this length

double cross(const Vec2& a, const Vec2& b) {
  return a.x * b.y - a.y * b.x;
}

double distance_to_segment(const Vec2& a, const Vec2& b) {
  const Vec2 e{b.x - a.x, b.y - a.y};
  const double length_sq = e.x * e.x + e.y * e.y;
  double t = length_sq > 0.0 ? -(a.x * e.x + a.y * e.y) / length_sq : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(a.x + t * e.x, a.y + t * e.y);
}

// Echo level of a facade hit: specular-ish incidence term (never below -24 units: rough walls
// still scatter at grazing angles), brighter pillars/frames every texture period, and a fixed
// per-metre scatter so a wall looks blotchy, the same blotches from every viewpoint.
float wall_level(const WallSegment& wall, std::uint64_t wall_key, double cos_incidence,
                 double along_m) {
  const double c2 = cos_incidence * cos_incidence;
  double level = wall.strength + 20.0 * std::log10(0.06 + 0.94 * c2 * c2);
  if (wall.texture_period_m > 0.0f) {
    const double phase =
        std::fmod(along_m, static_cast<double>(wall.texture_period_m)) / wall.texture_period_m;
    level += phase < 0.2 ? 8.0 : -2.0;
  }
  if (wall.scatter_units <= 0.0f) return static_cast<float>(level);
  const auto cell =
      static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(along_m / kScatterCellM)));
  const std::uint64_t h = mix64(wall_key ^ mix64(cell));
  level += wall.scatter_units * (2.0 * static_cast<double>(h >> 11) * 0x1.0p-53 - 1.0);
  return static_cast<float>(level);
}

// Identifies a wall by its geometry (not its index), so the scatter pattern is the same in
// every region generated of the same city.
std::uint64_t wall_key(const WallSegment& wall) {
  auto mm = [](double v) { return static_cast<std::uint64_t>(std::llround(v * 1000.0)); };
  return hash_key({mm(wall.a.x), mm(wall.a.y), mm(wall.b.x), mm(wall.b.y)});
}

}  // namespace

void collect_wall_hits(const World& world, const RayGeometry& rays, double beam_rad,
                       std::vector<Hit>& hits) {
  for (const WallSegment& wall : world.walls) {
    const Vec2 a = rays.to_middle(wall.a);
    const Vec2 b = rays.to_middle(wall.b);
    const double distance = distance_to_segment(a, b);
    if (distance >= rays.max_range_m + rays.max_displacement_m || distance < 1e-6) continue;
    const Vec2 e_world{wall.b.x - wall.a.x, wall.b.y - wall.a.y};
    const double length = std::hypot(e_world.x, e_world.y);
    if (length < 1e-9) continue;
    const std::uint64_t key = wall_key(wall);

    // The segment does not contain the sensor, so it spans less than pi of azimuth: walk the
    // rays of the shorter arc between its end points (seen from the middle pose, widened by
    // how far the sensor moves during the sweep).
    const double angle_a = std::atan2(a.y, a.x);
    double span = std::atan2(b.y, b.x) - angle_a;
    if (span > kPi) span -= kTwoPi;
    if (span < -kPi) span += kTwoPi;
    const double start = span >= 0.0 ? angle_a : angle_a + span;
    const int margin = rays.motion_margin_rays(distance);
    const int first = static_cast<int>(std::ceil(start / rays.step_rad)) - margin;
    const int last =
        std::min(first + rays.azimuths - 1,
                 static_cast<int>(std::floor((start + std::abs(span)) / rays.step_rad)) + margin);
    for (int i = first; i <= last; ++i) {
      const int ray = rays.wrap(i);
      const auto index = static_cast<std::size_t>(ray);
      const Vec2 dir{rays.cos_a[index], rays.sin_a[index]};
      const Vec2 w{wall.a.x - rays.origin[index].x, wall.a.y - rays.origin[index].y};
      const double denom = cross(dir, e_world);
      if (std::abs(denom) < 1e-12 * length) continue;  // ray parallel to the wall
      const double range = cross(w, e_world) / denom;
      const double t = cross(w, dir) / denom;
      if (range <= 0.0 || range >= rays.max_range_m || t < -1e-9 || t > 1.0 + 1e-9) continue;
      const double cos_incidence = std::min(1.0, std::abs(denom) / length);
      const double tan_incidence = std::sqrt(std::max(0.0, 1.0 - cos_incidence * cos_incidence)) /
                                   std::max(cos_incidence, 1e-6);
      // Within the beam a slanted wall covers a stretch of ranges: a streak, not a dot.
      const double extent = std::min(range * beam_rad * tan_incidence, kMaxGrazingExtentM);
      hits.push_back({ray, range, wall_level(wall, key, cos_incidence, t * length),
                      wall.transmission, static_cast<float>(extent), HitKind::wall,
                      rays.beam_reach});
    }
  }
}

void collect_pole_hits(const World& world, const RayGeometry& rays, std::vector<Hit>& hits) {
  for (const Pole& pole : world.poles) {
    const Vec2 c = rays.to_middle(pole.centre);
    const double distance = std::hypot(c.x, c.y);
    if (distance <= pole.radius_m ||
        distance - pole.radius_m >= rays.max_range_m + rays.max_displacement_m) {
      continue;
    }
    const double centre_index = rays.index_of(std::atan2(c.y, c.x));
    const double half_width = std::asin(pole.radius_m / distance) / rays.step_rad;
    const int reach = rays.beam_reach + static_cast<int>(std::ceil(half_width)) +
                      rays.motion_margin_rays(distance);
    const int nearest = static_cast<int>(std::lround(centre_index));
    // A pole is evaluated on every ray of its beam directly (not spread afterwards), so each
    // ray's own occluders decide whether it sees the pole.
    for (int i = nearest - reach; i <= nearest + reach && i < nearest - reach + rays.azimuths;
         ++i) {
      const int ray = rays.wrap(i);
      const Vec2 p = rays.along_ray(ray, pole.centre);
      const double d = std::hypot(p.x, p.y);
      if (p.x <= 0.0 || d <= pole.radius_m || d - pole.radius_m >= rays.max_range_m) continue;
      const double offset_steps = std::atan2(std::abs(p.y), p.x) / rays.step_rad;
      const double half = std::asin(pole.radius_m / d) / rays.step_rad;
      const float weight = rays.beam_weight(std::max(0.0, offset_steps - half));
      if (weight < kMinBeamWeight) continue;
      const float level = pole.strength + 20.0f * std::log10(weight);
      const float transmission = 1.0f - (1.0f - pole.transmission) * weight;
      // The ray nearest the pole's centre carries its side lobes, beyond the rays it covers.
      const int gap = i == nearest ? rays.beam_reach + static_cast<int>(half) : -1;
      hits.push_back({ray, d - pole.radius_m, level, transmission, 0.0f, HitKind::pole, gap});
    }
  }
}

void collect_foliage_hits(const World& world, const RayGeometry& rays, std::vector<Hit>& hits) {
  for (const Foliage& crown : world.foliage) {
    const Vec2 c = rays.to_middle(crown.centre);
    const double distance = std::hypot(c.x, c.y);
    const double radius = crown.radius_m;
    if (distance - radius >= rays.max_range_m + rays.max_displacement_m) continue;
    const double centre_index = rays.index_of(std::atan2(c.y, c.x));
    const double half_width =
        distance > radius ? std::asin(radius / distance) / rays.step_rad : rays.azimuths / 2.0;
    const int margin = rays.motion_margin_rays(std::max(distance - radius, 1e-6));
    const int first = static_cast<int>(std::ceil(centre_index - half_width)) - margin;
    const int last = static_cast<int>(std::floor(centre_index + half_width)) + margin;
    for (int i = first; i <= last && i < first + rays.azimuths; ++i) {
      const int ray = rays.wrap(i);
      const Vec2 p = rays.along_ray(ray, crown.centre);
      const double along = p.x;
      const double miss_sq = p.y * p.y;
      if (miss_sq >= radius * radius) continue;
      const double half_chord = std::sqrt(radius * radius - miss_sq);
      const double enter = std::max(0.0, along - half_chord);
      const double leave = along + half_chord;
      if (leave <= 0.0 || enter >= rays.max_range_m) continue;
      const auto transmission =
          static_cast<float>(std::exp(-crown.attenuation_per_m * (leave - enter)));
      hits.push_back({ray, enter, crown.strength, transmission, static_cast<float>(leave - enter),
                      HitKind::foliage});
    }
  }
}

}  // namespace radarpr::synthetic
