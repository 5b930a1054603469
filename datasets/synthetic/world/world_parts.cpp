#include "datasets/synthetic/world/world_parts.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace radarpr::synthetic {
namespace {

enum Tag : std::uint64_t { kParkedTag = 31, kChurnTag = 32 };

double unit(std::uint64_t h) {
  return static_cast<double>(h >> 11) * 0x1.0p-53;
}

Rect block_square(const GenerationContext& ctx, long long bx, long long by, double inset) {
  const double pitch = ctx.layout.block_pitch_m;
  return {static_cast<double>(bx) * pitch + inset, static_cast<double>(by) * pitch + inset,
          static_cast<double>(bx + 1) * pitch - inset, static_cast<double>(by + 1) * pitch - inset};
}

}  // namespace

bool GenerationContext::parked(std::uint64_t place_key) const {
  const bool redrawn =
      session > 0 &&
      unit(hash_key({seed, kChurnTag, place_key, static_cast<std::uint64_t>(session)})) <
          params.parked_car_churn;
  const std::uint64_t draw_session = redrawn ? static_cast<std::uint64_t>(session) : 0u;
  return unit(hash_key({seed, kParkedTag, place_key, draw_session})) < params.parked_cars;
}

Rect block_lot(const GenerationContext& ctx, long long bx, long long by) {
  return block_square(ctx, bx, by, ctx.layout.street.half_width_m());
}

Rect kerb_square(const GenerationContext& ctx, long long bx, long long by) {
  return block_square(ctx, bx, by, ctx.layout.street.kerb_offset_m());
}

StreetStretch street_stretch(const GenerationContext& ctx, bool vertical, long long i,
                             long long j) {
  StreetStretch street;
  street.vertical = vertical;
  street.i = i;
  street.j = j;
  street.seed = ctx.seed;
  street.profile = ctx.layout.street;
  const double pitch = ctx.layout.block_pitch_m;
  const double clear = street.profile.clear_of_crossing_m();
  street.line = static_cast<double>(vertical ? i : j) * pitch;
  const double start = static_cast<double>(vertical ? j : i) * pitch;
  street.lo = start + clear;
  street.hi = start + pitch - clear;
  street.yaw = vertical ? std::numbers::pi / 2.0 : 0.0;
  return street;
}

WallMaterial facade(Rng& rng) {
  const auto strength = static_cast<float>(rng.uniform(92.0, 108.0));
  const auto period = static_cast<float>(rng.chance(0.7) ? rng.uniform(2.5, 4.5) : 0.0);
  return {strength, 0.0f, period, 6.0f};
}

void add_lamp(World& world, Vec2 at) {
  world.poles.push_back({at, 0.12f, 82.0f, 0.92f});
}

void add_tree(World& world, Vec2 at, double crown_radius, Rng& rng, const GenerationContext& ctx,
              double max_crown_m) {
  const double strength = rng.uniform(44.0, 52.0);
  // Bare crowns are smaller and thinner: they return less and let more through.
  const double leaf = ctx.params.foliage;
  world.foliage.push_back({at, static_cast<float>(std::min(crown_radius * leaf, max_crown_m)),
                           static_cast<float>(strength + 6.0 * std::log2(leaf)),
                           static_cast<float>(0.35 * std::min(1.0, leaf))});
  world.poles.push_back({at, 0.2f, 62.0f, 0.85f});  // the trunk
}

void add_street_tree(World& world, const StreetStretch& street, double side, double along,
                     double crown_radius, Rng& rng, const GenerationContext& ctx) {
  const double lateral = street.pavement(std::min(1.5, 0.5 * street.profile.pavement_width_m));
  const double reach = lateral - street.profile.carriageway_half_m() - 1.0;
  add_tree(world, street.at(along, side * lateral), crown_radius, rng, ctx, reach);
}

void add_parked_car(World& world, Vec2 at, double yaw, Rng& rng, const GenerationContext& ctx,
                    std::uint64_t place_key) {
  const double jitter = rng.normal(0.0, 0.03);
  if (!ctx.parked(place_key)) return;
  add_box(world, at, kCarLength, kCarWidth, yaw + jitter, kCarBody);
}

void add_parking_lane(World& world, const StreetStretch& street, double side, double spacing_m,
                      Rng& rng, const GenerationContext& ctx, std::uint64_t place_tag,
                      std::uint64_t& place) {
  if (street.profile.parking_width_m < kCarWidth) return;  // no room to park
  for (double s = street.lo + 3.0; s + 3.0 < street.hi; s += spacing_m) {
    add_parked_car(world, street.at(s, side * street.parking_centre()), street.yaw, rng, ctx,
                   hash_key({street.key(place_tag), place++}));
  }
}

void add_fence(World& world, Vec2 a, Vec2 b, Rng& rng) {
  const double length = std::hypot(b.x - a.x, b.y - a.y);
  double s = 0.0;
  while (s < length) {
    const double piece_end = std::min(length, s + rng.uniform(5.0, 15.0));
    add_wall(world, {a.x + (b.x - a.x) * s / length, a.y + (b.y - a.y) * s / length},
             {a.x + (b.x - a.x) * piece_end / length, a.y + (b.y - a.y) * piece_end / length},
             kFence);
    s = piece_end + rng.uniform(1.0, 3.0);
  }
}

std::vector<double> split(double lo, double hi, int parts, Rng& rng) {
  std::vector<double> weights(static_cast<std::size_t>(parts));
  double total = 0.0;
  for (double& w : weights) total += (w = rng.uniform(0.6, 1.4));
  std::vector<double> cuts{lo};
  double acc = 0.0;
  for (const double w : weights) cuts.push_back(lo + (hi - lo) * ((acc += w) / total));
  return cuts;
}

}  // namespace radarpr::synthetic
