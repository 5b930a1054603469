#include "datasets/synthetic/world_params.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

namespace radarpr::synthetic {
namespace {

constexpr std::array<std::pair<WorldKind, std::string_view>, 5> kKinds = {{
    {WorldKind::city, "city"},
    {WorldKind::suburban, "suburban"},
    {WorldKind::campus, "campus"},
    {WorldKind::riverside, "riverside"},
    {WorldKind::offroad, "offroad"},
}};

void require(bool condition, const char* field, double value, const std::string& expected) {
  if (!condition) {
    throw std::invalid_argument(
        fmt::format("synthetic world: {} = {} is invalid, expected {}", field, value, expected));
  }
}

}  // namespace

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

void validate(const WorldParams& params, double block_pitch_m, double street_width_m) {
  require(params.parked_cars >= 0.0 && params.parked_cars <= 1.0, "parked_cars", params.parked_cars,
          "in [0, 1]");
  require(params.parked_car_churn >= 0.0 && params.parked_car_churn <= 1.0, "parked_car_churn",
          params.parked_car_churn, "in [0, 1]");
  require(params.foliage >= 0.2 && params.foliage <= 2.0, "foliage", params.foliage, "in [0.2, 2]");
  require(params.traffic >= 0.0 && params.traffic <= 5.0, "traffic", params.traffic, "in [0, 5]");
  if (params.kind != WorldKind::riverside) return;
  const double room = block_pitch_m - street_width_m - 20.0;
  require(std::isfinite(params.river_width_m) && params.river_width_m >= 10.0 &&
              params.river_width_m <= room,
          "river_width_m", params.river_width_m,
          fmt::format("in [10, {}] (the block minus its streets and two 10 m banks)", room));
}

}  // namespace radarpr::synthetic
