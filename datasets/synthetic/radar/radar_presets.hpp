#pragma once

#include <string_view>

#include "datasets/synthetic/radar/radar_renderer.hpp"

namespace radarpr::synthetic {

// Named sensor presets:
//   "cir204h"  Navtech CIR204-H (MulRan, early Boreas): 400 x 3360 bins of 0.0595238 m (200 m)
//   "cts350x"  Navtech CTS350-X (Oxford RobotCar, OORD): 400 x 3768 bins of 0.0432 m (163 m)
//   "short"    the CIR204-H's first 1680 bins (100 m): the quick default
//   "tiny"     120 x 420 bins of 0.238 m (100 m), for tests
// Throws std::invalid_argument listing the names.
RadarModel radar_preset(std::string_view name);

enum class Weather {
  clear,
  rain,  // attenuation and backscatter raise the noise near the sensor and shorten the range
  snow,  // more backscatter, less attenuation than rain
};

std::string_view to_string(Weather weather);
// Throws std::invalid_argument listing the names.
Weather weather_from(std::string_view name);

// The radar as the weather makes it.
RadarModel with_weather(RadarModel radar, Weather weather);

}  // namespace radarpr::synthetic
