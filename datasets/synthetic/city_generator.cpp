#include "datasets/synthetic/city_generator.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "datasets/synthetic/random.hpp"

namespace radarpr::synthetic {
namespace {

// Tags keep the random streams of blocks, streets and crossings with equal indices apart.
enum Tag : std::uint64_t { kBlockTag = 1, kStreetTag = 2, kCrossingTag = 3 };

constexpr WallMaterial kCarBody{90.0f, 0.35f, 0.0f,
                                3.0f};  // metal, but low: the radar sees over it
constexpr WallMaterial kFence{62.0f, 0.5f, 0.0f, 4.0f};
constexpr double kCarLength = 4.5;
constexpr double kCarWidth = 1.85;

std::uint64_t key_of(long long index) {
  return static_cast<std::uint64_t>(index);
}

struct Rect {
  double x0, y0, x1, y1;
  double width() const { return x1 - x0; }
  double height() const { return y1 - y0; }
};

// Which sides of a parcel face a street (and get a shorter, street-style setback).
struct Frontage {
  bool left = false, right = false, bottom = false, top = false;
  bool any() const { return left || right || bottom || top; }
};

WallMaterial facade(Rng& rng) {
  const auto strength = static_cast<float>(rng.uniform(92.0, 108.0));
  const auto period = static_cast<float>(rng.chance(0.7) ? rng.uniform(2.5, 4.5) : 0.0);
  return {strength, 0.0f, period, 6.0f};
}

void add_lamp(World& world, Vec2 at) {
  world.poles.push_back({at, 0.12f, 82.0f, 0.92f});
}

void add_tree(World& world, Vec2 at, double crown_radius, Rng& rng) {
  world.foliage.push_back(
      {at, static_cast<float>(crown_radius), static_cast<float>(rng.uniform(44.0, 52.0)), 0.35f});
  world.poles.push_back({at, 0.2f, 62.0f, 0.85f});  // the trunk
}

void add_car(World& world, Vec2 at, double yaw, Rng& rng) {
  add_box(world, at, kCarLength, kCarWidth, yaw + rng.normal(0.0, 0.03), kCarBody);
}

// A fence from a to b in pieces with gaps (gates, breaks).
void add_fence(World& world, Vec2 a, Vec2 b, Rng& rng) {
  const double length = std::hypot(b.x - a.x, b.y - a.y);
  double s = 0.0;
  while (s < length) {
    const double piece_end = std::min(length, s + rng.uniform(5.0, 15.0));
    world.walls.push_back(
        {{a.x + (b.x - a.x) * s / length, a.y + (b.y - a.y) * s / length},
         {a.x + (b.x - a.x) * piece_end / length, a.y + (b.y - a.y) * piece_end / length},
         kFence.strength,
         kFence.transmission,
         kFence.texture_period_m});
    s = piece_end + rng.uniform(1.0, 3.0);
  }
}

// Cut [lo, hi] into `parts` pieces of random but comparable lengths.
std::vector<double> split(double lo, double hi, int parts, Rng& rng) {
  std::vector<double> weights(static_cast<std::size_t>(parts));
  double total = 0.0;
  for (double& w : weights) total += (w = rng.uniform(0.6, 1.4));
  std::vector<double> cuts{lo};
  double acc = 0.0;
  for (const double w : weights) cuts.push_back(lo + (hi - lo) * ((acc += w) / total));
  return cuts;
}

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

void add_parking(World& world, const Rect& parcel, Rng& rng) {
  const Rect r{parcel.x0 + 2.0, parcel.y0 + 2.0, parcel.x1 - 2.0, parcel.y1 - 2.0};
  // Rows of cars parked nose to the aisle: 2.7 m per car across, 6.5 m per row.
  for (double y = r.y0 + 2.5; y + 2.5 <= r.y1; y += 6.5) {
    for (double x = r.x0 + 1.2; x + 1.2 <= r.x1; x += 2.7) {
      if (rng.chance(0.7)) add_car(world, {x, y}, std::numbers::pi / 2.0, rng);
    }
  }
  const int lamps = rng.uniform_int(1, 2);
  for (int i = 0; i < lamps; ++i) {
    add_lamp(world, {rng.uniform(r.x0, r.x1), rng.uniform(r.y0, r.y1)});
  }
}

void add_yard(World& world, const Rect& parcel, const Frontage& front, Rng& rng) {
  const int trees = rng.uniform_int(1, 4);
  for (int i = 0; i < trees; ++i) {
    const double crown = rng.uniform(1.5, 3.5);
    if (parcel.width() <= 2.0 * crown || parcel.height() <= 2.0 * crown) continue;
    add_tree(world,
             {rng.uniform(parcel.x0 + crown, parcel.x1 - crown),
              rng.uniform(parcel.y0 + crown, parcel.y1 - crown)},
             crown, rng);
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

void add_park(World& world, const Rect& lot, Rng& rng) {
  const int trees = rng.uniform_int(10, 24);
  for (int i = 0; i < trees; ++i) {
    const double crown = rng.uniform(1.5, 4.0);
    add_tree(world,
             {rng.uniform(lot.x0 + 3.0, lot.x1 - 3.0), rng.uniform(lot.y0 + 3.0, lot.y1 - 3.0)},
             crown, rng);
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

void generate_block(World& world, std::uint64_t seed, const CityLayout& layout, long long bx,
                    long long by) {
  Rng rng(hash_key({seed, kBlockTag, key_of(bx), key_of(by)}));
  const double pitch = layout.block_pitch_m;
  const double half_street = 0.5 * layout.street_width_m;
  const Rect lot{static_cast<double>(bx) * pitch + half_street,
                 static_cast<double>(by) * pitch + half_street,
                 static_cast<double>(bx + 1) * pitch - half_street,
                 static_cast<double>(by + 1) * pitch - half_street};
  if (rng.chance(layout.park_fraction)) {
    add_park(world, lot, rng);
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
        add_yard(world, parcel, front, rng);  // inner parcels: half courtyards
      } else if (!front.any() || roll < 0.72) {
        add_building(world, parcel, front, rng);
      } else if (roll < 0.85) {
        add_parking(world, parcel, rng);
      } else {
        add_yard(world, parcel, front, rng);
      }
    }
  }
}

// Street furniture of the stretch between two crossings: lamps, street trees, parked cars and
// small signs on both pavements. `along` runs between the crossings, `lateral` across.
void generate_street(World& world, std::uint64_t seed, const CityLayout& layout, bool vertical,
                     long long i, long long j) {
  Rng rng(hash_key({seed, kStreetTag, vertical ? 1u : 0u, key_of(i), key_of(j)}));
  const double pitch = layout.block_pitch_m;
  const double half_street = 0.5 * layout.street_width_m;
  const double line = static_cast<double>(vertical ? i : j) * pitch;
  const double start = static_cast<double>(vertical ? j : i) * pitch;
  const double lo = start + half_street + 1.5;
  const double hi = start + pitch - half_street - 1.5;
  const double yaw = vertical ? std::numbers::pi / 2.0 : 0.0;
  auto at = [&](double along, double lateral) {
    return vertical ? Vec2{line + lateral, along} : Vec2{along, line + lateral};
  };

  for (const double side : {-1.0, 1.0}) {
    if (rng.chance(0.8)) {
      const double spacing = rng.uniform(18.0, 32.0);
      for (double s = lo + rng.uniform(0.0, spacing); s < hi;
           s += spacing * rng.uniform(0.9, 1.1)) {
        add_lamp(world, at(s, side * (half_street - 1.5)));
      }
    }
    if (rng.chance(0.4)) {
      const double spacing = rng.uniform(7.0, 12.0);
      for (double s = lo + rng.uniform(0.0, spacing); s < hi;
           s += spacing * rng.uniform(0.85, 1.15)) {
        add_tree(world, at(s, side * (half_street - 1.0)), rng.uniform(1.2, 2.2), rng);
      }
    }
    if (rng.chance(0.5)) {
      for (double s = lo + 3.0; s + 3.0 < hi; s += 6.0) {
        if (rng.chance(0.55)) add_car(world, at(s, side * (half_street - 4.0)), yaw, rng);
      }
    }
    const int signs = rng.uniform_int(0, 3);
    for (int k = 0; k < signs; ++k) {
      world.poles.push_back({at(rng.uniform(lo, hi), side * (half_street - 0.8)),
                             static_cast<float>(rng.uniform(0.05, 0.1)),
                             static_cast<float>(rng.uniform(66.0, 76.0)), 0.95f});
    }
  }
}

void generate_crossing(World& world, std::uint64_t seed, const CityLayout& layout, long long i,
                       long long j) {
  Rng rng(hash_key({seed, kCrossingTag, key_of(i), key_of(j)}));
  if (!rng.chance(0.5)) return;
  // Traffic lights on the four corners.
  const double corner = 0.5 * layout.street_width_m - 1.2;
  const Vec2 centre{static_cast<double>(i) * layout.block_pitch_m,
                    static_cast<double>(j) * layout.block_pitch_m};
  for (const double sx : {-1.0, 1.0}) {
    for (const double sy : {-1.0, 1.0}) {
      world.poles.push_back({{centre.x + sx * corner, centre.y + sy * corner}, 0.15f, 86.0f, 0.9f});
    }
  }
}

void require(bool condition, const char* field, double value, const char* expected) {
  if (!condition) {
    throw std::invalid_argument(
        fmt::format("synthetic city: {} = {} is invalid, expected {}", field, value, expected));
  }
}

}  // namespace

void validate(const CityLayout& layout) {
  require(std::isfinite(layout.street_width_m) && layout.street_width_m >= 8.0, "street_width_m",
          layout.street_width_m, ">= 8 (two lanes and pavements)");
  require(
      std::isfinite(layout.block_pitch_m) && layout.block_pitch_m >= layout.street_width_m + 20.0,
      "block_pitch_m", layout.block_pitch_m, ">= street_width_m + 20 (room for buildings)");
  require(layout.park_fraction >= 0.0 && layout.park_fraction <= 1.0, "park_fraction",
          layout.park_fraction, "in [0, 1]");
}

World generate_city(std::uint64_t seed, const CityLayout& layout, Vec2 min, Vec2 max) {
  validate(layout);
  const double pitch = layout.block_pitch_m;
  const auto bx0 = static_cast<long long>(std::floor(min.x / pitch));
  const auto bx1 = static_cast<long long>(std::floor(max.x / pitch));
  const auto by0 = static_cast<long long>(std::floor(min.y / pitch));
  const auto by1 = static_cast<long long>(std::floor(max.y / pitch));
  World world;
  for (long long bx = bx0; bx <= bx1; ++bx) {
    for (long long by = by0; by <= by1; ++by) generate_block(world, seed, layout, bx, by);
  }
  // Streets and crossings on the block boundaries, including the far edges.
  for (long long i = bx0; i <= bx1 + 1; ++i) {
    for (long long j = by0; j <= by1 + 1; ++j) {
      if (i <= bx1) generate_street(world, seed, layout, false, i, j);
      if (j <= by1) generate_street(world, seed, layout, true, i, j);
      generate_crossing(world, seed, layout, i, j);
    }
  }
  return world;
}

}  // namespace radarpr::synthetic
