#pragma once

#include <string_view>

#include "datasets/synthetic/world/world_params.hpp"

namespace radarpr::synthetic {

// A named world: its street grid, contents and ground. Configs name one with "world".
struct WorldPreset {
  CityLayout layout;
  WorldParams params;
  double ground_clutter = 9.0;  // the radar's ground return (RadarModel)
  double ground_clutter_falloff_m = 60.0;
};

// "city", "suburban", "campus", "riverside", "offroad" (see world_presets.cpp for what each
// sets). Throws std::invalid_argument listing the names.
WorldPreset world_preset(std::string_view name);

}  // namespace radarpr::synthetic
