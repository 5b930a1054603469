// A riverside town (MulRan Riverside): a river along block row 0 crossed by bridges that all
// share one structure, promenades with trees at a fixed spacing, and slab blocks built to a few
// repeated plans: places that look alike.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "datasets/synthetic/world/world_kinds.hpp"

namespace radarpr::synthetic {
namespace {

enum Tag : std::uint64_t { kBlockTag = 61, kPlaceTag = 63, kPlanTag = 64 };

constexpr WallMaterial kEmbankment{84.0f, 0.3f, 5.0f, 3.0f};  // low: seen over
constexpr WallMaterial kParapet{92.0f, 0.25f, 2.0f, 2.0f};    // balusters every 2 m
constexpr WallMaterial kSlab{100.0f, 0.0f, 3.2f, 4.0f};

double river_centre(const GenerationContext& ctx) {
  return 0.5 * ctx.layout.block_pitch_m;
}

// A slab block built to plan `plan` (0 or 1) inside `lot`: the same two plans recur everywhere,
// but setbacks and sizes vary from block to block, as real estates built to one plan do.
void add_slabs(World& world, const Rect& lot, int plan, Rng& rng) {
  const double w = lot.width();
  const double h = lot.height();
  if (plan == 0) {  // two long slabs, one along each street
    const double depth = rng.uniform(0.18, 0.3) * h;
    // One draw per statement: the order of a call's arguments is the compiler's choice.
    const double front_x1 = lot.x1 - rng.uniform(3.0, 12.0);
    const double front_y0 = lot.y0 + rng.uniform(3.0, 8.0);
    const double front_x0 = lot.x0 + rng.uniform(3.0, 12.0);
    add_axis_box(world, front_x0, front_y0, front_x1, lot.y0 + 4.0 + depth, kSlab);
    const double back_y1 = lot.y1 - rng.uniform(3.0, 8.0);
    const double back_x1 = lot.x1 - rng.uniform(3.0, 20.0);
    const double back_x0 = lot.x0 + rng.uniform(3.0, 20.0);
    add_axis_box(world, back_x0, lot.y1 - 4.0 - depth, back_x1, back_y1, kSlab);
  } else {  // four towers
    for (const double fx : {0.08, 0.58}) {
      for (const double fy : {0.08, 0.58}) {
        const double size = rng.uniform(0.22, 0.36);
        const double x = fx + rng.uniform(0.0, 0.34 - size + 0.04);
        const double y = fy + rng.uniform(0.0, 0.34 - size + 0.04);
        add_axis_box(world, lot.x0 + x * w, lot.y0 + y * h, lot.x0 + (x + size) * w,
                     lot.y0 + (y + size) * h, kSlab);
      }
    }
  }
}

// One bank's promenade between x0 and x1 at the water's edge `edge_y`, land towards `land`.
void add_promenade(World& world, double x0, double x1, double edge_y, double land,
                   const GenerationContext& ctx, Rng& rng) {
  add_wall(world, {x0, edge_y}, {x1, edge_y}, kEmbankment);
  // Lamps every 20 m, the same from block to block; the trees were planted at about 10 m but
  // have grown apart, some died: each bank differs in detail.
  for (double x = x0 + rng.uniform(2.0, 8.0); x < x1 - 2.0; x += rng.uniform(7.0, 15.0)) {
    if (rng.chance(0.2)) continue;
    // One draw per statement: the order of a call's arguments is the compiler's choice.
    const double crown = rng.uniform(1.6, 3.0);
    add_tree(world, {x, edge_y + land * rng.uniform(3.0, 6.0)}, crown, rng, ctx);
  }
  for (double x = x0 + 10.0; x < x1 - 2.0; x += 20.0) add_lamp(world, {x, edge_y + land * 1.5});
}

}  // namespace

void riverside_block(World& world, const GenerationContext& ctx, long long bx, long long by) {
  Rng rng(hash_key({ctx.seed, kBlockTag, key_of(bx), key_of(by)}));
  const Rect lot = block_lot(ctx, bx, by);
  const int plan = static_cast<int>(hash_key({ctx.seed, kPlanTag, key_of(bx), key_of(by)}) % 2);
  if (by != 0) {
    add_slabs(world, lot, plan, rng);
    return;
  }
  // The river block: water in the middle (it returns nothing), a promenade on each bank and a
  // row of identical slabs between the promenade and the street.
  const double half_river = 0.5 * ctx.params.river_width_m;
  const double y_c = river_centre(ctx);
  // The river runs under the bridges: the promenades stop short of the bridge abutments.
  const double x0 = lot.x0 + 3.0;
  const double x1 = lot.x1 - 3.0;
  add_promenade(world, x0, x1, y_c - half_river, -1.0, ctx, rng);
  add_promenade(world, x0, x1, y_c + half_river, 1.0, ctx, rng);
  const double bank = y_c - half_river - lot.y0;
  if (bank > 16.0) {
    // Riverfront slabs of one design, at uneven spacings and lengths.
    for (double x = lot.x0 + rng.uniform(3.0, 10.0); x + 14.0 < lot.x1;) {
      const double length = std::min(rng.uniform(14.0, 30.0), lot.x1 - 3.0 - x);
      add_axis_box(world, x, lot.y0 + 3.0, x + length, lot.y0 + 3.0 + 0.5 * (bank - 8.0), kSlab);
      x += length + rng.uniform(5.0, 14.0);
    }
    for (double x = lot.x0 + rng.uniform(3.0, 10.0); x + 14.0 < lot.x1;) {
      const double length = std::min(rng.uniform(14.0, 30.0), lot.x1 - 3.0 - x);
      add_axis_box(world, x, lot.y1 - 3.0 - 0.5 * (bank - 8.0), x + length, lot.y1 - 3.0, kSlab);
      x += length + rng.uniform(5.0, 14.0);
    }
  }
}

void riverside_street(World& world, const GenerationContext& ctx, const StreetStretch& street,
                      Rng& rng) {
  if (street.vertical && street.j == 0) {
    // A bridge: the same parapets, lamps and end pillars on every crossing of the river. It
    // carries the lanes and a footway each side, no parking.
    const double half_river = 0.5 * ctx.params.river_width_m;
    const double y_c = river_centre(ctx);
    const double y0 = y_c - half_river - 4.0;
    const double y1 = y_c + half_river + 4.0;
    for (const double side : {-1.0, 1.0}) {
      const double x = street.line + side * (street.profile.kerb_offset_m() + 1.0);
      add_wall(world, {x, y0}, {x, y1}, kParapet);
      for (double y = y0 + 2.0; y < y1; y += 8.0) add_lamp(world, {x - side * 0.3, y});
      for (const double y : {y0, y1}) {
        world.poles.push_back({{x + side * 0.8, y}, 0.7f, 96.0f, 0.3f});  // end pillars
      }
    }
    return;
  }
  std::uint64_t place = 0;
  for (const double side : {-1.0, 1.0}) {
    // Lamps at a fixed spacing, the same on every street; street trees planted at about 12 m
    // with gaps, so streets differ in detail.
    for (double s = street.lo + rng.uniform(2.0, 8.0); s < street.hi; s += rng.uniform(8.0, 18.0)) {
      if (rng.chance(0.25)) continue;
      add_street_tree(world, street, side, s, rng.uniform(1.4, 2.6), rng, ctx);
    }
    for (double s = street.lo + 10.0; s < street.hi; s += 24.0) {
      add_lamp(world, street.at(s, side * street.pavement(0.6)));
    }
    add_parking_lane(world, street, side, 6.0, rng, ctx, kPlaceTag, place);
  }
}

}  // namespace radarpr::synthetic
