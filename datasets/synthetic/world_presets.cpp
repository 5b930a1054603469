#include "datasets/synthetic/world_presets.hpp"

namespace radarpr::synthetic {

WorldPreset world_preset(std::string_view name) {
  WorldPreset preset;
  preset.params.kind = world_kind_from(name);  // throws for an unknown name
  switch (preset.params.kind) {
    case WorldKind::city:  // 80 m blocks, light traffic
      preset.params.traffic = 0.3;
      break;
    case WorldKind::suburban:  // 100 m blocks of houses, quiet streets
      preset.layout = {100.0, 16.0, 0.0};
      preset.params.parked_cars = 0.5;
      preset.params.traffic = 0.2;
      break;
    case WorldKind::campus:  // 130 m blocks of lawn and trees, busy with vehicles
      preset.layout = {130.0, 20.0, 0.0};
      preset.params.parked_cars = 0.6;
      preset.params.traffic = 0.9;
      break;
    case WorldKind::riverside:  // 120 m blocks, a 40 m river along row 0
      preset.layout = {120.0, 18.0, 0.0};
      preset.params.river_width_m = 40.0;
      preset.params.traffic = 0.3;
      break;
    case WorldKind::offroad:  // 150 m between tracks, rough ground, nobody about
      preset.layout = {150.0, 10.0, 0.0};
      preset.params.parked_cars = 0.0;
      preset.ground_clutter = 14.0;
      preset.ground_clutter_falloff_m = 80.0;
      break;
  }
  return preset;
}

}  // namespace radarpr::synthetic
