#include "datasets/synthetic/synthetic_sequence.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "datasets/polar_png.hpp"
#include "datasets/synthetic/drive/pose_blend.hpp"
#include "datasets/synthetic/random.hpp"
#include "datasets/synthetic/require.hpp"
#include "datasets/synthetic/world/traffic.hpp"
#include "datasets/synthetic/world/world_generator.hpp"

namespace radarpr {
namespace {

// Bump whenever the generated pixels or poses change for an unchanged config: cached
// descriptors are keyed by the fingerprint and must not outlive the images they came from.
constexpr const char* kGeneratorVersion = "synthetic-v4";
constexpr std::uint64_t kSpeckleTag = 21;
constexpr std::int64_t kSessionStrideNs = 86'400'000'000'000;  // sessions start a day apart
constexpr int kMaxSession = 1000;
constexpr int kMaxScans = 1'000'000;
constexpr std::int64_t kYear2000Ns = 946'684'800'000'000'000;    // 2000-01-01T00:00:00Z
constexpr std::int64_t kYear2100Ns = 4'102'444'800'000'000'000;  // 2100-01-01T00:00:00Z
constexpr std::string_view kSubject = "synthetic dataset";

std::int64_t scan_period_ns(const SyntheticConfig& config) {
  return std::llround(1e9 / config.drive.scan_rate_hz);
}

}  // namespace

void validate(const SyntheticConfig& config) {
  using synthetic::require;
  require(config.session >= 0 && config.session <= kMaxSession, kSubject, "session", config.session,
          fmt::format("in [0, {}]", kMaxSession));
  require(config.scan_count >= 1 && config.scan_count <= kMaxScans, kSubject, "scan_count",
          config.scan_count, fmt::format("in [1, {}]", kMaxScans));
  // Scans are stamped in whole microseconds, the first between 2000 and 2100 (sessions start a
  // day apart after it, drives last at most days: no overflow of the nanosecond clock).
  if (config.start_time_ns < kYear2000Ns || config.start_time_ns >= kYear2100Ns ||
      config.start_time_ns % 1000 != 0) {
    throw std::invalid_argument(fmt::format(
        "{}: start_time_ns = {} is invalid, expected whole microseconds (a multiple of 1000) "
        "from 2000-01-01 ({}) to 2100-01-01 ({})",
        kSubject, config.start_time_ns, kYear2000Ns, kYear2100Ns));
  }
  synthetic::validate(config.radar);
  // Scans travel in the Oxford layout (scan_export.hpp), whose rows must be wider than the image
  // is high, as every real Navtech's are (thousands of range bins, hundreds of azimuths).
  if (config.radar.range_bin_count + kOxfordMetadataColumns <= config.radar.azimuth_count) {
    throw std::invalid_argument(fmt::format(
        "synthetic dataset: range_bin_count = {} is too few for azimuth_count = {}, expected more "
        "than {} (A - 11) so that a scan fits the Oxford layout, one row per azimuth",
        config.radar.range_bin_count, config.radar.azimuth_count,
        config.radar.azimuth_count - kOxfordMetadataColumns));
  }
  synthetic::validate(config.city);
  synthetic::validate(config.world, config.city);
  synthetic::validate(config.drive, config.city, config.scan_count,
                      synthetic::to_string(config.world.kind));
}

SyntheticSequence::SyntheticSequence(SyntheticConfig config) : config_(std::move(config)) {
  validate(config_);
  const std::vector<Pose2D> poses = synthetic::plan_drive(config_.drive, config_.city, config_.seed,
                                                          config_.session, config_.scan_count);

  const std::int64_t start = config_.start_time_ns + config_.session * kSessionStrideNs;
  const std::int64_t period = scan_period_ns(config_);
  const std::string sequence_name = name();
  records_.reserve(poses.size());
  synthetic::Vec2 low{poses.front().x, poses.front().y};
  synthetic::Vec2 high = low;
  for (std::size_t i = 0; i < poses.size(); ++i) {
    records_.push_back({start + static_cast<std::int64_t>(i) * period, poses[i],
                        fmt::format("{}#{}", sequence_name, i)});
    low = {std::min(low.x, poses[i].x), std::min(low.y, poses[i].y)};
    high = {std::max(high.x, poses[i].x), std::max(high.y, poses[i].y)};
  }
  // Only what some scan can see: the drive's bounding box grown by the radar's reach.
  const double reach = config_.radar.range_bin_count * config_.radar.range_resolution_m + 1.0;
  world_ =
      synthetic::generate_world(config_.seed, config_.session, config_.city, config_.world,
                                {low.x - reach, low.y - reach}, {high.x + reach, high.y + reach});
  effective_radar_ = synthetic::with_weather(config_.radar, config_.weather);
}

std::string SyntheticSequence::name() const {
  return fmt::format("synthetic(seed={},session={})", config_.seed, config_.session);
}

std::string SyntheticSequence::fingerprint() const {
  const auto& r = config_.radar;
  const auto& c = config_.city;
  const auto& w = config_.world;
  const auto& d = config_.drive;
  return fmt::format(
      "{}(seed={},session={},scan_count={},start_time_ns={},weather={},motion_distortion={},"
      "radar(azimuth_count={},range_bin_count={},range_resolution_m={},beam_width_deg={},"
      "range_spread_m={},noise_floor_near={},noise_floor_far={},noise_floor_falloff_m={},"
      "ground_clutter={},ground_clutter_falloff_m={},range_loss_per_m={},speckle={},speckle_"
      "correlation_m={},sidelobe_level={},sidelobe_reach_deg={},sidelobe_decay_per_deg={},"
      "multipath_loss={},multipath_min_level={},spreading_loss_per_decade={},"
      "atmospheric_loss_per_m={},precipitation_clutter={},precipitation_falloff_m={}),"
      "city(block_pitch_m={},lanes_per_direction={},lane_width_m={},parking_width_m={},"
      "pavement_width_m={},park_fraction={}),"
      "world(kind={},parked_cars={},parked_car_churn={},foliage={},traffic={},river_width_m={}),"
      "drive(route_blocks_x={},route_blocks_y={},route_origin_block_x={},"
      "route_origin_block_y={},lap_pattern={},lane={},speed_mps={},scan_rate_hz={},"
      "corner_radius_m={},session_offset_m={},heading_jitter_deg={}))",
      kGeneratorVersion, config_.seed, config_.session, config_.scan_count, config_.start_time_ns,
      synthetic::to_string(config_.weather), config_.motion_distortion, r.azimuth_count,
      r.range_bin_count, r.range_resolution_m, r.beam_width_deg, r.range_spread_m,
      r.noise_floor_near, r.noise_floor_far, r.noise_floor_falloff_m, r.ground_clutter,
      r.ground_clutter_falloff_m, r.range_loss_per_m, r.speckle, r.speckle_correlation_m,
      r.sidelobe_level, r.sidelobe_reach_deg, r.sidelobe_decay_per_deg, r.multipath_loss,
      r.multipath_min_level, r.spreading_loss_per_decade, r.atmospheric_loss_per_m,
      r.precipitation_clutter, r.precipitation_falloff_m, c.block_pitch_m,
      c.street.lanes_per_direction, c.street.lane_width_m, c.street.parking_width_m,
      c.street.pavement_width_m, c.park_fraction, synthetic::to_string(w.kind), w.parked_cars,
      w.parked_car_churn, w.foliage, w.traffic, w.river_width_m, d.route_blocks_x, d.route_blocks_y,
      d.route_origin_block_x, d.route_origin_block_y, d.lap_pattern, d.lane, d.speed_mps,
      d.scan_rate_hz, d.corner_radius_m, d.session_offset_m, d.heading_jitter_deg);
}

DatasetReport SyntheticSequence::describe() const {
  DatasetReport report = ScanSequence::describe();
  report.type = "synthetic";
  report.location = "generated (seed " + std::to_string(config_.seed) + ")";
  report.layout = "rendered, azimuth rows";
  report.azimuths = config_.radar.azimuth_count;
  report.range_bins = config_.radar.range_bin_count;
  report.range_resolution_m = config_.radar.range_resolution_m;
  report.resolution_source = "configured";
  report.pose_source = "the simulated drive";
  report.pose_samples = records_.size();
  report.pose_times = report.scan_times;
  if (records_.size() > 1) {
    report.largest_pose_gap_s = static_cast<double>(scan_period_ns(config_)) * 1e-9;
  }
  return report;
}

synthetic::SensorSweep SyntheticSequence::sweep(std::size_t index) const {
  const Pose2D& pose = records_.at(index).pose;
  if (!config_.motion_distortion || records_.size() < 2) {
    return synthetic::SensorSweep::still(pose);
  }
  // Half a scan period either side, on the straight line to the neighbouring scan (or away from
  // it at the ends of the drive).
  using synthetic::blend_poses;
  const Pose2D start = index > 0 ? blend_poses(records_[index - 1].pose, pose, 0.5)
                                 : blend_poses(pose, records_[index + 1].pose, -0.5);
  const Pose2D end = index + 1 < records_.size() ? blend_poses(pose, records_[index + 1].pose, 0.5)
                                                 : blend_poses(records_[index - 1].pose, pose, 1.5);
  return {start, pose, end};
}

synthetic::World SyntheticSequence::traffic(std::size_t index) const {
  const ScanRecord& record = records_.at(index);
  const double reach = config_.radar.range_bin_count * config_.radar.range_resolution_m;
  const double time_s =
      static_cast<double>(record.timestamp_ns - records_.front().timestamp_ns) * 1e-9;
  return synthetic::moving_vehicles(config_.seed, config_.session, config_.city, config_.world,
                                    time_s, record.pose, reach);
}

PolarImage SyntheticSequence::load_image(std::size_t index) const {
  if (index >= records_.size()) {
    throw std::out_of_range(fmt::format("{}: scan index {} out of range (the sequence has {})",
                                        name(), index, records_.size()));
  }
  const std::uint64_t noise_seed =
      synthetic::hash_key({config_.seed, static_cast<std::uint64_t>(config_.session), kSpeckleTag,
                           static_cast<std::uint64_t>(index)});
  const ScanRecord& record = records_[index];
  const synthetic::World moving = traffic(index);
  const synthetic::World* layers[] = {&world_, &moving};
  PolarImage image = synthetic::render_scan(layers, sweep(index), effective_radar_, noise_seed);

  // One revolution per scan period, middle azimuth at the scan's timestamp.
  const int azimuths = image.azimuth_count();
  const std::int64_t period = scan_period_ns(config_);
  image.azimuth_times_ns.resize(static_cast<std::size_t>(azimuths));
  for (int a = 0; a < azimuths; ++a) {
    image.azimuth_times_ns[static_cast<std::size_t>(a)] =
        record.timestamp_ns + (a - azimuths / 2) * period / azimuths;
  }
  return image;
}

}  // namespace radarpr
