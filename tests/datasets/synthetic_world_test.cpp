// The world kinds: what each generates, what changes between sessions, the identical bridges
// of the riverside and the moving vehicles.
#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "datasets/synthetic/world/traffic.hpp"
#include "datasets/synthetic/world/world_generator.hpp"
#include "datasets/synthetic/world/world_presets.hpp"

namespace radarpr::synthetic {
namespace {

World generate(std::string_view preset_name, int session, Vec2 min, Vec2 max, double churn = 0.0,
               double foliage = 1.0) {
  WorldPreset preset = world_preset(preset_name);
  preset.params.parked_car_churn = churn;
  preset.params.foliage = foliage;
  return generate_world(7, session, preset.layout, preset.params, min, max);
}

using WallKey = std::tuple<long, long, long, long>;
WallKey key_of(const WallSegment& w, double dx = 0.0, double dy = 0.0) {
  auto mm = [](double v) { return std::lround(v * 1000.0); };
  return {mm(w.a.x - dx), mm(w.a.y - dy), mm(w.b.x - dx), mm(w.b.y - dy)};
}

bool is_car(const WallSegment& w) {
  return w.transmission == 0.35f;  // kCarBody
}

TEST(SyntheticWorldKinds, EveryKindGeneratesItsOwnMix) {
  const Vec2 lo{0.0, 0.0};
  const Vec2 hi{300.0, 300.0};
  const World city = generate("city", 0, lo, hi);
  const World offroad = generate("offroad", 0, lo, hi);
  const World campus = generate("campus", 0, lo, hi);
  const World suburban = generate("suburban", 0, lo, hi);
  const World riverside = generate("riverside", 0, lo, hi);
  // Off-road is sparse: a tenth of the city's walls, and no lamps (82-unit poles).
  EXPECT_LT(offroad.walls.size() * 10, city.walls.size());
  EXPECT_GT(offroad.poles.size(), 20u);  // rocks and marker posts
  // The campus has more trees than the city (crowns, not patches of rough ground); suburbs have
  // many small houses and hedges.
  auto crowns = [](const World& world) {
    return std::count_if(world.foliage.begin(), world.foliage.end(),
                         [](const Foliage& f) { return f.attenuation_per_m >= 0.05f; });
  };
  EXPECT_GT(crowns(campus), crowns(city));
  EXPECT_GT(suburban.foliage.size(), 200u);
  EXPECT_GT(riverside.walls.size(), 100u);
}

TEST(SyntheticWorldKinds, RiversideBridgesShareOneStructure) {
  // Bridges on the vertical streets x = 0 and x = 240 (pitch 120) over the river at y = 60.
  const World world = generate("riverside", 0, {-50.0, -50.0}, {300.0, 170.0});
  // The boulevards are 34 m wide (three lanes, parking and pavement each way); the bridges
  // carry the lanes with a footway each side: parapets 14 m off the centre line.
  auto near_bridge = [](const Vec2& p, double x) {
    return std::abs(p.x - x) < 16.0 && p.y > 30.0 && p.y < 90.0;
  };
  std::set<WallKey> first;
  std::set<WallKey> second;
  for (const WallSegment& w : world.walls) {
    if (w.transmission != 0.25f) continue;  // parapets
    if (near_bridge(w.a, 0.0)) first.insert(key_of(w));
    if (near_bridge(w.a, 240.0)) second.insert(key_of(w, 240.0, 0.0));
  }
  EXPECT_EQ(first.size(), 2u);  // one parapet each side
  EXPECT_EQ(first, second);
  std::multiset<std::pair<long, long>> lamps_first;
  std::multiset<std::pair<long, long>> lamps_second;
  for (const Pole& p : world.poles) {
    const std::pair<long, long> at{std::lround(p.centre.x * 100), std::lround(p.centre.y * 100)};
    if (near_bridge(p.centre, 0.0)) lamps_first.insert(at);
    if (near_bridge(p.centre, 240.0)) lamps_second.insert({at.first - 24000, at.second});
  }
  EXPECT_GT(lamps_first.size(), 10u);
  EXPECT_EQ(lamps_first, lamps_second);
  // Nothing stands in the water between the promenades (y in (45, 75)) away from the bridges.
  for (const WallSegment& w : world.walls) {
    const bool in_water = w.a.y > 45.0 && w.a.y < 75.0 && std::abs(w.a.x) > 16.0 &&
                          std::abs(w.a.x - 120.0) > 16.0 && std::abs(w.a.x - 240.0) > 16.0;
    EXPECT_FALSE(in_water) << w.a.x << " " << w.a.y;
  }
}

TEST(SyntheticWorldKinds, SessionsKeepTheBuildingsAndMoveSomeCars) {
  const Vec2 lo{0.0, 0.0};
  const Vec2 hi{160.0, 80.0};
  const World base = generate("city", 0, lo, hi);
  const World same = generate("city", 3, lo, hi);        // no churn: the same cars
  const World moved = generate("city", 3, lo, hi, 0.6);  // 60 % of places redrawn
  auto walls = [](const World& w, bool cars) {
    std::set<WallKey> keys;
    for (const WallSegment& s : w.walls) {
      if (is_car(s) == cars) keys.insert(key_of(s));
    }
    return keys;
  };
  EXPECT_EQ(walls(base, false), walls(moved, false));  // buildings and fences stay
  EXPECT_EQ(walls(base, true), walls(same, true));
  const auto cars0 = walls(base, true);
  const auto cars3 = walls(moved, true);
  std::vector<WallKey> common;
  std::set_intersection(cars0.begin(), cars0.end(), cars3.begin(), cars3.end(),
                        std::back_inserter(common));
  EXPECT_GT(cars0.size(), 40u);
  EXPECT_LT(common.size(), cars0.size());      // some left
  EXPECT_GT(common.size(), cars0.size() / 4);  // many stayed
}

TEST(SyntheticWorldKinds, BareFoliageIsSmallerAndThinner) {
  const World summer = generate("campus", 0, {0.0, 0.0}, {130.0, 130.0});
  const World winter = generate("campus", 1, {0.0, 0.0}, {130.0, 130.0}, 0.0, 0.6);
  ASSERT_EQ(summer.foliage.size(), winter.foliage.size());
  int crowns = 0;
  for (std::size_t i = 0; i < summer.foliage.size(); ++i) {
    if (summer.foliage[i].attenuation_per_m < 0.05f) continue;  // rough ground: no season
    EXPECT_LT(winter.foliage[i].radius_m, summer.foliage[i].radius_m);
    EXPECT_LT(winter.foliage[i].attenuation_per_m, summer.foliage[i].attenuation_per_m);
    // 0.6 times as wide, but for street trees whose full crown is cut back clear of the lanes.
    crowns += std::abs(winter.foliage[i].radius_m - 0.6 * summer.foliage[i].radius_m) < 1e-4;
  }
  EXPECT_GT(crowns, 50);
}

TEST(SyntheticWorldKinds, VehiclesMoveAndKeepClearOfTheSensor) {
  WorldPreset preset = world_preset("campus");
  // The sensor's car eastbound in lane 0 of the street y = 0, mid-block.
  const Pose2D ego{65.0, -1.75, 0.0};
  auto traffic_at = [&](double time_s) {
    return moving_vehicles(7, 0, preset.layout, preset.params, time_s, ego, 150.0);
  };
  const World t0 = traffic_at(10.0);
  const World t1 = traffic_at(11.0);
  const World again = traffic_at(10.0);
  ASSERT_GT(t0.walls.size(), 8u);
  ASSERT_EQ(t0.walls.size(), again.walls.size());
  for (std::size_t i = 0; i < t0.walls.size(); ++i)
    EXPECT_EQ(key_of(t0.walls[i]), key_of(again.walls[i]));
  int moved = 0;
  for (std::size_t i = 0; i < std::min(t0.walls.size(), t1.walls.size()); ++i) {
    moved += key_of(t0.walls[i]) != key_of(t1.walls[i]);
  }
  EXPECT_GT(moved, 0);
  // Vehicles drive in the lane centres of their direction: 1.75 or 5.25 m off the centre line.
  std::set<long> lanes;
  for (std::size_t i = 0; i + 3 < t0.walls.size(); i += 4) {
    const Vec2 c{0.5 * (t0.walls[i].a.x + t0.walls[i + 2].a.x),
                 0.5 * (t0.walls[i].a.y + t0.walls[i + 2].a.y)};
    const double across =
        std::min(std::abs(std::remainder(c.x, 130.0)), std::abs(std::remainder(c.y, 130.0)));
    lanes.insert(std::lround(across * 100.0));
  }
  EXPECT_EQ(lanes, (std::set<long>{175, 525}));
  // Over a minute of traffic none touches the sensor's car (4.5 m x 1.9 m around the sensor): a
  // side of a vehicle box never comes within a metre of the sensor.
  for (double time_s = 0.0; time_s < 60.0; time_s += 0.25) {
    for (const WallSegment& w : traffic_at(time_s).walls) {
      const double ex = w.b.x - w.a.x;
      const double ey = w.b.y - w.a.y;
      const double t =
          std::clamp(((ego.x - w.a.x) * ex + (ego.y - w.a.y) * ey) / (ex * ex + ey * ey), 0.0, 1.0);
      EXPECT_GT(std::hypot(w.a.x + t * ex - ego.x, w.a.y + t * ey - ego.y), 1.0) << time_s;
    }
  }
  preset.params.traffic = 0.0;
  EXPECT_TRUE(traffic_at(10.0).walls.empty());
}

TEST(SyntheticWorldKinds, StreetFurnitureStandsOnThePavement) {
  // City streets: lanes to 7 m from the centre line, parking lane to the kerb at 9.5 m, then
  // 3.5 m of pavement. Poles (lamps, signs, trunks, traffic lights) stand beyond the kerb; the
  // only walls inside it are parked cars, in the parking lane.
  const WorldPreset preset = world_preset("city");
  const World world = generate("city", 0, {0.0, 0.0}, {160.0, 80.0});
  auto across = [](const Vec2& p) {
    return std::min(std::abs(std::remainder(p.x, 80.0)), std::abs(std::remainder(p.y, 80.0)));
  };
  const double lanes = preset.layout.street.carriageway_half_m();
  const double kerb = preset.layout.street.kerb_offset_m();
  EXPECT_EQ(lanes, 7.0);
  EXPECT_EQ(kerb, 9.5);
  int poles = 0;
  for (const Pole& p : world.poles) {
    ++poles;
    EXPECT_GE(across(p.centre) - p.radius_m, kerb) << p.centre.x << " " << p.centre.y;
  }
  EXPECT_GT(poles, 50);
  int cars = 0;
  for (const WallSegment& w : world.walls) {
    if (across(w.a) >= kerb - 1e-9) continue;
    ASSERT_TRUE(is_car(w)) << w.a.x << " " << w.a.y;
    ++cars;
    EXPECT_GT(across(w.a), lanes) << w.a.x << " " << w.a.y;
  }
  EXPECT_GT(cars, 40);
  // Crowns of street trees may overhang the parking lane, not the lanes.
  for (const Foliage& f : world.foliage) {
    EXPECT_GE(across(f.centre) - f.radius_m, lanes + 1.0 - 1e-9) << f.centre.x << " " << f.centre.y;
  }
}

TEST(SyntheticWorldKinds, UnknownNamesAreRefused) {
  EXPECT_THROW(world_preset("moon"), std::invalid_argument);
  WorldParams params;
  params.kind = WorldKind::riverside;
  params.river_width_m = 200.0;
  EXPECT_THROW(validate(params, world_preset("riverside").layout), std::invalid_argument);
}

}  // namespace
}  // namespace radarpr::synthetic
