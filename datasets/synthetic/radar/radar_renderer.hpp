#pragma once

#include <cstdint>
#include <span>

#include "datasets/polar_image.hpp"
#include "datasets/scan_sequence.hpp"
#include "datasets/synthetic/radar/radar_model.hpp"
#include "datasets/synthetic/world/synthetic_world.hpp"

namespace radarpr::synthetic {

// Renders one scan of `world` seen from `pose` (sensor at (x, y), azimuth 0 along `yaw`,
// azimuths counter-clockwise, row a at angle 2*pi*a/A): A x R bytes, uniform azimuths, no
// per-azimuth times. Pure function: the same arguments always give the same pixels, and the
// noise depends only on `noise_seed`. Safe to call from several threads at once.
PolarImage render_scan(const World& world, const Pose2D& pose, const RadarModel& radar,
                       std::uint64_t noise_seed);

// The general form: every layer's objects (the fixed world, the moving vehicles of this
// instant) seen from a moving sensor, each azimuth from its own pose (motion distortion).
PolarImage render_scan(std::span<const World* const> layers, const SensorSweep& sweep,
                       const RadarModel& radar, std::uint64_t noise_seed);

}  // namespace radarpr::synthetic
