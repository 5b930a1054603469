#include "datasets/synthetic/radar/echo_buffer.hpp"

#include <cmath>

namespace radarpr::synthetic {
namespace {

// Echo level loss over `range_m` (units): the linear range loss, weather attenuation and the
// spreading loss beyond 10 m.
double path_loss(const RadarModel& radar, double range_m) {
  double loss = (radar.range_loss_per_m + radar.atmospheric_loss_per_m) * range_m;
  if (radar.spreading_loss_per_decade > 0.0 && range_m > 10.0) {
    loss += radar.spreading_loss_per_decade * std::log10(range_m / 10.0);
  }
  return loss;
}

}  // namespace

EchoBuffer::EchoBuffer(const RadarModel& radar, const RayGeometry& rays)
    : rays_(rays),
      bins_(radar.range_bin_count),
      resolution_(radar.range_resolution_m),
      power_(static_cast<std::size_t>(rays.azimuths) * static_cast<std::size_t>(bins_), 0.0f),
      opaque_bin_(static_cast<std::size_t>(rays.azimuths), bins_),
      visible_power_(static_cast<float>(
          std::pow(10.0, std::min(radar.noise_floor_near, radar.noise_floor_far) / 20.0))) {
  const double sigma_bins = radar.range_spread_m / resolution_;
  const int reach = static_cast<int>(std::ceil(3.0 * sigma_bins));
  for (int j = -reach; j <= reach; ++j) {
    psf_.push_back(sigma_bins > 0.0
                       ? static_cast<float>(std::exp(-0.5 * (j / sigma_bins) * (j / sigma_bins)))
                       : 1.0f);
  }
}

void EchoBuffer::deposit(const Hit& hit, float power) {
  if (hit.kind == HitKind::pole) {
    add_to_row(hit.ray, hit, power);  // already weighted by the beam, ray by ray
  } else {
    const int reach = rays_.beam_reach;
    for (int k = -reach; k <= reach; ++k) {
      add_to_row(rays_.wrap(hit.ray + k), hit,
                 power * rays_.beam_spread[static_cast<std::size_t>(k + reach)]);
    }
  }
  if (hit.sidelobe_gap >= 0) add_sidelobes(hit, power);
}

// Side lobes only where they can rise above the noise: strong echoes (facades, cars, lamps,
// pillars); each lobe lands on the rays either side, whatever they hit first.
void EchoBuffer::add_sidelobes(const Hit& hit, float power) {
  if (power * rays_.sidelobe_peak <= visible_power_) return;
  for (std::size_t j = 0; j < rays_.sidelobe_spread.size(); ++j) {
    const float side = power * rays_.sidelobe_spread[j];
    if (side <= 0.1f * visible_power_) continue;
    const int k = hit.sidelobe_gap + 1 + static_cast<int>(j);
    add_to_row(rays_.wrap(hit.ray + k), hit, side);
    add_to_row(rays_.wrap(hit.ray - k), hit, side);
  }
}

void EchoBuffer::add_to_row(int ray, const Hit& hit, float power) {
  float* row = power_.data() + static_cast<std::size_t>(ray) * static_cast<std::size_t>(bins_);
  const double first_bin = hit.range_m / resolution_;
  if (hit.kind == HitKind::foliage) {
    // Volume return over the crossed depth, fading as the crown attenuates the beam.
    const int begin = static_cast<int>(first_bin);
    const int end =
        std::min(bins_, static_cast<int>((hit.range_m + hit.extent_m) / resolution_) + 1);
    const float fade =
        std::pow(hit.transmission, 1.0f / static_cast<float>(std::max(1, end - begin)));
    float level = power;
    for (int r = std::max(0, begin); r < end; ++r, level *= fade) row[r] += level;
    return;
  }
  if (hit.extent_m / resolution_ > 2.0) {
    // Slanted wall: a streak centred on the pencil ray's hit.
    const int begin = static_cast<int>((hit.range_m - 0.5 * hit.extent_m) / resolution_);
    const int end =
        std::min(bins_, static_cast<int>((hit.range_m + 0.5 * hit.extent_m) / resolution_) + 1);
    for (int r = std::max(0, begin); r < end; ++r) row[r] += power;
    return;
  }
  // Bin r covers ranges [r, r + 1) x resolution, as in real Navtech data (and as the shadow,
  // streak and volume echoes above count them).
  const int centre = static_cast<int>(std::floor(first_bin));
  const int reach = static_cast<int>(psf_.size() / 2);
  const int begin = std::max(0, centre - reach);
  const int end = std::min(bins_, centre + reach + 1);
  for (int r = begin; r < end; ++r)
    row[r] += power * psf_[static_cast<std::size_t>(r - centre + reach)];
}

void trace_rays(std::vector<Hit>& hits, const RadarModel& radar, const RayGeometry& rays,
                EchoBuffer& echoes) {
  std::stable_sort(hits.begin(), hits.end(), [](const Hit& l, const Hit& r) {
    return l.ray != r.ray ? l.ray < r.ray : l.range_m < r.range_m;
  });
  std::size_t i = 0;
  while (i < hits.size()) {
    const int ray = hits[i].ray;
    double transmission = 1.0;  // two-way, up to the current hit
    for (; i < hits.size() && hits[i].ray == ray; ++i) {
      if (transmission <= 0.0) continue;  // already stopped: skip the rest of this ray
      const Hit& hit = hits[i];
      // The echo as it comes back through what the beam crossed on the way.
      const double level =
          hit.level - path_loss(radar, hit.range_m) + 20.0 * std::log10(transmission);
      echoes.deposit(hit, static_cast<float>(std::pow(10.0, level / 20.0)));
      const double reached = transmission;
      transmission *= hit.transmission;
      if (transmission >= 1e-3) continue;
      transmission = 0.0;
      echoes.set_opaque(ray, hit.range_m);
      const double ghost_range = 2.0 * hit.range_m;
      if (hit.kind == HitKind::wall && level >= radar.multipath_min_level &&
          ghost_range < rays.max_range_m) {
        // The ghost goes round twice (sensor - wall - vehicle - wall - sensor): the path, and
        // what lies between the sensor and the wall, again; and the bounce off the vehicle.
        const double ghost_level = level - radar.multipath_loss - path_loss(radar, hit.range_m) +
                                   20.0 * std::log10(reached);
        Hit ghost = hit;
        ghost.range_m = ghost_range;
        ghost.extent_m = 0.0f;
        echoes.deposit(ghost, static_cast<float>(std::pow(10.0, ghost_level / 20.0)));
      }
    }
  }
}

}  // namespace radarpr::synthetic
