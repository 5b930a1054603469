#pragma once

#include <algorithm>
#include <vector>

#include "datasets/synthetic/radar/echo_hits.hpp"
#include "datasets/synthetic/radar/radar_model.hpp"
#include "datasets/synthetic/radar/ray_geometry.hpp"

namespace radarpr::synthetic {

// Renderer internals: the echoes of one scan before noise and quantisation.

// Dense linear echo power, A x R, plus where each ray stopped at an opaque object.
class EchoBuffer {
 public:
  EchoBuffer(const RadarModel& radar, const RayGeometry& rays);

  // Adds one visible echo of linear power `power` found on `hit.ray`, spread over the beam and
  // its side lobes.
  void deposit(const Hit& hit, float power);

  void set_opaque(int ray, double range_m) {
    opaque_bin_[static_cast<std::size_t>(ray)] =
        std::min(bins_, static_cast<int>(range_m / resolution_));
  }

  const float* row(int ray) const {
    return power_.data() + static_cast<std::size_t>(ray) * static_cast<std::size_t>(bins_);
  }
  int opaque_bin(int ray) const { return opaque_bin_[static_cast<std::size_t>(ray)]; }

 private:
  void add_sidelobes(const Hit& hit, float power);
  void add_to_row(int ray, const Hit& hit, float power);

  const RayGeometry& rays_;
  int bins_;
  double resolution_;
  std::vector<float> power_;
  std::vector<int> opaque_bin_;
  std::vector<float> psf_;
  float visible_power_;  // the lowest noise floor, linear: weaker leaks are not drawn
};

// Walks each ray's hits near to far: attenuates by what was crossed, stops at opaque objects;
// a strong echo that stops the beam also returns a multipath ghost at twice its range.
// Sorts `hits`.
void trace_rays(std::vector<Hit>& hits, const RadarModel& radar, const RayGeometry& rays,
                EchoBuffer& echoes);

}  // namespace radarpr::synthetic
