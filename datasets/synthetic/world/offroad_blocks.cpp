// Off-road terrain (OORD): single-lane tracks through open country - rocks, bushes, lone trees,
// earth banks (ridges the radar partly sees through) and the odd hut or fence. Weak and
// scattered: about 3.6 Cen features per azimuth with the CIR204-H preset (1.2 within 100 m),
// fewer than any of the real urban samples (6.4 - 9.0; 2.3 - 4.8 within 100 m), as OORD's open
// moorland is sparser than a town.
#include <cmath>
#include <numbers>

#include "datasets/synthetic/world/world_kinds.hpp"

namespace radarpr::synthetic {
namespace {

enum Tag : std::uint64_t { kBlockTag = 71 };

constexpr WallMaterial kRidge{70.0f, 0.55f, 0.0f, 9.0f};  // earth bank: weak, blotchy, partial
constexpr WallMaterial kHut{96.0f, 0.0f, 0.0f, 5.0f};

}  // namespace

void offroad_block(World& world, const GenerationContext& ctx, long long bx, long long by) {
  Rng rng(hash_key({ctx.seed, kBlockTag, key_of(bx), key_of(by)}));
  const Rect lot = block_lot(ctx, bx, by);
  auto somewhere = [&](double margin) {
    return Vec2{rng.uniform(lot.x0 + margin, lot.x1 - margin),
                rng.uniform(lot.y0 + margin, lot.y1 - margin)};
  };
  const int rocks = rng.uniform_int(24, 44);
  for (int k = 0; k < rocks; ++k) {
    world.poles.push_back({somewhere(2.0), static_cast<float>(rng.uniform(0.4, 1.5)),
                           static_cast<float>(rng.uniform(68.0, 84.0)), 0.4f});
  }
  const int bushes = rng.uniform_int(20, 36);
  for (int k = 0; k < bushes; ++k) {
    world.foliage.push_back({somewhere(3.0),
                             static_cast<float>(rng.uniform(1.0, 3.0) * ctx.params.foliage),
                             static_cast<float>(rng.uniform(40.0, 48.0)), 0.5f});
  }
  const int trees = rng.uniform_int(2, 7);
  for (int k = 0; k < trees; ++k) {
    // One draw per statement: the order of a call's arguments is the compiler's choice.
    const double crown = rng.uniform(2.0, 4.0);
    add_tree(world, somewhere(4.0), crown, rng, ctx);
  }
  const int ridges = rng.uniform_int(1, 4);
  for (int k = 0; k < ridges; ++k) {
    const Vec2 a = somewhere(5.0);
    const double heading = rng.uniform(0.0, std::numbers::pi);
    const double length = rng.uniform(20.0, 60.0);
    // A curved bank in three slightly bent pieces, ending where it would reach the track.
    Vec2 from = a;
    double direction = heading;
    for (int piece = 0; piece < 3; ++piece) {
      const Vec2 to{from.x + length / 3.0 * std::cos(direction),
                    from.y + length / 3.0 * std::sin(direction)};
      direction += rng.normal(0.0, 0.25);
      if (to.x < lot.x0 + 2.0 || to.x > lot.x1 - 2.0 || to.y < lot.y0 + 2.0 ||
          to.y > lot.y1 - 2.0) {
        continue;  // draws stay the same whether or not the piece is there
      }
      add_wall(world, from, to, kRidge);
      from = to;
    }
  }
  if (rng.chance(0.3)) {
    const Vec2 at = somewhere(10.0);
    const double yaw = rng.uniform(0.0, 3.0);
    const double width = rng.uniform(4.0, 6.0);
    const double length = rng.uniform(5.0, 9.0);
    add_box(world, at, length, width, yaw, kHut);
  }
  if (rng.chance(0.25)) {
    const double y = rng.uniform(lot.y0 + 5.0, lot.y1 - 5.0);
    add_fence(world, {lot.x0 + 1.0, y}, {lot.x1 - 1.0, y}, rng);
  }
}

void offroad_street(World& world, const GenerationContext& /*ctx*/, const StreetStretch& street,
                    Rng& rng) {
  // Marker posts now and then, and a gate with its posts at a third of the tracks.
  for (double s = street.lo + rng.uniform(0.0, 60.0); s < street.hi; s += rng.uniform(50.0, 90.0)) {
    const double side = rng.chance(0.5) ? 1.0 : -1.0;
    world.poles.push_back({street.at(s, side * street.pavement(0.5)), 0.08f, 68.0f, 0.95f});
  }
  if (rng.chance(0.33)) {
    const double s = rng.uniform(street.lo, street.hi);
    for (const double side : {-1.0, 1.0}) {
      world.poles.push_back(
          {street.at(s, side * street.profile.half_width_m()), 0.15f, 84.0f, 0.9f});
    }
  }
}

}  // namespace radarpr::synthetic
