#include "datasets/synthetic/traffic.hpp"

#include <cmath>
#include <numbers>

#include "datasets/synthetic/random.hpp"

namespace radarpr::synthetic {
namespace {

enum Tag : std::uint64_t { kTrafficTag = 81 };

constexpr WallMaterial kVehicle{92.0f, 0.3f, 0.0f, 3.0f};
constexpr WallMaterial kBus{100.0f, 0.0f, 2.5f, 4.0f};  // tall: hides what is behind it
constexpr double kEgoClearanceM = 8.0;

}  // namespace

World moving_vehicles(std::uint64_t seed, int session, const CityLayout& layout,
                      const WorldParams& params, double lane_offset_m, double time_s, Vec2 centre,
                      double reach_m) {
  World world;
  if (params.traffic <= 0.0) return world;
  const double pitch = layout.block_pitch_m;
  const double half_street = 0.5 * layout.street_width_m;
  const double stretch = pitch - 2.0 * half_street;
  const auto i0 = static_cast<long long>(std::floor((centre.x - reach_m) / pitch));
  const auto i1 = static_cast<long long>(std::floor((centre.x + reach_m) / pitch)) + 1;
  const auto j0 = static_cast<long long>(std::floor((centre.y - reach_m) / pitch));
  const auto j1 = static_cast<long long>(std::floor((centre.y + reach_m) / pitch)) + 1;
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
            const double length = kind < 0.8 ? 4.5 : kind < 0.95 ? 6.0 : 11.5;
            const double width = kind < 0.8 ? 1.85 : kind < 0.95 ? 2.1 : 2.5;
            // Around its stretch of street and back in at the start: only the appearance of
            // traffic matters, not where each vehicle goes.
            const double travelled = std::fmod(phase * stretch + speed * time_s, stretch);
            const double along_from_start = direction > 0 ? travelled : stretch - travelled;
            const double along =
                static_cast<double>(vertical ? j : i) * pitch + half_street + along_from_start;
            const double line = static_cast<double>(vertical ? i : j) * pitch;
            // Right-hand traffic: the lane right of the direction of travel.
            const double lateral = (vertical ? direction : -direction) * lane_offset_m;
            const Vec2 at = vertical ? Vec2{line + lateral, along} : Vec2{along, line + lateral};
            const double distance = std::hypot(at.x - centre.x, at.y - centre.y);
            if (distance < kEgoClearanceM || distance > reach_m) continue;
            const double yaw = (vertical ? std::numbers::pi / 2.0 : 0.0) +
                               (direction > 0 ? 0.0 : std::numbers::pi);
            add_box(world, at, length, width, yaw, length > 10.0 ? kBus : kVehicle);
          }
        }
      }
    }
  }
  return world;
}

}  // namespace radarpr::synthetic
