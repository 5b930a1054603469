#include "datasets/synthetic/world/world_kinds.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include "datasets/synthetic/random.hpp"
#include "datasets/synthetic/world/world_parts.hpp"

namespace radarpr::synthetic {
namespace {

// Tags keep the random streams of blocks, streets and crossings with equal indices apart.
enum Tag : std::uint64_t { kBlockTag = 1, kCrossingTag = 3, kPlaceTag = 4 };

constexpr WallMaterial kShelter{84.0f, 0.6f, 1.2f, 4.0f};  // glass panes in a steel frame

// Which sides of a parcel face a street (and get a shorter, street-style setback).
struct Frontage {
  bool left = false, right = false, bottom = false, top = false;
  bool any() const { return left || right || bottom || top; }
};

void add_building(World& world, const Rect& parcel, const Frontage& front, Rng& rng) {
  auto inset = [&rng](bool street) {
    return street ? rng.uniform(0.3, 5.0) : rng.uniform(0.8, 3.5);
  };
  const Rect r{parcel.x0 + inset(front.left), parcel.y0 + inset(front.bottom),
               parcel.x1 - inset(front.right), parcel.y1 - inset(front.top)};
  if (r.width() < 5.0 || r.height() < 5.0) return;
  const WallMaterial material = facade(rng);
  if (r.width() > 14.0 && r.height() > 14.0 && rng.chance(0.25)) {
    // L-shaped: two overlapping boxes; their inner walls are hidden inside the union.
    const double notch_x = r.width() * rng.uniform(0.35, 0.6);
    const double notch_y = r.height() * rng.uniform(0.35, 0.6);
    const bool notch_right = rng.chance(0.5);
    const bool notch_top = rng.chance(0.5);
    const double cut_y = notch_top ? r.y1 - notch_y : r.y0 + notch_y;
    const double cut_x = notch_right ? r.x1 - notch_x : r.x0 + notch_x;
    add_axis_box(world, r.x0, notch_top ? r.y0 : cut_y, r.x1, notch_top ? cut_y : r.y1, material);
    add_axis_box(world, notch_right ? r.x0 : cut_x, r.y0, notch_right ? cut_x : r.x1, r.y1,
                 material);
    return;
  }
  add_axis_box(world, r.x0, r.y0, r.x1, r.y1, material);
}

void add_parking(World& world, const Rect& parcel, Rng& rng, const GenerationContext& ctx,
                 std::uint64_t parcel_key) {
  std::uint64_t place = 0;
  const Rect r{parcel.x0 + 2.0, parcel.y0 + 2.0, parcel.x1 - 2.0, parcel.y1 - 2.0};
  // Rows of cars parked nose to the aisle: 2.7 m per car across, 6.5 m per row.
  for (double y = r.y0 + 2.5; y + 2.5 <= r.y1; y += 6.5) {
    for (double x = r.x0 + 1.2; x + 1.2 <= r.x1; x += 2.7) {
      add_parked_car(world, {x, y}, std::numbers::pi / 2.0, rng, ctx,
                     hash_key({parcel_key, kPlaceTag, place++}));
    }
  }
  const int lamps = rng.uniform_int(1, 2);
  for (int i = 0; i < lamps; ++i) {
    add_lamp(world, {rng.uniform(r.x0, r.x1), rng.uniform(r.y0, r.y1)});
  }
}

void add_yard(World& world, const Rect& parcel, const Frontage& front, Rng& rng,
              const GenerationContext& ctx) {
  const int trees = rng.uniform_int(1, 4);
  for (int i = 0; i < trees; ++i) {
    const double crown = rng.uniform(1.5, 3.5);
    if (parcel.width() <= 2.0 * crown || parcel.height() <= 2.0 * crown) continue;
    add_tree(world,
             {rng.uniform(parcel.x0 + crown, parcel.x1 - crown),
              rng.uniform(parcel.y0 + crown, parcel.y1 - crown)},
             crown, rng, ctx);
  }
  if (front.any() && rng.chance(0.5)) {
    const double in = 0.3;
    if (front.bottom)
      add_fence(world, {parcel.x0, parcel.y0 + in}, {parcel.x1, parcel.y0 + in}, rng);
    if (front.top) add_fence(world, {parcel.x0, parcel.y1 - in}, {parcel.x1, parcel.y1 - in}, rng);
    if (front.left) add_fence(world, {parcel.x0 + in, parcel.y0}, {parcel.x0 + in, parcel.y1}, rng);
    if (front.right)
      add_fence(world, {parcel.x1 - in, parcel.y0}, {parcel.x1 - in, parcel.y1}, rng);
  }
}

void add_park(World& world, const Rect& lot, Rng& rng, const GenerationContext& ctx) {
  const int trees = rng.uniform_int(10, 24);
  for (int i = 0; i < trees; ++i) {
    const double crown = rng.uniform(1.5, 4.0);
    add_tree(world,
             {rng.uniform(lot.x0 + 3.0, lot.x1 - 3.0), rng.uniform(lot.y0 + 3.0, lot.y1 - 3.0)},
             crown, rng, ctx);
  }
  const int lamps = rng.uniform_int(2, 5);
  for (int i = 0; i < lamps; ++i) {
    add_lamp(world,
             {rng.uniform(lot.x0 + 2.0, lot.x1 - 2.0), rng.uniform(lot.y0 + 2.0, lot.y1 - 2.0)});
  }
  if (rng.chance(0.35)) {  // a pavilion
    const double w = rng.uniform(8.0, 14.0);
    const double h = rng.uniform(6.0, 10.0);
    const double cx = rng.uniform(lot.x0 + 10.0, lot.x1 - 10.0);
    const double cy = rng.uniform(lot.y0 + 10.0, lot.y1 - 10.0);
    add_axis_box(world, cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2, facade(rng));
  }
  if (rng.chance(0.5)) {
    add_fence(world, {lot.x0 + 0.5, lot.y0 + 0.5}, {lot.x1 - 0.5, lot.y0 + 0.5}, rng);
    add_fence(world, {lot.x1 - 0.5, lot.y0 + 0.5}, {lot.x1 - 0.5, lot.y1 - 0.5}, rng);
    add_fence(world, {lot.x1 - 0.5, lot.y1 - 0.5}, {lot.x0 + 0.5, lot.y1 - 0.5}, rng);
    add_fence(world, {lot.x0 + 0.5, lot.y1 - 0.5}, {lot.x0 + 0.5, lot.y0 + 0.5}, rng);
  }
}

}  // namespace

void city_block(World& world, const GenerationContext& ctx, long long bx, long long by) {
  Rng rng(hash_key({ctx.seed, kBlockTag, key_of(bx), key_of(by)}));
  const Rect lot = block_lot(ctx, bx, by);
  if (rng.chance(ctx.layout.park_fraction)) {
    add_park(world, lot, rng, ctx);
    return;
  }
  // A built block: a grid of 2-3 x 2-3 parcels, each a building, a car park or a yard.
  const int nx = rng.uniform_int(2, 3);
  const int ny = rng.uniform_int(2, 3);
  const std::vector<double> xs = split(lot.x0, lot.x1, nx, rng);
  const std::vector<double> ys = split(lot.y0, lot.y1, ny, rng);
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j) {
      const Rect parcel{xs[static_cast<std::size_t>(i)], ys[static_cast<std::size_t>(j)],
                        xs[static_cast<std::size_t>(i + 1)], ys[static_cast<std::size_t>(j + 1)]};
      const Frontage front{i == 0, i == nx - 1, j == 0, j == ny - 1};
      const double roll = rng.uniform();
      if (!front.any() && roll >= 0.5) {
        add_yard(world, parcel, front, rng, ctx);  // inner parcels: half courtyards
      } else if (!front.any() || roll < 0.72) {
        add_building(world, parcel, front, rng);
      } else if (roll < 0.85) {
        add_parking(world, parcel, rng, ctx,
                    hash_key({ctx.seed, kBlockTag, key_of(bx), key_of(by), key_of(i * 4 + j)}));
      } else {
        add_yard(world, parcel, front, rng, ctx);
      }
    }
  }
}

void city_street(World& world, const GenerationContext& ctx, const StreetStretch& street,
                 Rng& rng) {
  std::uint64_t place = 0;
  for (const double side : {-1.0, 1.0}) {
    // On the pavement: lamps, street trees, signs; cars along the kerb on some streets.
    if (rng.chance(0.8)) {
      const double spacing = rng.uniform(18.0, 32.0);
      for (double s = street.lo + rng.uniform(0.0, spacing); s < street.hi;
           s += spacing * rng.uniform(0.9, 1.1)) {
        add_lamp(world, street.at(s, side * street.pavement(0.6)));
      }
    }
    if (rng.chance(0.5)) {
      const double spacing = rng.uniform(7.0, 12.0);
      for (double s = street.lo + rng.uniform(0.0, spacing); s < street.hi;
           s += spacing * rng.uniform(0.85, 1.15)) {
        add_street_tree(world, street, side, s, rng.uniform(1.2, 2.2), rng, ctx);
      }
    }
    if (rng.chance(0.75)) add_parking_lane(world, street, side, 6.0, rng, ctx, kPlaceTag, place);
    const int signs = rng.uniform_int(1, 4);
    for (int k = 0; k < signs; ++k) {
      world.poles.push_back(
          {street.at(rng.uniform(street.lo, street.hi), side * street.pavement(0.4)),
           static_cast<float>(rng.uniform(0.05, 0.1)), static_cast<float>(rng.uniform(66.0, 76.0)),
           0.95f});
    }
    // Bins, bollards, cabinets and bike racks along the pavement.
    const int clutter = rng.uniform_int(2, 6);
    for (int k = 0; k < clutter; ++k) {
      // One draw per statement: the order of a call's arguments is the compiler's choice.
      const double out = rng.uniform(0.4, 1.2);
      const double along = rng.uniform(street.lo, street.hi);
      world.poles.push_back({street.at(along, side * street.pavement(out)),
                             static_cast<float>(rng.uniform(0.2, 0.45)),
                             static_cast<float>(rng.uniform(62.0, 76.0)), 0.7f});
    }
    if (rng.chance(0.3)) {  // a bus shelter: glass walls that let most through
      const double s = rng.uniform(street.lo + 3.0, street.hi - 3.0);
      add_box(world, street.at(s, side * street.pavement(1.6)), 4.0, 1.6, street.yaw, kShelter);
    }
  }
}

void crossing_lights(World& world, const GenerationContext& ctx, long long i, long long j) {
  Rng rng(hash_key({ctx.seed, kCrossingTag, key_of(i), key_of(j)}));
  if (!rng.chance(0.5)) return;
  // Traffic lights on the four corners of the pavement.
  const double corner = ctx.layout.street.kerb_offset_m() + 0.8;
  const Vec2 centre{static_cast<double>(i) * ctx.layout.block_pitch_m,
                    static_cast<double>(j) * ctx.layout.block_pitch_m};
  for (const double sx : {-1.0, 1.0}) {
    for (const double sy : {-1.0, 1.0}) {
      world.poles.push_back({{centre.x + sx * corner, centre.y + sy * corner}, 0.15f, 86.0f, 0.9f});
    }
  }
}

}  // namespace radarpr::synthetic
