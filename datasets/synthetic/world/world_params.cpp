#include "datasets/synthetic/world/world_params.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "datasets/synthetic/require.hpp"

namespace radarpr::synthetic {
namespace {

constexpr std::array<std::pair<WorldKind, std::string_view>, 5> kKinds = {{
    {WorldKind::city, "city"},
    {WorldKind::suburban, "suburban"},
    {WorldKind::campus, "campus"},
    {WorldKind::riverside, "riverside"},
    {WorldKind::offroad, "offroad"},
}};

constexpr std::string_view kCity = "synthetic city";
constexpr std::string_view kWorld = "synthetic world";

bool in_range(double value, double low, double high) {
  return std::isfinite(value) && value >= low && value <= high;
}

}  // namespace

void validate(const CityLayout& layout) {
  const StreetProfile& street = layout.street;
  require(street.lanes_per_direction >= 1 && street.lanes_per_direction <= 4, kCity,
          "lanes_per_direction", street.lanes_per_direction, "in [1, 4]");
  require(in_range(street.lane_width_m, 2.5, 4.5), kCity, "lane_width_m", street.lane_width_m,
          "in [2.5, 4.5]");
  require(in_range(street.parking_width_m, 0.0, 3.5), kCity, "parking_width_m",
          street.parking_width_m, "in [0, 3.5] (0: no parking lane)");
  require(in_range(street.pavement_width_m, 1.0, 10.0), kCity, "pavement_width_m",
          street.pavement_width_m, "in [1, 10]");
  const double street_width = layout.street_width_m();
  require(in_range(layout.block_pitch_m, street_width + 20.0, 1000.0), kCity, "block_pitch_m",
          layout.block_pitch_m,
          fmt::format("in [{}, 1000] (the street's {} m plus 20 m for buildings)",
                      street_width + 20.0, street_width));
  require(in_range(layout.park_fraction, 0.0, 1.0), kCity, "park_fraction", layout.park_fraction,
          "in [0, 1]");
}

std::string_view to_string(WorldKind kind) {
  for (const auto& [k, name] : kKinds) {
    if (k == kind) return name;
  }
  return "?";
}

WorldKind world_kind_from(std::string_view name) {
  for (const auto& [kind, known] : kKinds) {
    if (known == name) return kind;
  }
  throw std::invalid_argument(fmt::format(
      "synthetic world: unknown kind '{}', expected city, suburban, campus, riverside or offroad",
      name));
}

void validate(const WorldParams& params, const CityLayout& layout) {
  require(in_range(params.parked_cars, 0.0, 1.0), kWorld, "parked_cars", params.parked_cars,
          "in [0, 1]");
  require(in_range(params.parked_car_churn, 0.0, 1.0), kWorld, "parked_car_churn",
          params.parked_car_churn, "in [0, 1]");
  require(in_range(params.foliage, 0.2, 2.0), kWorld, "foliage", params.foliage, "in [0.2, 2]");
  require(in_range(params.traffic, 0.0, 5.0), kWorld, "traffic", params.traffic, "in [0, 5]");
  if (params.kind != WorldKind::riverside) return;
  const double room = layout.block_pitch_m - layout.street_width_m() - 20.0;
  require(in_range(params.river_width_m, 10.0, room), kWorld, "river_width_m", params.river_width_m,
          fmt::format("in [10, {}] (the block minus its streets and two 10 m banks)", room));
}

}  // namespace radarpr::synthetic
