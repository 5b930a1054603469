// A campus (MulRan KAIST): institute buildings of many sizes spread over lawns, seen far across
// the open ground between them; groves, lamp-lined paths, car parks; tree-lined avenues.
#include <cmath>
#include <numbers>

#include "datasets/synthetic/world/world_kinds.hpp"

namespace radarpr::synthetic {
namespace {

enum Tag : std::uint64_t { kBlockTag = 51, kPlaceTag = 53 };

bool overlaps(const Rect& a, const Rect& b, double gap) {
  return a.x0 < b.x1 + gap && b.x0 < a.x1 + gap && a.y0 < b.y1 + gap && b.y0 < a.y1 + gap;
}

}  // namespace

void campus_block(World& world, const GenerationContext& ctx, long long bx, long long by) {
  Rng rng(hash_key({ctx.seed, kBlockTag, key_of(bx), key_of(by)}));
  const Rect lot = block_lot(ctx, bx, by);
  // Buildings of every size, placed until the block holds its share (or no room is left),
  // some with a wing: each block's skyline is its own.
  std::vector<Rect> buildings;
  const int wanted = rng.uniform_int(4, 7);
  for (int attempt = 0; attempt < 40 && static_cast<int>(buildings.size()) < wanted; ++attempt) {
    const double w = rng.uniform(12.0, std::min(48.0, lot.width() - 12.0));
    const double h = rng.uniform(10.0, std::min(30.0, lot.height() - 12.0));
    const double x0 = rng.uniform(lot.x0 + 4.0, lot.x1 - 4.0 - w);
    const double y0 = rng.uniform(lot.y0 + 4.0, lot.y1 - 4.0 - h);
    const Rect r{x0, y0, x0 + w, y0 + h};
    bool free = true;
    for (const Rect& other : buildings) free = free && !overlaps(r, other, 7.0);
    if (!free) continue;
    buildings.push_back(r);
    const WallMaterial material = facade(rng);
    add_axis_box(world, r.x0, r.y0, r.x1, r.y1, material);
    if (w > 20.0 && rng.chance(0.4)) {  // a wing off the long side, within the gap's room
      const double wing_w = rng.uniform(6.0, 0.4 * w);
      const double wx = rng.uniform(r.x0, r.x1 - wing_w);
      const double depth = rng.uniform(3.0, 6.0);
      const bool north = rng.chance(0.5);
      add_axis_box(world, wx, north ? r.y1 : r.y0 - depth, wx + wing_w, north ? r.y1 + depth : r.y0,
                   material);
    }
  }
  // Groves: clusters of trees on the lawns.
  const int groves = rng.uniform_int(2, 5);
  for (int g = 0; g < groves; ++g) {
    const Vec2 centre{rng.uniform(lot.x0 + 5.0, lot.x1 - 5.0),
                      rng.uniform(lot.y0 + 5.0, lot.y1 - 5.0)};
    const int trees = rng.uniform_int(3, 9);
    for (int t = 0; t < trees; ++t) {
      const Vec2 at{centre.x + rng.normal(0.0, 7.0), centre.y + rng.normal(0.0, 7.0)};
      const Rect spot{at.x - 3.0, at.y - 3.0, at.x + 3.0, at.y + 3.0};
      bool free = at.x > lot.x0 + 2 && at.x < lot.x1 - 2 && at.y > lot.y0 + 2 && at.y < lot.y1 - 2;
      for (const Rect& b : buildings) free = free && !overlaps(spot, b, 1.0);
      if (free) add_tree(world, at, rng.uniform(2.0, 4.5), rng, ctx);
    }
  }
  // A lamp-lined diagonal path across the lawn.
  if (rng.chance(0.6)) {
    const Vec2 a{lot.x0 + 3.0, rng.uniform(lot.y0 + 3.0, lot.y1 - 3.0)};
    const Vec2 b{lot.x1 - 3.0, rng.uniform(lot.y0 + 3.0, lot.y1 - 3.0)};
    for (double f = 0.1; f < 1.0; f += 0.2) {
      const Vec2 at{a.x + f * (b.x - a.x), a.y + f * (b.y - a.y)};
      bool free = true;
      for (const Rect& r : buildings) free = free && !overlaps({at.x, at.y, at.x, at.y}, r, 1.0);
      if (free) add_lamp(world, at);
    }
  }
  if (rng.chance(0.4)) {  // a car park along the south edge
    std::uint64_t place = 0;
    const std::uint64_t key = hash_key({ctx.seed, kPlaceTag, key_of(bx), key_of(by)});
    for (double x = lot.x0 + 4.0; x < lot.x0 + 40.0; x += 2.7) {
      const Rect spot{x - 1.0, lot.y0 + 1.0, x + 1.0, lot.y0 + 6.0};
      bool free = true;
      for (const Rect& r : buildings) free = free && !overlaps(spot, r, 0.5);
      if (free) {
        add_parked_car(world, {x, lot.y0 + 3.5}, std::numbers::pi / 2.0, rng, ctx,
                       hash_key({key, place++}));
      }
    }
  }
}

void campus_street(World& world, const GenerationContext& ctx, const StreetStretch& street,
                   Rng& rng) {
  std::uint64_t place = 0;
  for (const double side : {-1.0, 1.0}) {
    // Parking along some avenues only; trees along most, planted at a steady spacing but with
    // gaps where one died; lamps between them.
    if (rng.chance(0.35)) add_parking_lane(world, street, side, 6.0, rng, ctx, kPlaceTag, place);
    if (rng.chance(0.75)) {
      const double spacing = rng.uniform(8.0, 14.0);
      for (double s = street.lo + rng.uniform(0.0, spacing); s < street.hi; s += spacing) {
        const double crown = rng.uniform(2.0, 3.2);
        if (rng.chance(0.8)) add_street_tree(world, street, side, s, crown, rng, ctx);
      }
    }
    for (double s = street.lo + rng.uniform(0.0, 25.0); s < street.hi; s += 25.0) {
      add_lamp(world, street.at(s, side * street.pavement(0.6)));
    }
  }
}

}  // namespace radarpr::synthetic
