// A riverside town (MulRan Riverside): a river along block row 0 crossed by bridges that all
// share one structure, promenades with trees at a fixed spacing, and slab blocks built to a few
// repeated plans: places that look alike.
#include <cmath>
#include <numbers>

#include "datasets/synthetic/world_kinds.hpp"

namespace radarpr::synthetic {
namespace {

enum Tag : std::uint64_t { kBlockTag = 61, kStreetTag = 62, kPlaceTag = 63, kPlanTag = 64 };

constexpr WallMaterial kEmbankment{84.0f, 0.3f, 5.0f, 3.0f};  // low: seen over
constexpr WallMaterial kParapet{92.0f, 0.25f, 2.0f, 2.0f};    // balusters every 2 m
constexpr WallMaterial kSlab{100.0f, 0.0f, 3.2f, 4.0f};

double river_centre(const GenerationContext& ctx) {
  return 0.5 * ctx.layout.block_pitch_m;
}

// A slab block built to plan `plan` (0 or 1) inside `lot`: the same plans recur everywhere.
void add_slabs(World& world, const Rect& lot, int plan) {
  const double w = lot.width();
  const double h = lot.height();
  if (plan == 0) {  // two long slabs, one along each street
    add_axis_box(world, lot.x0 + 4.0, lot.y0 + 4.0, lot.x1 - 4.0, lot.y0 + 4.0 + 0.25 * h, kSlab);
    add_axis_box(world, lot.x0 + 4.0, lot.y1 - 4.0 - 0.25 * h, lot.x1 - 4.0, lot.y1 - 4.0, kSlab);
  } else {  // four towers
    for (const double fx : {0.08, 0.58}) {
      for (const double fy : {0.08, 0.58}) {
        add_axis_box(world, lot.x0 + fx * w, lot.y0 + fy * h, lot.x0 + (fx + 0.34) * w,
                     lot.y0 + (fy + 0.34) * h, kSlab);
      }
    }
  }
}

// One bank's promenade between x0 and x1 at the water's edge `edge_y`, land towards `land`.
void add_promenade(World& world, double x0, double x1, double edge_y, double land,
                   const GenerationContext& ctx, Rng& rng) {
  world.walls.push_back({{x0, edge_y},
                         {x1, edge_y},
                         kEmbankment.strength,
                         kEmbankment.transmission,
                         kEmbankment.texture_period_m,
                         kEmbankment.scatter_units});
  // Trees every 10 m and lamps every 20 m, aligned to the block: the same from block to block.
  for (double x = x0 + 5.0; x < x1 - 2.0; x += 10.0) {
    add_tree(world, {x, edge_y + land * 4.0}, 2.2, rng, ctx);
  }
  for (double x = x0 + 10.0; x < x1 - 2.0; x += 20.0) add_lamp(world, {x, edge_y + land * 1.5});
}

}  // namespace

void riverside_block(World& world, const GenerationContext& ctx, long long bx, long long by) {
  Rng rng(hash_key({ctx.seed, kBlockTag, key_of(bx), key_of(by)}));
  const Rect lot = block_lot(ctx, bx, by);
  const int plan = static_cast<int>(hash_key({ctx.seed, kPlanTag, key_of(bx), key_of(by)}) % 2);
  if (by != 0) {
    add_slabs(world, lot, plan);
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
    for (double x = lot.x0 + 6.0; x + 24.0 < lot.x1; x += 32.0) {
      add_axis_box(world, x, lot.y0 + 3.0, x + 24.0, lot.y0 + 3.0 + 0.5 * (bank - 8.0), kSlab);
      add_axis_box(world, x, lot.y1 - 3.0 - 0.5 * (bank - 8.0), x + 24.0, lot.y1 - 3.0, kSlab);
    }
  }
}

void riverside_street(World& world, const GenerationContext& ctx, bool vertical, long long i,
                      long long j) {
  const StreetStretch street = street_stretch(ctx, vertical, i, j);
  Rng rng(street.key(kStreetTag));
  if (vertical && j == 0) {
    // A bridge: the same parapets, lamps and end pillars on every crossing of the river.
    const double half_river = 0.5 * ctx.params.river_width_m;
    const double y_c = river_centre(ctx);
    const double y0 = y_c - half_river - 4.0;
    const double y1 = y_c + half_river + 4.0;
    for (const double side : {-1.0, 1.0}) {
      const double x = street.line + side * 7.5;
      world.walls.push_back({{x, y0},
                             {x, y1},
                             kParapet.strength,
                             kParapet.transmission,
                             kParapet.texture_period_m,
                             kParapet.scatter_units});
      for (double y = y0 + 2.0; y < y1; y += 8.0) add_lamp(world, {x - side * 0.3, y});
      for (const double y : {y0, y1}) {
        world.poles.push_back({{x + side * 0.8, y}, 0.7f, 96.0f, 0.3f});  // end pillars
      }
    }
    return;
  }
  std::uint64_t place = 0;
  for (const double side : {-1.0, 1.0}) {
    // Trees and lamps at fixed spacings, the same on every street.
    for (double s = street.lo + 4.0; s < street.hi; s += 12.0) {
      add_tree(world, street.at(s, side * (street.half_width - 1.0)), 1.8, rng, ctx);
    }
    for (double s = street.lo + 10.0; s < street.hi; s += 24.0) {
      add_lamp(world, street.at(s, side * (street.half_width - 1.8)));
    }
    for (double s = street.lo + 3.0; s + 3.0 < street.hi; s += 6.0) {
      add_parked_car(world, street.at(s, side * (street.half_width - 4.0)), street.yaw, rng, ctx,
                     hash_key({street.key(kPlaceTag), place++}));
    }
  }
}

}  // namespace radarpr::synthetic
