#include "datasets/synthetic/world/traffic.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "datasets/synthetic/drive/drive_path.hpp"
#include "datasets/synthetic/random.hpp"
#include "datasets/synthetic/world/world_parts.hpp"

namespace radarpr::synthetic {
namespace {

enum Tag : std::uint64_t { kTrafficTag = 81 };

constexpr WallMaterial kVehicle{92.0f, 0.3f, 0.0f, 3.0f};
constexpr WallMaterial kBus{100.0f, 0.0f, 2.5f, 4.0f};  // tall: hides what is behind it
constexpr double kEgoGapM = 0.3;

// A vehicle's footprint, generously: the segment along its length swept by half its width.
struct Capsule {
  Vec2 a, b;
  double radius = 0.0;
};

Capsule capsule_of(Vec2 centre, double yaw, double length, double half_width) {
  const Vec2 half{0.5 * length * std::cos(yaw), 0.5 * length * std::sin(yaw)};
  return {
      {centre.x - half.x, centre.y - half.y}, {centre.x + half.x, centre.y + half.y}, half_width};
}

double point_to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const double ex = b.x - a.x;
  const double ey = b.y - a.y;
  const double length_sq = ex * ex + ey * ey;
  const double t = length_sq > 0.0
                       ? std::clamp(((p.x - a.x) * ex + (p.y - a.y) * ey) / length_sq, 0.0, 1.0)
                       : 0.0;
  return std::hypot(p.x - a.x - t * ex, p.y - a.y - t * ey);
}

double orientation(Vec2 a, Vec2 b, Vec2 c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

double segment_distance(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const bool crossing = orientation(a, b, c) * orientation(a, b, d) < 0.0 &&
                        orientation(c, d, a) * orientation(c, d, b) < 0.0;
  if (crossing) return 0.0;
  return std::min({point_to_segment(a, c, d), point_to_segment(b, c, d), point_to_segment(c, a, b),
                   point_to_segment(d, a, b)});
}

double gap(const Capsule& p, const Capsule& q) {
  return segment_distance(p.a, p.b, q.a, q.b) - p.radius - q.radius;
}

}  // namespace

World moving_vehicles(std::uint64_t seed, int session, const CityLayout& layout,
                      const WorldParams& params, double time_s, const Pose2D& ego, double reach_m) {
  World world;
  if (params.traffic <= 0.0) return world;
  const double pitch = layout.block_pitch_m;
  const double half_street = layout.street.half_width_m();
  const double stretch = pitch - 2.0 * half_street;
  const Capsule own_car = capsule_of({ego.x, ego.y}, ego.yaw, kCarLength, kVehicleHalfWidthM);
  const auto i0 = static_cast<long long>(std::floor((ego.x - reach_m) / pitch));
  const auto i1 = static_cast<long long>(std::floor((ego.x + reach_m) / pitch)) + 1;
  const auto j0 = static_cast<long long>(std::floor((ego.y - reach_m) / pitch));
  const auto j1 = static_cast<long long>(std::floor((ego.y + reach_m) / pitch)) + 1;
  for (long long i = i0; i <= i1; ++i) {
    for (long long j = j0; j <= j1; ++j) {
      for (const bool vertical : {false, true}) {
        for (const double direction : {1.0, -1.0}) {
          Rng rng(hash_key({seed, kTrafficTag, static_cast<std::uint64_t>(session),
                            static_cast<std::uint64_t>(i), static_cast<std::uint64_t>(j),
                            vertical ? 1u : 0u, direction > 0 ? 1u : 0u}));
          const int count = static_cast<int>(std::floor(params.traffic + rng.uniform()));
          for (int k = 0; k < count; ++k) {
            const double phase = rng.uniform();
            const double speed = rng.uniform(5.0, 12.0);
            const double kind = rng.uniform();
            const int lane = rng.uniform_int(0, layout.street.lanes_per_direction - 1);
            const double length = kind < 0.8 ? 4.5 : kind < 0.95 ? 6.0 : 11.5;
            const double width = kind < 0.8 ? 1.85 : kind < 0.95 ? 2.1 : 2.5;
            // Around its stretch of street and back in at the start: only the appearance of
            // traffic matters, not where each vehicle goes.
            const double travelled = std::fmod(phase * stretch + speed * time_s, stretch);
            const double along_from_start = direction > 0 ? travelled : stretch - travelled;
            const double along =
                static_cast<double>(vertical ? j : i) * pitch + half_street + along_from_start;
            const double line = static_cast<double>(vertical ? i : j) * pitch;
            // Right-hand traffic: the lanes right of the direction of travel.
            const double lateral =
                (vertical ? direction : -direction) * layout.street.lane_centre_m(lane);
            const Vec2 at = vertical ? Vec2{line + lateral, along} : Vec2{along, line + lateral};
            const double yaw = (vertical ? std::numbers::pi / 2.0 : 0.0) +
                               (direction > 0 ? 0.0 : std::numbers::pi);
            if (std::hypot(at.x - ego.x, at.y - ego.y) > reach_m) continue;
            if (gap(capsule_of(at, yaw, length, 0.5 * width), own_car) < kEgoGapM) continue;
            add_box(world, at, length, width, yaw, length > 10.0 ? kBus : kVehicle);
          }
        }
      }
    }
  }
  return world;
}

}  // namespace radarpr::synthetic
