#include "datasets/pose_track.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

namespace radarpr {

double wrap_angle(double radians) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  double wrapped = std::fmod(radians, kTwoPi);  // (-2 pi, 2 pi)
  if (wrapped > std::numbers::pi) wrapped -= kTwoPi;
  if (wrapped <= -std::numbers::pi) wrapped += kTwoPi;
  return wrapped;
}

double interpolate_yaw(double from, double to, double f) {
  return wrap_angle(from + f * wrap_angle(to - from));
}

PoseTrack::PoseTrack(std::vector<PoseSample> samples) {
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const Pose2D& p = samples[i].pose;
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.yaw)) {
      throw std::invalid_argument(
          fmt::format("pose sample {} (t = {} ns) is not finite: x = {}, y = {}, yaw = {}", i,
                      samples[i].timestamp_ns, p.x, p.y, p.yaw));
    }
  }
  std::stable_sort(samples.begin(), samples.end(), [](const PoseSample& a, const PoseSample& b) {
    return a.timestamp_ns < b.timestamp_ns;
  });
  samples_.reserve(samples.size());
  for (const PoseSample& sample : samples) {
    if (!samples_.empty() && samples_.back().timestamp_ns == sample.timestamp_ns) {
      ++duplicated_timestamps_;
      continue;
    }
    if (!samples_.empty()) {
      largest_gap_ns_ =
          std::max(largest_gap_ns_, sample.timestamp_ns - samples_.back().timestamp_ns);
    }
    samples_.push_back(sample);
  }
}

std::int64_t PoseTrack::largest_gap_ns(std::int64_t first_ns, std::int64_t last_ns) const {
  std::int64_t largest = 0;
  for (std::size_t i = 1; i < samples_.size(); ++i) {
    const std::int64_t begin = samples_[i - 1].timestamp_ns;
    const std::int64_t end = samples_[i].timestamp_ns;
    if (end >= first_ns && begin <= last_ns) largest = std::max(largest, end - begin);
  }
  return largest;
}

std::optional<Pose2D> PoseTrack::at(std::int64_t timestamp_ns, std::int64_t max_gap_ns) const {
  if (samples_.empty()) return std::nullopt;
  if (timestamp_ns < first_ns()) {
    if (first_ns() - timestamp_ns <= kEndToleranceNs) return samples_.front().pose;
    return std::nullopt;
  }
  if (timestamp_ns > last_ns()) {
    if (timestamp_ns - last_ns() <= kEndToleranceNs) return samples_.back().pose;
    return std::nullopt;
  }
  // First sample at or after the time; it exists because the time is <= last_ns().
  const auto after = std::lower_bound(
      samples_.begin(), samples_.end(), timestamp_ns,
      [](const PoseSample& sample, std::int64_t t) { return sample.timestamp_ns < t; });
  if (after->timestamp_ns == timestamp_ns) return after->pose;
  const auto before = std::prev(after);
  const std::int64_t gap = after->timestamp_ns - before->timestamp_ns;
  if (gap > max_gap_ns) return std::nullopt;
  const double f =
      static_cast<double>(timestamp_ns - before->timestamp_ns) / static_cast<double>(gap);
  const Pose2D& a = before->pose;
  const Pose2D& b = after->pose;
  return Pose2D{a.x + f * (b.x - a.x), a.y + f * (b.y - a.y), interpolate_yaw(a.yaw, b.yaw, f)};
}

}  // namespace radarpr
