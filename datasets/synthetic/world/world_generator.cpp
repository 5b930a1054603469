#include "datasets/synthetic/world/world_generator.hpp"

#include <cmath>

#include "datasets/synthetic/random.hpp"
#include "datasets/synthetic/world/world_kinds.hpp"

namespace radarpr::synthetic {
namespace {

enum Tag : std::uint64_t { kGroundTag = 91, kStreetTag = 92 };

constexpr WallMaterial kKerb{58.0f, 0.97f, 0.0f, 10.0f};  // low edges: seen over, streaky

// What every world has beside its kind's objects: kerbs along the roads (paved kinds) and
// patches of rough ground (grass, gravel, verges) that return a little and hide nothing.
void add_ground(World& world, const GenerationContext& ctx, long long bx, long long by,
                bool kerbs) {
  Rng rng(hash_key({ctx.seed, kGroundTag, key_of(bx), key_of(by)}));
  const Rect lot = block_lot(ctx, bx, by);
  const int patches = rng.uniform_int(8, 16);
  for (int k = 0; k < patches; ++k) {
    world.foliage.push_back({{rng.uniform(lot.x0, lot.x1), rng.uniform(lot.y0, lot.y1)},
                             static_cast<float>(rng.uniform(1.5, 4.0)),
                             static_cast<float>(rng.uniform(30.0, 40.0)),
                             0.01f});
  }
  if (!kerbs) return;
  // The block's four kerbs, between the roadway (parking lane) and the pavement.
  const Rect kerb = kerb_square(ctx, bx, by);
  const Vec2 corners[] = {
      {kerb.x0, kerb.y0}, {kerb.x1, kerb.y0}, {kerb.x1, kerb.y1}, {kerb.x0, kerb.y1}};
  for (int k = 0; k < 4; ++k) add_wall(world, corners[k], corners[(k + 1) % 4], kKerb);
}

using BlockFiller = void (*)(World&, const GenerationContext&, long long, long long);
using StreetFiller = void (*)(World&, const GenerationContext&, const StreetStretch&, Rng&);

struct KindFillers {
  BlockFiller block;
  StreetFiller street;
  bool crossing_lights;
};

KindFillers fillers_of(WorldKind kind) {
  switch (kind) {
    case WorldKind::suburban:
      return {suburban_block, suburban_street, true};
    case WorldKind::campus:
      return {campus_block, campus_street, true};
    case WorldKind::riverside:
      return {riverside_block, riverside_street, true};
    case WorldKind::offroad:
      return {offroad_block, offroad_street, false};
    case WorldKind::city:
      break;
  }
  return {city_block, city_street, true};
}

// The stretch's own random stream: the same whatever else is generated.
void fill_street(World& world, const GenerationContext& ctx, StreetFiller filler, bool vertical,
                 long long i, long long j) {
  const StreetStretch street = street_stretch(ctx, vertical, i, j);
  Rng rng(street.key(kStreetTag));
  filler(world, ctx, street, rng);
}

}  // namespace

World generate_world(std::uint64_t seed, int session, const CityLayout& layout,
                     const WorldParams& params, Vec2 min, Vec2 max) {
  validate(layout);
  validate(params, layout);
  const GenerationContext ctx{seed, session, layout, params};
  const KindFillers fill = fillers_of(params.kind);
  const double pitch = layout.block_pitch_m;
  const auto bx0 = static_cast<long long>(std::floor(min.x / pitch));
  const auto bx1 = static_cast<long long>(std::floor(max.x / pitch));
  const auto by0 = static_cast<long long>(std::floor(min.y / pitch));
  const auto by1 = static_cast<long long>(std::floor(max.y / pitch));
  World world;
  for (long long bx = bx0; bx <= bx1; ++bx) {
    for (long long by = by0; by <= by1; ++by) {
      fill.block(world, ctx, bx, by);
      add_ground(world, ctx, bx, by, params.kind != WorldKind::offroad);
    }
  }
  // Streets and crossings on the block boundaries, including the far edges.
  for (long long i = bx0; i <= bx1 + 1; ++i) {
    for (long long j = by0; j <= by1 + 1; ++j) {
      if (i <= bx1) fill_street(world, ctx, fill.street, false, i, j);
      if (j <= by1) fill_street(world, ctx, fill.street, true, i, j);
      if (fill.crossing_lights) crossing_lights(world, ctx, i, j);
    }
  }
  return world;
}

}  // namespace radarpr::synthetic
