#include "datasets/synthetic/radar/radar_renderer.hpp"

#include <numbers>
#include <vector>

#include "datasets/synthetic/radar/echo_buffer.hpp"
#include "datasets/synthetic/radar/echo_hits.hpp"
#include "datasets/synthetic/radar/radar_quantise.hpp"
#include "datasets/synthetic/radar/ray_geometry.hpp"

namespace radarpr::synthetic {

PolarImage render_scan(const World& world, const Pose2D& pose, const RadarModel& radar,
                       std::uint64_t noise_seed) {
  const World* layers[] = {&world};
  return render_scan(layers, SensorSweep::still(pose), radar, noise_seed);
}

// The pipeline: ray geometry, the hits of every object on every ray, their echoes traced near
// to far (occlusion, multipath), then the receiver (noise, speckle, quantisation).
PolarImage render_scan(std::span<const World* const> layers, const SensorSweep& sweep,
                       const RadarModel& radar, std::uint64_t noise_seed) {
  validate(radar);
  const RayGeometry rays(radar, sweep);

  std::size_t elements = 0;
  for (const World* world : layers) elements += world->element_count();
  std::vector<Hit> hits;
  hits.reserve(elements * 8);
  for (const World* world : layers) {
    collect_wall_hits(*world, rays, radar.beam_width_deg * std::numbers::pi / 180.0, hits);
    collect_pole_hits(*world, rays, hits);
    collect_foliage_hits(*world, rays, hits);
  }

  EchoBuffer echoes(radar, rays);
  trace_rays(hits, radar, rays, echoes);

  PolarImage image;
  image.power = quantise(echoes, radar, noise_seed);
  image.azimuths_rad = uniform_azimuths(radar.azimuth_count);
  image.range_resolution_m = radar.range_resolution_m;
  return image;
}

}  // namespace radarpr::synthetic
