#include "datasets/synthetic/radar_renderer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "datasets/synthetic/random.hpp"

namespace radarpr::synthetic {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kMaxGrazingExtentM = 6.0;  // longest streak a grazing wall leaves along range
constexpr float kMinBeamWeight = 0.01f;     // beam tails below -20 dB are ignored
constexpr int kSpeckleLutBits = 12;
constexpr double kScatterCellM = 0.8;  // facade scatter varies per cell of this length

enum class HitKind : std::uint8_t { wall, pole, foliage };

// One object crossed by the pencil ray of one azimuth.
struct Hit {
  int ray = 0;
  double range_m = 0.0;
  float level = 0.0f;         // echo level at this range before attenuation (units)
  float transmission = 1.0f;  // two-way power fraction passing the object
  float extent_m = 0.0f;      // depth the echo covers along range (0 = point echo)
  HitKind kind = HitKind::wall;
};

double cross(const Vec2& a, const Vec2& b) {
  return a.x * b.y - a.y * b.x;
}

double distance_to_segment(const Vec2& a, const Vec2& b) {
  const Vec2 e{b.x - a.x, b.y - a.y};
  const double length_sq = e.x * e.x + e.y * e.y;
  double t = length_sq > 0.0 ? -(a.x * e.x + a.y * e.y) / length_sq : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(a.x + t * e.x, a.y + t * e.y);
}

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

  RayGeometry(const RadarModel& radar, const SensorSweep& sweep)
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
      max_turn_rad =
          std::max(max_turn_rad, std::abs(std::remainder(pose.yaw - middle.yaw, kTwoPi)));
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

  float beam_weight(double offset_steps) const {
    const double z = offset_steps / beam_sigma_steps;
    return static_cast<float>(std::exp(-0.5 * z * z));
  }
  int wrap(int ray) const { return ((ray % azimuths) + azimuths) % azimuths; }
  // Continuous azimuth index of a sensor-frame angle, in [0, A).
  double index_of(double angle_rad) const {
    double index = angle_rad / step_rad;
    index = std::fmod(index, static_cast<double>(azimuths));
    return index < 0.0 ? index + azimuths : index;
  }
  // A world point in the middle pose's sensor frame.
  Vec2 to_middle(const Vec2& p) const {
    const double dx = p.x - middle.x;
    const double dy = p.y - middle.y;
    return {middle_c * dx + middle_s * dy, -middle_s * dx + middle_c * dy};
  }
  // How many extra rays either side an object `distance_m` away may move by during the sweep.
  int motion_margin_rays(double distance_m) const {
    if (max_displacement_m == 0.0 && max_turn_rad == 0.0) return 0;
    const double shift =
        max_turn_rad + std::asin(std::min(1.0, max_displacement_m / std::max(distance_m, 1e-6)));
    return static_cast<int>(std::ceil(shift / step_rad)) + 1;
  }
  // Ray `ray` relative to its own origin: the point's (range along the ray, signed offset).
  Vec2 along_ray(int ray, const Vec2& p) const {
    const auto index = static_cast<std::size_t>(ray);
    const double dx = p.x - origin[index].x;
    const double dy = p.y - origin[index].y;
    return {cos_a[index] * dx + sin_a[index] * dy, -sin_a[index] * dx + cos_a[index] * dy};
  }
};

// Echo level of a facade hit: specular-ish incidence term (never below -24 units: rough walls
// still scatter at grazing angles), brighter pillars/frames every texture period, and a fixed
// per-metre scatter so a wall looks blotchy, the same blotches from every viewpoint.
float wall_level(const WallSegment& wall, std::uint64_t wall_key, double cos_incidence,
                 double along_m) {
  const double c2 = cos_incidence * cos_incidence;
  double level = wall.strength + 20.0 * std::log10(0.06 + 0.94 * c2 * c2);
  if (wall.texture_period_m > 0.0f) {
    const double phase =
        std::fmod(along_m, static_cast<double>(wall.texture_period_m)) / wall.texture_period_m;
    level += phase < 0.2 ? 8.0 : -2.0;
  }
  if (wall.scatter_units <= 0.0f) return static_cast<float>(level);
  const auto cell =
      static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(along_m / kScatterCellM)));
  const std::uint64_t h = mix64(wall_key ^ mix64(cell));
  level += wall.scatter_units * (2.0 * static_cast<double>(h >> 11) * 0x1.0p-53 - 1.0);
  return static_cast<float>(level);
}

// Identifies a wall by its geometry (not its index), so the scatter pattern is the same in
// every region generated of the same city.
std::uint64_t wall_key(const WallSegment& wall) {
  auto mm = [](double v) { return static_cast<std::uint64_t>(std::llround(v * 1000.0)); };
  return hash_key({mm(wall.a.x), mm(wall.a.y), mm(wall.b.x), mm(wall.b.y)});
}

void collect_wall_hits(const World& world, const RayGeometry& rays, double beam_rad,
                       std::vector<Hit>& hits) {
  for (const WallSegment& wall : world.walls) {
    const Vec2 a = rays.to_middle(wall.a);
    const Vec2 b = rays.to_middle(wall.b);
    const double distance = distance_to_segment(a, b);
    if (distance >= rays.max_range_m + rays.max_displacement_m || distance < 1e-6) continue;
    const Vec2 e_world{wall.b.x - wall.a.x, wall.b.y - wall.a.y};
    const double length = std::hypot(e_world.x, e_world.y);
    if (length < 1e-9) continue;
    const std::uint64_t key = wall_key(wall);

    // The segment does not contain the sensor, so it spans less than pi of azimuth: walk the
    // rays of the shorter arc between its end points (seen from the middle pose, widened by
    // how far the sensor moves during the sweep).
    const double angle_a = std::atan2(a.y, a.x);
    double span = std::atan2(b.y, b.x) - angle_a;
    if (span > kPi) span -= kTwoPi;
    if (span < -kPi) span += kTwoPi;
    const double start = span >= 0.0 ? angle_a : angle_a + span;
    const int margin = rays.motion_margin_rays(distance);
    const int first = static_cast<int>(std::ceil(start / rays.step_rad)) - margin;
    const int last =
        std::min(first + rays.azimuths - 1,
                 static_cast<int>(std::floor((start + std::abs(span)) / rays.step_rad)) + margin);
    for (int i = first; i <= last; ++i) {
      const int ray = rays.wrap(i);
      const auto index = static_cast<std::size_t>(ray);
      const Vec2 dir{rays.cos_a[index], rays.sin_a[index]};
      const Vec2 w{wall.a.x - rays.origin[index].x, wall.a.y - rays.origin[index].y};
      const double denom = cross(dir, e_world);
      if (std::abs(denom) < 1e-12 * length) continue;  // ray parallel to the wall
      const double range = cross(w, e_world) / denom;
      const double t = cross(w, dir) / denom;
      if (range <= 0.0 || range >= rays.max_range_m || t < -1e-9 || t > 1.0 + 1e-9) continue;
      const double cos_incidence = std::min(1.0, std::abs(denom) / length);
      const double tan_incidence = std::sqrt(std::max(0.0, 1.0 - cos_incidence * cos_incidence)) /
                                   std::max(cos_incidence, 1e-6);
      // Within the beam a slanted wall covers a stretch of ranges: a streak, not a dot.
      const double extent = std::min(range * beam_rad * tan_incidence, kMaxGrazingExtentM);
      hits.push_back({ray, range, wall_level(wall, key, cos_incidence, t * length),
                      wall.transmission, static_cast<float>(extent), HitKind::wall});
    }
  }
}

void collect_pole_hits(const World& world, const RayGeometry& rays, std::vector<Hit>& hits) {
  for (const Pole& pole : world.poles) {
    const Vec2 c = rays.to_middle(pole.centre);
    const double distance = std::hypot(c.x, c.y);
    if (distance <= pole.radius_m ||
        distance - pole.radius_m >= rays.max_range_m + rays.max_displacement_m) {
      continue;
    }
    const double centre_index = rays.index_of(std::atan2(c.y, c.x));
    const double half_width = std::asin(pole.radius_m / distance) / rays.step_rad;
    const int reach = rays.beam_reach + static_cast<int>(std::ceil(half_width)) +
                      rays.motion_margin_rays(distance);
    const int nearest = static_cast<int>(std::lround(centre_index));
    // A pole is evaluated on every ray of its beam directly (not spread afterwards), so each
    // ray's own occluders decide whether it sees the pole.
    for (int i = nearest - reach; i <= nearest + reach && i < nearest - reach + rays.azimuths;
         ++i) {
      const int ray = rays.wrap(i);
      const Vec2 p = rays.along_ray(ray, pole.centre);
      const double d = std::hypot(p.x, p.y);
      if (p.x <= 0.0 || d <= pole.radius_m || d - pole.radius_m >= rays.max_range_m) continue;
      const double offset_steps = std::atan2(std::abs(p.y), p.x) / rays.step_rad;
      const double half = std::asin(pole.radius_m / d) / rays.step_rad;
      const float weight = rays.beam_weight(std::max(0.0, offset_steps - half));
      if (weight < kMinBeamWeight) continue;
      const float level = pole.strength + 20.0f * std::log10(weight);
      const float transmission = 1.0f - (1.0f - pole.transmission) * weight;
      hits.push_back({ray, d - pole.radius_m, level, transmission, 0.0f, HitKind::pole});
    }
  }
}

void collect_foliage_hits(const World& world, const RayGeometry& rays, std::vector<Hit>& hits) {
  for (const Foliage& crown : world.foliage) {
    const Vec2 c = rays.to_middle(crown.centre);
    const double distance = std::hypot(c.x, c.y);
    const double radius = crown.radius_m;
    if (distance - radius >= rays.max_range_m + rays.max_displacement_m) continue;
    const double centre_index = rays.index_of(std::atan2(c.y, c.x));
    const double half_width =
        distance > radius ? std::asin(radius / distance) / rays.step_rad : rays.azimuths / 2.0;
    const int margin = rays.motion_margin_rays(std::max(distance - radius, 1e-6));
    const int first = static_cast<int>(std::ceil(centre_index - half_width)) - margin;
    const int last = static_cast<int>(std::floor(centre_index + half_width)) + margin;
    for (int i = first; i <= last && i < first + rays.azimuths; ++i) {
      const int ray = rays.wrap(i);
      const Vec2 p = rays.along_ray(ray, crown.centre);
      const double along = p.x;
      const double miss_sq = p.y * p.y;
      if (miss_sq >= radius * radius) continue;
      const double half_chord = std::sqrt(radius * radius - miss_sq);
      const double enter = std::max(0.0, along - half_chord);
      const double leave = along + half_chord;
      if (leave <= 0.0 || enter >= rays.max_range_m) continue;
      const auto transmission =
          static_cast<float>(std::exp(-crown.attenuation_per_m * (leave - enter)));
      hits.push_back({ray, enter, crown.strength, transmission, static_cast<float>(leave - enter),
                      HitKind::foliage});
    }
  }
}

// Dense linear echo power, A x R, plus where each ray stopped at an opaque object.
class EchoBuffer {
 public:
  EchoBuffer(const RadarModel& radar, const RayGeometry& rays)
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

  // Adds one visible echo of linear power `power` found on `ray`.
  void deposit(const Hit& hit, float power) {
    if (hit.kind == HitKind::pole) {
      add_to_row(hit.ray, hit, power);  // already weighted by the beam
      return;
    }
    const int reach = rays_.beam_reach;
    for (int k = -reach; k <= reach; ++k) {
      add_to_row(rays_.wrap(hit.ray + k), hit,
                 power * rays_.beam_spread[static_cast<std::size_t>(k + reach)]);
    }
    // Side lobes only where they can rise above the noise: strong echoes (walls, cars).
    if (hit.kind == HitKind::wall && power * rays_.sidelobe_peak > visible_power_) {
      for (std::size_t j = 0; j < rays_.sidelobe_spread.size(); ++j) {
        const float side = power * rays_.sidelobe_spread[j];
        if (side <= 0.1f * visible_power_) continue;
        const int k = reach + 1 + static_cast<int>(j);
        add_to_row(rays_.wrap(hit.ray + k), hit, side);
        add_to_row(rays_.wrap(hit.ray - k), hit, side);
      }
    }
  }

  void set_opaque(int ray, double range_m) {
    opaque_bin_[static_cast<std::size_t>(ray)] =
        std::min(bins_, static_cast<int>(range_m / resolution_));
  }

  const float* row(int ray) const {
    return power_.data() + static_cast<std::size_t>(ray) * static_cast<std::size_t>(bins_);
  }
  int opaque_bin(int ray) const { return opaque_bin_[static_cast<std::size_t>(ray)]; }

 private:
  void add_to_row(int ray, const Hit& hit, float power) {
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
    const int centre = static_cast<int>(std::lround(first_bin));
    const int reach = static_cast<int>(psf_.size() / 2);
    const int begin = std::max(0, centre - reach);
    const int end = std::min(bins_, centre + reach + 1);
    for (int r = begin; r < end; ++r)
      row[r] += power * psf_[static_cast<std::size_t>(r - centre + reach)];
  }

  const RayGeometry& rays_;
  int bins_;
  double resolution_;
  std::vector<float> power_;
  std::vector<int> opaque_bin_;
  std::vector<float> psf_;
  float visible_power_;  // the lowest noise floor, linear: weaker leaks are not drawn
};

// Echo level loss over `range_m` (units): the linear range loss, weather attenuation and the
// spreading loss beyond 10 m.
double path_loss(const RadarModel& radar, double range_m) {
  double loss = (radar.range_loss_per_m + radar.atmospheric_loss_per_m) * range_m;
  if (radar.spreading_loss_per_decade > 0.0 && range_m > 10.0) {
    loss += radar.spreading_loss_per_decade * std::log10(range_m / 10.0);
  }
  return loss;
}

// Walks each ray's hits near to far: attenuates by what was crossed, stops at opaque objects;
// a strong echo that stops the beam also returns a multipath ghost at twice its range.
void trace_rays(std::vector<Hit>& hits, const RadarModel& radar, const RayGeometry& rays,
                EchoBuffer& echoes) {
  std::stable_sort(hits.begin(), hits.end(), [](const Hit& l, const Hit& r) {
    return l.ray != r.ray ? l.ray < r.ray : l.range_m < r.range_m;
  });
  std::size_t i = 0;
  while (i < hits.size()) {
    const int ray = hits[i].ray;
    double transmission = 1.0;
    for (; i < hits.size() && hits[i].ray == ray; ++i) {
      if (transmission <= 0.0) continue;  // already stopped: skip the rest of this ray
      const Hit& hit = hits[i];
      const double level = hit.level - path_loss(radar, hit.range_m);
      echoes.deposit(hit, static_cast<float>(transmission * std::pow(10.0, level / 20.0)));
      transmission *= hit.transmission;
      if (transmission < 1e-3) {
        transmission = 0.0;
        echoes.set_opaque(ray, hit.range_m);
        const double ghost_range = 2.0 * hit.range_m;
        if (hit.kind == HitKind::wall && level >= radar.multipath_min_level &&
            ghost_range < rays.max_range_m) {
          // The second round trip loses the path again and the bounce off the vehicle.
          const double ghost_level = level - radar.multipath_loss - path_loss(radar, hit.range_m);
          Hit ghost = hit;
          ghost.range_m = ghost_range;
          ghost.extent_m = 0.0f;
          echoes.deposit(ghost, static_cast<float>(std::pow(10.0, ghost_level / 20.0)));
        }
      }
    }
  }
}

// Quantiles of the exponential distribution (speckle of a fully developed scatterer) in units.
const std::array<float, 1 << kSpeckleLutBits>& speckle_table() {
  static const auto table = [] {
    std::array<float, 1 << kSpeckleLutBits> t{};
    for (std::size_t i = 0; i < t.size(); ++i) {
      const double u = (static_cast<double>(i) + 0.5) / static_cast<double>(t.size());
      t[i] = static_cast<float>(20.0 * std::log10(-std::log(1.0 - u)));
    }
    return t;
  }();
  return table;
}

cv::Mat quantise(const EchoBuffer& echoes, const RadarModel& radar, std::uint64_t noise_seed) {
  const int bins = radar.range_bin_count;
  std::vector<float> floor_units(static_cast<std::size_t>(bins));
  std::vector<float> clutter_units(static_cast<std::size_t>(bins));
  std::vector<float> floor_power(static_cast<std::size_t>(bins));
  std::vector<float> clutter_power(static_cast<std::size_t>(bins));
  for (int r = 0; r < bins; ++r) {
    const double range = (r + 0.5) * radar.range_resolution_m;
    // Rain or snow backscatter adds to the receiver noise, strongest near the sensor.
    const double floor =
        radar.noise_floor_far +
        (radar.noise_floor_near - radar.noise_floor_far) *
            std::exp(-range / radar.noise_floor_falloff_m) +
        radar.precipitation_clutter * std::exp(-range / radar.precipitation_falloff_m);
    const double clutter =
        floor + radar.ground_clutter * std::exp(-range / radar.ground_clutter_falloff_m);
    const auto index = static_cast<std::size_t>(r);
    floor_units[index] = static_cast<float>(floor);
    clutter_units[index] = static_cast<float>(clutter);
    floor_power[index] = static_cast<float>(std::pow(10.0, floor / 20.0));
    clutter_power[index] = static_cast<float>(std::pow(10.0, clutter / 20.0));
  }

  // Row by row in separate simple passes (base level, sparse echoes, speckle) so the dense
  // passes stay branch-free: this loop touches every pixel and dominates the render time.
  const auto& speckle = speckle_table();
  constexpr int kDrawsPerRandom = 64 / kSpeckleLutBits;
  constexpr std::uint64_t kLutMask = (1u << kSpeckleLutBits) - 1;
  // Speckle is drawn once per range cell and interpolated in between: real speckle is
  // correlated over the radar's range resolution, which spans several bins.
  const int cell = std::max(
      1, static_cast<int>(std::lround(radar.speckle_correlation_m / radar.range_resolution_m)));
  const auto cells = static_cast<std::size_t>(bins / cell + 2);
  std::vector<float> interpolation(static_cast<std::size_t>(cell));
  for (int j = 0; j < cell; ++j)
    interpolation[static_cast<std::size_t>(j)] = static_cast<float>(j) / static_cast<float>(cell);
  Rng rng(noise_seed);
  std::vector<float> units(cells * static_cast<std::size_t>(cell));
  std::vector<float> nodes(cells + kDrawsPerRandom);
  cv::Mat power(radar.azimuth_count, bins, CV_8UC1);
  for (int a = 0; a < radar.azimuth_count; ++a) {
    const float* echo = echoes.row(a);
    const auto lit_end = static_cast<std::size_t>(std::min(echoes.opaque_bin(a), bins));
    const auto end = static_cast<std::size_t>(bins);
    std::copy(clutter_units.begin(), clutter_units.begin() + static_cast<std::ptrdiff_t>(lit_end),
              units.begin());
    std::copy(floor_units.begin() + static_cast<std::ptrdiff_t>(lit_end), floor_units.end(),
              units.begin() + static_cast<std::ptrdiff_t>(lit_end));
    std::fill(units.begin() + bins, units.end(), 0.0f);  // padding up to a whole cell
    for (std::size_t r = 0; r < lit_end; ++r) {
      if (echo[r] > 0.0f) units[r] = 20.0f * std::log10(clutter_power[r] + echo[r]);
    }
    for (std::size_t r = lit_end; r < end; ++r) {
      if (echo[r] > 0.0f) units[r] = 20.0f * std::log10(floor_power[r] + echo[r]);
    }

    if (radar.speckle) {
      for (std::size_t k = 0; k < cells; k += kDrawsPerRandom) {
        std::uint64_t bits = rng.next();
        for (int d = 0; d < kDrawsPerRandom; ++d, bits >>= kSpeckleLutBits) {
          nodes[k + static_cast<std::size_t>(d)] = speckle[bits & kLutMask];
        }
      }
      for (std::size_t k = 0; k + 1 < cells; ++k) {
        float* span = units.data() + k * static_cast<std::size_t>(cell);
        const float step = nodes[k + 1] - nodes[k];
        for (std::size_t j = 0; j < interpolation.size(); ++j) {
          span[j] += nodes[k] + step * interpolation[j];
        }
      }
    }
    auto* out = power.ptr<std::uint8_t>(a);
    for (std::size_t r = 0; r < end; ++r) {
      out[r] = static_cast<std::uint8_t>(std::clamp(units[r] + 0.5f, 0.0f, 255.0f));
    }
  }
  return power;
}

void require(bool condition, const char* field, double value, const char* expected) {
  if (!condition) {
    throw std::invalid_argument(
        fmt::format("synthetic radar: {} = {} is invalid, expected {}", field, value, expected));
  }
}

}  // namespace

void validate(const RadarModel& radar) {
  require(radar.azimuth_count >= 8, "azimuth_count", radar.azimuth_count, ">= 8");
  require(radar.range_bin_count >= 1, "range_bin_count", radar.range_bin_count, ">= 1");
  require(radar.range_resolution_m > 0.0 && std::isfinite(radar.range_resolution_m),
          "range_resolution_m", radar.range_resolution_m, "> 0");
  require(radar.beam_width_deg > 0.0 && radar.beam_width_deg <= 90.0, "beam_width_deg",
          radar.beam_width_deg, "in (0, 90]");
  require(radar.range_spread_m >= 0.0 && std::isfinite(radar.range_spread_m), "range_spread_m",
          radar.range_spread_m, ">= 0");
  require(std::isfinite(radar.noise_floor_near), "noise_floor_near", radar.noise_floor_near,
          "a finite number");
  require(std::isfinite(radar.noise_floor_far), "noise_floor_far", radar.noise_floor_far,
          "a finite number");
  require(radar.noise_floor_falloff_m > 0.0, "noise_floor_falloff_m", radar.noise_floor_falloff_m,
          "> 0");
  require(radar.ground_clutter >= 0.0 && std::isfinite(radar.ground_clutter), "ground_clutter",
          radar.ground_clutter, ">= 0");
  require(radar.ground_clutter_falloff_m > 0.0, "ground_clutter_falloff_m",
          radar.ground_clutter_falloff_m, "> 0");
  require(radar.speckle_correlation_m >= 0.0 && std::isfinite(radar.speckle_correlation_m),
          "speckle_correlation_m", radar.speckle_correlation_m, ">= 0");
  require(radar.range_loss_per_m >= 0.0 && std::isfinite(radar.range_loss_per_m),
          "range_loss_per_m", radar.range_loss_per_m, ">= 0");
  require(std::isfinite(radar.sidelobe_level) && radar.sidelobe_level <= 0.0, "sidelobe_level",
          radar.sidelobe_level, "<= 0 (units below the main lobe)");
  require(radar.sidelobe_reach_deg >= 0.0 && radar.sidelobe_reach_deg <= 180.0,
          "sidelobe_reach_deg", radar.sidelobe_reach_deg, "in [0, 180]");
  require(radar.sidelobe_decay_per_deg >= 0.0 && std::isfinite(radar.sidelobe_decay_per_deg),
          "sidelobe_decay_per_deg", radar.sidelobe_decay_per_deg, ">= 0");
  require(radar.multipath_loss >= 0.0 && std::isfinite(radar.multipath_loss), "multipath_loss",
          radar.multipath_loss, ">= 0");
  require(std::isfinite(radar.multipath_min_level), "multipath_min_level",
          radar.multipath_min_level, "a finite number");
  require(radar.spreading_loss_per_decade >= 0.0 && std::isfinite(radar.spreading_loss_per_decade),
          "spreading_loss_per_decade", radar.spreading_loss_per_decade, ">= 0");
  require(radar.atmospheric_loss_per_m >= 0.0 && std::isfinite(radar.atmospheric_loss_per_m),
          "atmospheric_loss_per_m", radar.atmospheric_loss_per_m, ">= 0");
  require(radar.precipitation_clutter >= 0.0 && std::isfinite(radar.precipitation_clutter),
          "precipitation_clutter", radar.precipitation_clutter, ">= 0");
  require(radar.precipitation_falloff_m > 0.0 && std::isfinite(radar.precipitation_falloff_m),
          "precipitation_falloff_m", radar.precipitation_falloff_m, "> 0");
}

Pose2D SensorSweep::at_row(int a, int azimuth_count) const {
  const int half = azimuth_count / 2;
  auto lerp = [](const Pose2D& p, const Pose2D& q, double f) {
    return Pose2D{p.x + f * (q.x - p.x), p.y + f * (q.y - p.y),
                  p.yaw + f * std::remainder(q.yaw - p.yaw, kTwoPi)};
  };
  if (a < half) return lerp(start, middle, static_cast<double>(a) / half);
  return lerp(middle, end, static_cast<double>(a - half) / (azimuth_count - half));
}

PolarImage render_scan(const World& world, const Pose2D& pose, const RadarModel& radar,
                       std::uint64_t noise_seed) {
  const World* layers[] = {&world};
  return render_scan(layers, SensorSweep::still(pose), radar, noise_seed);
}

PolarImage render_scan(std::span<const World* const> layers, const SensorSweep& sweep,
                       const RadarModel& radar, std::uint64_t noise_seed) {
  validate(radar);
  const RayGeometry rays(radar, sweep);

  std::size_t elements = 0;
  for (const World* world : layers) elements += world->element_count();
  std::vector<Hit> hits;
  hits.reserve(elements * 8);
  for (const World* world : layers) {
    collect_wall_hits(*world, rays, radar.beam_width_deg * kPi / 180.0, hits);
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
