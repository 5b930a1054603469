#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "datasets/scan_sequence.hpp"

namespace radarpr {

struct PoseSample {
  std::int64_t timestamp_ns = 0;
  Pose2D pose;
};

// A dataset's ground-truth trajectory, queried at scan times. Positions are interpolated
// linearly and yaw along the shorter arc of the circle; a time outside the track, or inside a
// gap longer than the caller's limit, has no pose: it is never extrapolated or bridged.
class PoseTrack {
 public:
  static constexpr std::int64_t kNoGapLimit = std::numeric_limits<std::int64_t>::max();
  // A time this close outside the track gets the end pose: scans named in µs against poses in ns
  // with sub-µs digits would otherwise lose the first scan by a few ns.
  static constexpr std::int64_t kEndToleranceNs = 1000;

  // Sorts the samples by time. Of samples sharing a timestamp the first (in the given order) is
  // kept and the others are counted in duplicated_timestamps(): a track must be a function of
  // time. Throws std::invalid_argument for a non-finite pose.
  explicit PoseTrack(std::vector<PoseSample> samples);

  // The pose at `timestamp_ns`, or nullopt when it lies outside [first, last] by more than
  // kEndToleranceNs or between two samples more than `max_gap_ns` apart. An exact sample time
  // returns that sample; a time within the tolerance outside the track, the end sample.
  std::optional<Pose2D> at(std::int64_t timestamp_ns, std::int64_t max_gap_ns = kNoGapLimit) const;

  const std::vector<PoseSample>& samples() const { return samples_; }
  bool empty() const { return samples_.empty(); }
  std::size_t size() const { return samples_.size(); }
  std::int64_t first_ns() const { return samples_.front().timestamp_ns; }
  std::int64_t last_ns() const { return samples_.back().timestamp_ns; }
  // Longest time between consecutive samples; 0 with fewer than two.
  std::int64_t largest_gap_ns() const { return largest_gap_ns_; }
  // Longest time between consecutive samples whose interval meets [first_ns, last_ns]: the gaps
  // that matter to scans taken in that span. 0 when no interval meets it.
  std::int64_t largest_gap_ns(std::int64_t first_ns, std::int64_t last_ns) const;
  std::size_t duplicated_timestamps() const { return duplicated_timestamps_; }

 private:
  std::vector<PoseSample> samples_;
  std::int64_t largest_gap_ns_ = 0;
  std::size_t duplicated_timestamps_ = 0;
};

// Wraps an angle to (-pi, pi].
double wrap_angle(double radians);
// The yaw a fraction `f` of the way from `from` to `to` along the shorter arc, wrapped.
double interpolate_yaw(double from, double to, double f);

}  // namespace radarpr
