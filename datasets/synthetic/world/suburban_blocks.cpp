// Suburbs: detached houses set back in gardens, hedges and fences along the street, trees,
// cars in driveways and along the kerb.
#include <cmath>
#include <numbers>

#include "datasets/synthetic/world/world_kinds.hpp"

namespace radarpr::synthetic {
namespace {

enum Tag : std::uint64_t { kBlockTag = 41, kPlaceTag = 43 };

constexpr WallMaterial kHouse{94.0f, 0.0f, 3.0f, 7.0f};

// A hedge: a row of small overlapping crowns.
void add_hedge(World& world, Vec2 a, Vec2 b, const GenerationContext& ctx) {
  const double length = std::hypot(b.x - a.x, b.y - a.y);
  const int pieces = std::max(1, static_cast<int>(length / 1.6));
  for (int k = 0; k < pieces; ++k) {
    const double f = (k + 0.5) / pieces;
    world.foliage.push_back({{a.x + f * (b.x - a.x), a.y + f * (b.y - a.y)},
                             static_cast<float>(0.9 * ctx.params.foliage),
                             46.0f,
                             0.6f});
  }
}

// One garden plot, its front on the street below it (`street_at_bottom`) or above it.
void add_plot(World& world, const Rect& plot, bool street_at_bottom, Rng& rng,
              const GenerationContext& ctx, std::uint64_t place_key) {
  const double setback = rng.uniform(5.0, 9.0);
  const double depth = rng.uniform(8.0, 11.0);
  const double width = std::min(plot.width() - 4.0, rng.uniform(8.0, 12.0));
  const double cx = 0.5 * (plot.x0 + plot.x1) + rng.uniform(-1.5, 1.5);
  const double y_front = street_at_bottom ? plot.y0 + setback : plot.y1 - setback;
  const double y_back = street_at_bottom ? y_front + depth : y_front - depth;
  WallMaterial material = kHouse;
  material.strength = static_cast<float>(rng.uniform(88.0, 100.0));
  add_axis_box(world, cx - width / 2, std::min(y_front, y_back), cx + width / 2,
               std::max(y_front, y_back), material);
  const double edge = street_at_bottom ? plot.y0 + 0.5 : plot.y1 - 0.5;
  const double roll = rng.uniform();
  if (roll < 0.4) {
    add_hedge(world, {plot.x0 + 0.5, edge}, {plot.x1 - 3.5, edge}, ctx);
  } else if (roll < 0.7) {
    add_fence(world, {plot.x0, edge}, {plot.x1 - 3.0, edge}, rng);
  }
  // The driveway car, beside the house.
  add_parked_car(world, {plot.x1 - 1.8, 0.5 * (edge + y_front)}, std::numbers::pi / 2.0, rng, ctx,
                 place_key);
  const int trees = rng.uniform_int(0, 2);
  for (int k = 0; k < trees; ++k) {
    const double crown = rng.uniform(1.5, 3.0);
    const double ty = street_at_bottom ? rng.uniform(y_back + 1.0, plot.y1 - 1.0)
                                       : rng.uniform(plot.y0 + 1.0, y_back - 1.0);
    add_tree(world, {rng.uniform(plot.x0 + 1.0, plot.x1 - 1.0), ty}, crown, rng, ctx);
  }
}

}  // namespace

void suburban_block(World& world, const GenerationContext& ctx, long long bx, long long by) {
  Rng rng(hash_key({ctx.seed, kBlockTag, key_of(bx), key_of(by)}));
  const Rect lot = block_lot(ctx, bx, by);
  // Two rows of plots back to back: the south row faces the south street, the north row the
  // north one.
  const double middle = 0.5 * (lot.y0 + lot.y1);
  const int plots = std::max(2, static_cast<int>(lot.width() / rng.uniform(17.0, 22.0)));
  const std::vector<double> xs = split(lot.x0, lot.x1, plots, rng);
  std::uint64_t place = 0;
  for (int k = 0; k < plots; ++k) {
    const auto x0 = xs[static_cast<std::size_t>(k)];
    const auto x1 = xs[static_cast<std::size_t>(k + 1)];
    const std::uint64_t block_key = hash_key({ctx.seed, kPlaceTag, key_of(bx), key_of(by)});
    add_plot(world, {x0, lot.y0, x1, middle}, true, rng, ctx, hash_key({block_key, place++}));
    add_plot(world, {x0, middle, x1, lot.y1}, false, rng, ctx, hash_key({block_key, place++}));
  }
}

void suburban_street(World& world, const GenerationContext& ctx, const StreetStretch& street,
                     Rng& rng) {
  std::uint64_t place = 0;
  for (const double side : {-1.0, 1.0}) {
    // Trees on the verge, lamps now and then, cars along the kerb.
    const double spacing = rng.uniform(9.0, 14.0);
    if (rng.chance(0.75)) {
      for (double s = street.lo + rng.uniform(0.0, spacing); s < street.hi;
           s += spacing * rng.uniform(0.8, 1.2)) {
        add_street_tree(world, street, side, s, rng.uniform(1.5, 2.8), rng, ctx);
      }
    }
    for (double s = street.lo + rng.uniform(0.0, 30.0); s < street.hi; s += rng.uniform(28, 36)) {
      add_lamp(world, street.at(s, side * street.pavement(0.6)));
    }
    add_parking_lane(world, street, side, 6.5, rng, ctx, kPlaceTag, place);
  }
}

}  // namespace radarpr::synthetic
