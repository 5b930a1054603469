#include "datasets/synthetic/radar/radar_model.hpp"

#include <cmath>

#include <fmt/format.h>

#include "datasets/synthetic/drive/pose_blend.hpp"
#include "datasets/synthetic/require.hpp"

namespace radarpr::synthetic {
namespace {

constexpr double kMaxScanPixels = 1 << 24;
constexpr double kMaxReachM = 500.0;

}  // namespace

void validate(const RadarModel& radar) {
  constexpr std::string_view kSubject = "synthetic radar";
  require(radar.azimuth_count >= 8, kSubject, "azimuth_count", radar.azimuth_count, ">= 8");
  require(radar.range_bin_count >= 1, kSubject, "range_bin_count", radar.range_bin_count, ">= 1");
  // Bounds that keep a typo from asking for gigabytes: a scan's pixels and the radar's reach
  // (the world is generated out to it around the drive).
  const double pixels = static_cast<double>(radar.azimuth_count) * radar.range_bin_count;
  require(pixels <= kMaxScanPixels, kSubject, "azimuth_count x range_bin_count", pixels,
          fmt::format("at most 2^24 = {}", kMaxScanPixels));
  require(radar.range_resolution_m > 0.0 && std::isfinite(radar.range_resolution_m), kSubject,
          "range_resolution_m", radar.range_resolution_m, "> 0");
  const double reach = radar.range_bin_count * radar.range_resolution_m;
  require(reach <= kMaxReachM, kSubject, "range_bin_count x range_resolution_m", reach,
          fmt::format("at most {} m", kMaxReachM));
  require(radar.beam_width_deg > 0.0 && radar.beam_width_deg <= 90.0, kSubject, "beam_width_deg",
          radar.beam_width_deg, "in (0, 90]");
  require(radar.range_spread_m >= 0.0 && radar.range_spread_m <= 5.0, kSubject, "range_spread_m",
          radar.range_spread_m, "in [0, 5]");
  require(std::isfinite(radar.noise_floor_near), kSubject, "noise_floor_near",
          radar.noise_floor_near, "a finite number");
  require(std::isfinite(radar.noise_floor_far), kSubject, "noise_floor_far", radar.noise_floor_far,
          "a finite number");
  require(radar.noise_floor_falloff_m > 0.0 && std::isfinite(radar.noise_floor_falloff_m), kSubject,
          "noise_floor_falloff_m", radar.noise_floor_falloff_m, "> 0");
  require(radar.ground_clutter >= 0.0 && std::isfinite(radar.ground_clutter), kSubject,
          "ground_clutter", radar.ground_clutter, ">= 0");
  require(radar.ground_clutter_falloff_m > 0.0 && std::isfinite(radar.ground_clutter_falloff_m),
          kSubject, "ground_clutter_falloff_m", radar.ground_clutter_falloff_m, "> 0");
  require(radar.speckle_correlation_m >= 0.0 && radar.speckle_correlation_m <= 10.0, kSubject,
          "speckle_correlation_m", radar.speckle_correlation_m, "in [0, 10]");
  require(radar.range_loss_per_m >= 0.0 && std::isfinite(radar.range_loss_per_m), kSubject,
          "range_loss_per_m", radar.range_loss_per_m, ">= 0");
  require(std::isfinite(radar.sidelobe_level) && radar.sidelobe_level <= 0.0, kSubject,
          "sidelobe_level", radar.sidelobe_level, "<= 0 (units below the main lobe)");
  require(radar.sidelobe_reach_deg >= 0.0 && radar.sidelobe_reach_deg <= 180.0, kSubject,
          "sidelobe_reach_deg", radar.sidelobe_reach_deg, "in [0, 180]");
  require(radar.sidelobe_decay_per_deg >= 0.0 && std::isfinite(radar.sidelobe_decay_per_deg),
          kSubject, "sidelobe_decay_per_deg", radar.sidelobe_decay_per_deg, ">= 0");
  require(radar.multipath_loss >= 0.0 && std::isfinite(radar.multipath_loss), kSubject,
          "multipath_loss", radar.multipath_loss, ">= 0");
  require(std::isfinite(radar.multipath_min_level), kSubject, "multipath_min_level",
          radar.multipath_min_level, "a finite number");
  require(radar.spreading_loss_per_decade >= 0.0 && std::isfinite(radar.spreading_loss_per_decade),
          kSubject, "spreading_loss_per_decade", radar.spreading_loss_per_decade, ">= 0");
  require(radar.atmospheric_loss_per_m >= 0.0 && std::isfinite(radar.atmospheric_loss_per_m),
          kSubject, "atmospheric_loss_per_m", radar.atmospheric_loss_per_m, ">= 0");
  require(radar.precipitation_clutter >= 0.0 && std::isfinite(radar.precipitation_clutter),
          kSubject, "precipitation_clutter", radar.precipitation_clutter, ">= 0");
  require(radar.precipitation_falloff_m > 0.0 && std::isfinite(radar.precipitation_falloff_m),
          kSubject, "precipitation_falloff_m", radar.precipitation_falloff_m, "> 0");
}

Pose2D SensorSweep::at_row(int a, int azimuth_count) const {
  const int half = azimuth_count / 2;
  if (a < half) return blend_poses(start, middle, static_cast<double>(a) / half);
  return blend_poses(middle, end, static_cast<double>(a - half) / (azimuth_count - half));
}

}  // namespace radarpr::synthetic
