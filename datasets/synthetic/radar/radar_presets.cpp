#include "datasets/synthetic/radar/radar_presets.hpp"

#include <stdexcept>

#include <fmt/format.h>

namespace radarpr::synthetic {

RadarModel radar_preset(std::string_view name) {
  RadarModel radar;  // defaults: CIR204-H optics and noise, 1680 bins
  if (name == "cir204h") {
    radar.range_bin_count = 3360;
    return radar;
  }
  if (name == "cts350x") {
    // Finer bins: the same echo spans more of them; a quieter receiver far out.
    radar.range_bin_count = 3768;
    radar.range_resolution_m = 0.0432;
    radar.noise_floor_far -= 0.7;
    return radar;
  }
  if (name == "short") return radar;
  if (name == "tiny") {
    radar.azimuth_count = 120;
    radar.range_bin_count = 420;
    radar.range_resolution_m = 0.238;
    return radar;
  }
  throw std::invalid_argument(fmt::format(
      "synthetic radar: unknown preset '{}', expected cir204h, cts350x, short or tiny", name));
}

std::string_view to_string(Weather weather) {
  switch (weather) {
    case Weather::rain:
      return "rain";
    case Weather::snow:
      return "snow";
    case Weather::clear:
      break;
  }
  return "clear";
}

Weather weather_from(std::string_view name) {
  if (name == "clear") return Weather::clear;
  if (name == "rain") return Weather::rain;
  if (name == "snow") return Weather::snow;
  throw std::invalid_argument(
      fmt::format("synthetic radar: unknown weather '{}', expected clear, rain or snow", name));
}

RadarModel with_weather(RadarModel radar, Weather weather) {
  switch (weather) {
    case Weather::rain:
      // Heavy rain: 0.08 units per metre of range (both ways), 10 units at 125 m (~40 dB/km
      // at 77 GHz); the drops' backscatter brightens the first tens of metres.
      radar.atmospheric_loss_per_m += 0.08;
      radar.precipitation_clutter += 4.0;
      radar.noise_floor_far += 1.0;
      break;
    case Weather::snow:
      // Heavy snow: far less attenuation than rain (0.015 units per metre, 7.5 dB/km), more
      // backscatter.
      radar.atmospheric_loss_per_m += 0.015;
      radar.precipitation_clutter += 5.0;
      radar.noise_floor_far += 1.0;
      break;
    case Weather::clear:
      break;
  }
  return radar;
}

}  // namespace radarpr::synthetic
