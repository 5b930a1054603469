#include "evaluation/ground_truth.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

namespace radarpr {
namespace {

// Cells are this much (relative) larger than the radius: two points within the radius then
// differ by less than 1 - 1e-6 cells along each axis, and the rounding of a cell coordinate
// (below 2^30 * 2^-52 ~ 2.4e-7) can never push them two cells apart.
constexpr double kCellMargin = 1e-6;
// Largest cell coordinate per axis; bounds the rounding above and keeps the packed key in 64 bits.
constexpr double kMaxCellCoordinate = 1073741824.0;  // 2^30

std::string describe(const Position2D& position) {
  return "(" + std::to_string(position.x) + ", " + std::to_string(position.y) + ")";
}

bool finite(const Position2D& position) {
  return std::isfinite(position.x) && std::isfinite(position.y);
}

// The smaller angle between two headings, in [0, pi].
double yaw_difference(double a, double b) {
  return std::abs(std::remainder(a - b, 2.0 * std::numbers::pi));
}

void require_time_order(const std::vector<ScanRecord>& records) {
  for (std::size_t i = 1; i < records.size(); ++i) {
    if (records[i].timestamp_ns < records[i - 1].timestamp_ns) {
      throw std::invalid_argument(
          "single_session_eligible_ends: records must be in time order, but record " +
          std::to_string(i) + " (" + records[i].source +
          ", t=" + std::to_string(records[i].timestamp_ns) + " ns) is older than record " +
          std::to_string(i - 1) + " (t=" + std::to_string(records[i - 1].timestamp_ns) + " ns)");
    }
  }
}

}  // namespace

std::vector<Position2D> positions_of(const std::vector<ScanRecord>& records) {
  std::vector<Position2D> positions;
  positions.reserve(records.size());
  for (const ScanRecord& record : records) {
    positions.push_back({record.pose.x, record.pose.y, record.pose.yaw});
  }
  return positions;
}

std::vector<std::size_t> single_session_eligible_ends(const std::vector<ScanRecord>& records,
                                                      const Protocol& protocol) {
  std::vector<std::size_t> ends(records.size(), 0);
  if (protocol.exclude_recent_seconds.has_value()) {
    const double window_s = *protocol.exclude_recent_seconds;
    // A window of 0 would let a query match itself.
    if (!std::isfinite(window_s) || window_s <= 0.0) {
      throw std::invalid_argument(
          "single_session_eligible_ends: exclude_recent_seconds must be a finite number > 0, "
          "got " +
          std::to_string(window_s));
    }
    require_time_order(records);
    const double window_ns = window_s * 1e9;
    // Frame j is eligible for query q when t_q - t_j >= window; time order makes that a prefix
    // of [0, q) (frames from q on are never older than q).
    for (std::size_t q = 0; q < records.size(); ++q) {
      const std::int64_t t_q = records[q].timestamp_ns;
      const auto first_too_recent =
          std::partition_point(records.begin(), records.begin() + static_cast<std::ptrdiff_t>(q),
                               [&](const ScanRecord& r) {
                                 return static_cast<double>(t_q - r.timestamp_ns) >= window_ns;
                               });
      ends[q] = static_cast<std::size_t>(first_too_recent - records.begin());
    }
    return ends;
  }

  const int exclude = protocol.exclude_recent_frames;
  // 0 would let a query match itself.
  if (exclude < 1) {
    throw std::invalid_argument(
        "single_session_eligible_ends: exclude_recent_frames must be >= 1, got " +
        std::to_string(exclude));
  }
  // Frame j is eligible for query q when q - j >= exclude, i.e. j < q - exclude + 1.
  const auto exclude_count = static_cast<std::size_t>(exclude);
  for (std::size_t q = 0; q < records.size(); ++q) {
    ends[q] = q + 1 >= exclude_count ? q + 1 - exclude_count : 0;
  }
  return ends;
}

RevisitGroundTruth::RevisitGroundTruth(std::vector<Position2D> database_positions, double radius_m,
                                       RadiusComparison comparison,
                                       std::optional<double> max_yaw_difference_deg)
    : database_(std::move(database_positions)), radius_m_(radius_m), comparison_(comparison) {
  if (!std::isfinite(radius_m_) || radius_m_ <= 0.0) {
    throw std::invalid_argument(
        "RevisitGroundTruth: the revisit radius must be a finite number of metres > 0, got " +
        std::to_string(radius_m_));
  }
  if (max_yaw_difference_deg) {
    const double limit = *max_yaw_difference_deg;
    if (!(limit > 0.0 && limit <= 180.0)) {
      throw std::invalid_argument(
          "RevisitGroundTruth: the heading limit must be in (0, 180] degrees, got " +
          std::to_string(limit));
    }
    max_yaw_difference_rad_ = limit * std::numbers::pi / 180.0;
    for (std::size_t i = 0; i < database_.size(); ++i) {
      if (!std::isfinite(database_[i].yaw)) {
        throw std::invalid_argument("RevisitGroundTruth: database heading " + std::to_string(i) +
                                    " is not finite: " + std::to_string(database_[i].yaw));
      }
    }
    // Poses read without a heading have yaw 0 everywhere, which would make every heading
    // close: a silently wrong ground truth. No real drive keeps an exact heading of 0.
    const bool no_heading =
        database_.size() >= 2 && std::all_of(database_.begin(), database_.end(),
                                             [](const Position2D& p) { return p.yaw == 0.0; });
    if (no_heading) {
      throw std::invalid_argument(
          "the heading limit (protocol.revisit_max_yaw_deg) needs poses with a heading, but all " +
          std::to_string(database_.size()) +
          " database poses have yaw 0: these poses carry no heading; remove the key");
    }
  }
  for (std::size_t i = 0; i < database_.size(); ++i) {
    if (!finite(database_[i])) {
      throw std::invalid_argument("RevisitGroundTruth: database position " + std::to_string(i) +
                                  " is not finite: " + describe(database_[i]));
    }
  }
  cell_size_ = radius_m_ * (1.0 + kCellMargin);
  if (database_.empty()) return;

  const auto [min_x, max_x] =
      std::minmax_element(database_.begin(), database_.end(),
                          [](const Position2D& a, const Position2D& b) { return a.x < b.x; });
  const auto [min_y, max_y] =
      std::minmax_element(database_.begin(), database_.end(),
                          [](const Position2D& a, const Position2D& b) { return a.y < b.y; });
  origin_x_ = min_x->x;
  origin_y_ = min_y->y;
  const double last_x = cell_coordinate(max_x->x, origin_x_);
  const double last_y = cell_coordinate(max_y->y, origin_y_);
  if (last_x >= kMaxCellCoordinate || last_y >= kMaxCellCoordinate) {
    throw std::invalid_argument(
        "RevisitGroundTruth: the database positions span " + std::to_string(max_x->x - min_x->x) +
        " m x " + std::to_string(max_y->y - min_y->y) + " m, more than 2^30 cells of the " +
        std::to_string(radius_m_) + " m radius per axis");
  }
  cell_count_x_ = static_cast<long long>(last_x) + 1;
  cell_count_y_ = static_cast<long long>(last_y) + 1;

  std::vector<std::pair<long long, std::size_t>> keyed;
  keyed.reserve(database_.size());
  for (std::size_t i = 0; i < database_.size(); ++i) {
    const auto cell_x = static_cast<long long>(cell_coordinate(database_[i].x, origin_x_));
    const auto cell_y = static_cast<long long>(cell_coordinate(database_[i].y, origin_y_));
    keyed.emplace_back(cell_x * cell_count_y_ + cell_y, i);
  }
  // Sorting the (key, index) pairs keeps each cell's indices increasing.
  std::sort(keyed.begin(), keyed.end());
  for (const auto& [key, index] : keyed) {
    if (cells_.empty() || cells_.back().first != key)
      cells_.emplace_back(key, std::vector<std::size_t>{});
    cells_.back().second.push_back(index);
  }
}

double RevisitGroundTruth::cell_coordinate(double value, double origin) const {
  return std::floor((value - origin) / cell_size_);
}

const std::vector<std::size_t>* RevisitGroundTruth::cell(long long cell_x, long long cell_y) const {
  if (cell_x < 0 || cell_x >= cell_count_x_ || cell_y < 0 || cell_y >= cell_count_y_) {
    return nullptr;
  }
  const long long key = cell_x * cell_count_y_ + cell_y;
  const auto it = std::lower_bound(cells_.begin(), cells_.end(), key,
                                   [](const std::pair<long long, std::vector<std::size_t>>& c,
                                      long long k) { return c.first < k; });
  return it != cells_.end() && it->first == key ? &it->second : nullptr;
}

// Compared squared, no sqrt; inclusive unless the protocol asks for the strict comparison.
bool RevisitGroundTruth::is_positive(const Position2D& query, std::size_t database_index) const {
  if (database_index >= database_.size()) {
    throw std::out_of_range("RevisitGroundTruth::is_positive: database index " +
                            std::to_string(database_index) + " is out of range (database size " +
                            std::to_string(database_.size()) + ")");
  }
  const double dx = query.x - database_[database_index].x;
  const double dy = query.y - database_[database_index].y;
  const double squared = dx * dx + dy * dy;
  const double limit = radius_m_ * radius_m_;
  const bool near = comparison_ == RadiusComparison::strict ? squared < limit : squared <= limit;
  if (!near || !max_yaw_difference_rad_) return near;
  if (!std::isfinite(query.yaw)) {
    throw std::invalid_argument("RevisitGroundTruth::is_positive: query heading is not finite: " +
                                std::to_string(query.yaw));
  }
  return yaw_difference(query.yaw, database_[database_index].yaw) <= *max_yaw_difference_rad_;
}

bool RevisitGroundTruth::has_revisit(const Position2D& query, std::size_t eligible_end) const {
  if (eligible_end > database_.size()) {
    throw std::invalid_argument("RevisitGroundTruth::has_revisit: eligible end " +
                                std::to_string(eligible_end) + " exceeds the database size " +
                                std::to_string(database_.size()));
  }
  if (!finite(query)) {
    throw std::invalid_argument("RevisitGroundTruth::has_revisit: query position is not finite: " +
                                describe(query));
  }
  if (eligible_end == 0) return false;
  const double query_x = cell_coordinate(query.x, origin_x_);
  const double query_y = cell_coordinate(query.y, origin_y_);
  // Beyond one cell outside the grid nothing is within the radius (also avoids huge casts).
  if (query_x < -1.0 || query_x > static_cast<double>(cell_count_x_) || query_y < -1.0 ||
      query_y > static_cast<double>(cell_count_y_)) {
    return false;
  }
  const auto cell_x = static_cast<long long>(query_x);
  const auto cell_y = static_cast<long long>(query_y);
  for (long long x = cell_x - 1; x <= cell_x + 1; ++x) {
    for (long long y = cell_y - 1; y <= cell_y + 1; ++y) {
      const std::vector<std::size_t>* indices = cell(x, y);
      if (indices == nullptr) continue;
      for (const std::size_t index : *indices) {
        if (index >= eligible_end) break;
        if (is_positive(query, index)) return true;
      }
    }
  }
  return false;
}

}  // namespace radarpr
