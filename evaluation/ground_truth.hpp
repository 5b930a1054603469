#pragma once

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "datasets/scan_sequence.hpp"
#include "evaluation/protocol.hpp"

namespace radarpr {

struct Position2D {
  double x = 0.0;
  double y = 0.0;
  double yaw = 0.0;  // radians; read only by a heading-aware ground truth
};

std::vector<Position2D> positions_of(const std::vector<ScanRecord>& records);

// Single session: for each query frame q (time order), the end of its eligible database prefix
// [0, end): the frames at least `exclude_recent_frames` frames older, or at least
// `exclude_recent_seconds` older when that is set. 0 = no eligible frame.
std::vector<std::size_t> single_session_eligible_ends(const std::vector<ScanRecord>& records,
                                                      const Protocol& protocol);

// Revisits from positions (protocols.md, "Ground truth"): sub-quadratic through a uniform grid.
// With a heading limit a database frame is a positive only when the headings also differ by at
// most that much (the smaller angle between them).
class RevisitGroundTruth {
 public:
  RevisitGroundTruth(std::vector<Position2D> database_positions, double radius_m,
                     RadiusComparison comparison = RadiusComparison::inclusive,
                     std::optional<double> max_yaw_difference_deg = std::nullopt);

  // Whether database frame `database_index` is a positive for `query`: distance <= radius_m
  // (inclusive: a frame exactly radius_m away is within it), or < radius_m for
  // RadiusComparison::strict; and, with a heading limit, |yaw difference| <= the limit.
  bool is_positive(const Position2D& query, std::size_t database_index) const;
  // Whether some database frame in [0, eligible_end) is a positive for `query`.
  bool has_revisit(const Position2D& query, std::size_t eligible_end) const;

  double radius_m() const { return radius_m_; }
  std::size_t database_size() const { return database_.size(); }

 private:
  std::vector<Position2D> database_;
  double radius_m_;
  RadiusComparison comparison_;
  std::optional<double> max_yaw_difference_rad_;
  // Cell index of a coordinate along one axis (may be outside [0, cell_count) for queries).
  double cell_coordinate(double value, double origin) const;
  const std::vector<std::size_t>* cell(long long cell_x, long long cell_y) const;

  // Grid of cell size radius_m: cell key -> database indices in increasing order.
  std::vector<std::pair<long long, std::vector<std::size_t>>> cells_;  // sorted by key
  // Cells are a hair larger than the radius (see ground_truth.cpp) and anchored at the lower
  // corner of the database positions; key = cell_x * cell_count_y_ + cell_y.
  double cell_size_ = 0.0;
  double origin_x_ = 0.0;
  double origin_y_ = 0.0;
  long long cell_count_x_ = 0;
  long long cell_count_y_ = 0;
};

}  // namespace radarpr
