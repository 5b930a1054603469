#pragma once

#include <cmath>
#include <vector>

#include "datasets/synthetic/radar/radar_model.hpp"
#include "datasets/synthetic/world/synthetic_world.hpp"

namespace radarpr::synthetic {

// Renderer internals: the geometry of one scan's rays.

inline constexpr float kMinBeamWeight = 0.01f;  // beam tails below -20 dB are ignored

// Everything that depends on the radar model and the sweep, computed once per scan. Each ray
// (azimuth row) has its own origin and world direction: the sensor moves during the sweep.
struct RayGeometry {
  int azimuths = 0;
  double step_rad = 0.0;
  double max_range_m = 0.0;
  std::vector<Vec2> origin;          // world position of the sensor when row a was measured
  std::vector<double> cos_a, sin_a;  // world direction of ray a
  Pose2D middle;                     // the sweep's middle pose: candidate rays are found from it
  double middle_c = 1.0, middle_s = 0.0;
  double max_turn_rad = 0.0;           // largest yaw change from the middle pose
  double max_displacement_m = 0.0;     // largest distance from the middle pose
  double beam_sigma_steps = 0.0;       // Gaussian two-way beam, in azimuth steps
  std::vector<float> beam_spread;      // main-lobe weights for azimuth offsets -K..K
  int beam_reach = 0;                  // K
  std::vector<float> sidelobe_spread;  // side-lobe weights for offsets K+1..S (index 0 = K+1)
  float sidelobe_peak = 0.0f;

  RayGeometry(const RadarModel& radar, const SensorSweep& sweep);

  float beam_weight(double offset_steps) const {
    const double z = offset_steps / beam_sigma_steps;
    return static_cast<float>(std::exp(-0.5 * z * z));
  }
  int wrap(int ray) const { return ((ray % azimuths) + azimuths) % azimuths; }
  // Continuous azimuth index of a sensor-frame angle, in [0, A).
  double index_of(double angle_rad) const;
  // A world point in the middle pose's sensor frame.
  Vec2 to_middle(const Vec2& p) const {
    const double dx = p.x - middle.x;
    const double dy = p.y - middle.y;
    return {middle_c * dx + middle_s * dy, -middle_s * dx + middle_c * dy};
  }
  // How many extra rays either side an object `distance_m` away may move by during the sweep.
  int motion_margin_rays(double distance_m) const;
  // Ray `ray` relative to its own origin: the point's (range along the ray, signed offset).
  Vec2 along_ray(int ray, const Vec2& p) const {
    const auto index = static_cast<std::size_t>(ray);
    const double dx = p.x - origin[index].x;
    const double dy = p.y - origin[index].y;
    return {cos_a[index] * dx + sin_a[index] * dy, -sin_a[index] * dx + cos_a[index] * dy};
  }
};

}  // namespace radarpr::synthetic
