#pragma once

#include <cmath>
#include <numbers>

#include "datasets/scan_sequence.hpp"

namespace radarpr::synthetic {

// The pose a fraction `f` of the way from p to q: x and y linearly, yaw along the shorter arc
// (the result in [-pi, pi]). `f` may lie outside [0, 1] to extrapolate.
inline Pose2D blend_poses(const Pose2D& p, const Pose2D& q, double f) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  return {p.x + f * (q.x - p.x), p.y + f * (q.y - p.y),
          std::remainder(p.yaw + f * std::remainder(q.yaw - p.yaw, kTwoPi), kTwoPi)};
}

}  // namespace radarpr::synthetic
