#include "datasets/synthetic/world/world_presets.hpp"

namespace radarpr::synthetic {

WorldPreset world_preset(std::string_view name) {
  WorldPreset preset;
  preset.params.kind = world_kind_from(name);  // throws for an unknown name
  // Streets: {lanes each way, lane width, parking lane, pavement} (world_params.hpp).
  switch (preset.params.kind) {
    case WorldKind::city:  // 80 m blocks, two lanes each way, parking, light traffic
      preset.layout = {80.0, {2, 3.5, 2.5, 3.5}, 0.2};
      preset.params.traffic = 0.3;
      break;
    case WorldKind::suburban:  // 100 m blocks of houses, one lane each way, quiet streets
      preset.layout = {100.0, {1, 3.5, 2.3, 4.2}, 0.0};
      preset.params.parked_cars = 0.5;
      preset.params.traffic = 0.2;
      break;
    case WorldKind::campus:  // 130 m blocks, two-lane avenues each way, busy with vehicles
      preset.layout = {130.0, {2, 3.5, 2.5, 4.0}, 0.0};
      preset.params.parked_cars = 0.6;
      preset.params.traffic = 0.9;
      break;
    case WorldKind::riverside:  // 120 m blocks, three-lane boulevards, a 40 m river on row 0
      preset.layout = {120.0, {3, 3.5, 2.5, 4.0}, 0.0};
      preset.params.river_width_m = 40.0;
      preset.params.traffic = 0.3;
      break;
    case WorldKind::offroad:  // 150 m between single-lane tracks with verges, nobody about
      preset.layout = {150.0, {1, 3.5, 0.0, 1.5}, 0.0};
      preset.params.parked_cars = 0.0;
      preset.ground_clutter = 14.0;
      preset.ground_clutter_falloff_m = 80.0;
      break;
  }
  return preset;
}

}  // namespace radarpr::synthetic
