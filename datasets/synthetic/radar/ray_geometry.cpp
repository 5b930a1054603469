#include "datasets/synthetic/radar/ray_geometry.hpp"

#include <algorithm>
#include <numbers>

namespace radarpr::synthetic {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

}  // namespace

RayGeometry::RayGeometry(const RadarModel& radar, const SensorSweep& sweep)
    : azimuths(radar.azimuth_count),
      step_rad(kTwoPi / radar.azimuth_count),
      max_range_m(radar.range_bin_count * radar.range_resolution_m),
      middle(sweep.middle),
      middle_c(std::cos(sweep.middle.yaw)),
      middle_s(std::sin(sweep.middle.yaw)) {
  origin.resize(static_cast<std::size_t>(azimuths));
  cos_a.resize(static_cast<std::size_t>(azimuths));
  sin_a.resize(static_cast<std::size_t>(azimuths));
  for (int a = 0; a < azimuths; ++a) {
    const Pose2D pose = sweep.at_row(a, azimuths);
    const auto index = static_cast<std::size_t>(a);
    origin[index] = {pose.x, pose.y};
    cos_a[index] = std::cos(pose.yaw + a * step_rad);
    sin_a[index] = std::sin(pose.yaw + a * step_rad);
  }
  for (const Pose2D& pose : {sweep.start, sweep.end}) {
    max_turn_rad = std::max(max_turn_rad, std::abs(std::remainder(pose.yaw - middle.yaw, kTwoPi)));
    max_displacement_m =
        std::max(max_displacement_m, std::hypot(pose.x - middle.x, pose.y - middle.y));
  }
  // -3 dB full width = 2.3548 sigma for a Gaussian.
  beam_sigma_steps = (radar.beam_width_deg / 2.354820045) / (360.0 / azimuths);
  beam_reach = 0;
  while (beam_reach < azimuths / 2 && beam_weight(beam_reach + 1.0) >= kMinBeamWeight) {
    ++beam_reach;
  }
  for (int k = -beam_reach; k <= beam_reach; ++k) beam_spread.push_back(beam_weight(k));
  // Side lobes: a decaying envelope with a lobe every 2 degrees (nulls in between).
  const double step_deg = 360.0 / azimuths;
  const int side_reach =
      std::min(azimuths / 2, static_cast<int>(radar.sidelobe_reach_deg / step_deg));
  for (int k = beam_reach + 1; k <= side_reach; ++k) {
    const double beyond_deg = (k - beam_reach - 1) * step_deg;
    const double envelope = radar.sidelobe_level - radar.sidelobe_decay_per_deg * beyond_deg;
    const double lobe = std::cos(kPi * beyond_deg / 2.0);
    const double weight = std::pow(10.0, envelope / 20.0) * (0.1 + 0.9 * lobe * lobe);
    sidelobe_spread.push_back(static_cast<float>(weight));
    sidelobe_peak = std::max(sidelobe_peak, static_cast<float>(weight));
  }
}

double RayGeometry::index_of(double angle_rad) const {
  double index = angle_rad / step_rad;
  index = std::fmod(index, static_cast<double>(azimuths));
  return index < 0.0 ? index + azimuths : index;
}

int RayGeometry::motion_margin_rays(double distance_m) const {
  if (max_displacement_m == 0.0 && max_turn_rad == 0.0) return 0;
  const double shift =
      max_turn_rad + std::asin(std::min(1.0, max_displacement_m / std::max(distance_m, 1e-6)));
  return static_cast<int>(std::ceil(shift / step_rad)) + 1;
}

}  // namespace radarpr::synthetic
