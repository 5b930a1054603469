#pragma once

#include <flann/flann.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

// Internal to the retrieval strategies (retrieval.cpp, blocked_l2_search.cpp): exact candidate
// collection over float distances that only approximate the descriptor's distance().
namespace radarpr::retrieval_detail {

// Squared L2 between search keys, written so the compiler vectorises it (eight independent
// lanes); the KD-trees and the scans share it, so both paths see identical key distances.
inline float squared_l2(const float* a, const float* b, std::size_t size) {
  float lanes[8] = {};
  std::size_t i = 0;
  for (; i + 8 <= size; i += 8) {
    for (std::size_t lane = 0; lane < 8; ++lane) {
      const float difference = a[i + lane] - b[i + lane];
      lanes[lane] += difference * difference;
    }
  }
  float sum = ((lanes[0] + lanes[4]) + (lanes[1] + lanes[5])) +
              ((lanes[2] + lanes[6]) + (lanes[3] + lanes[7]));
  for (; i < size; ++i) {
    const float difference = a[i] - b[i];
    sum += difference * difference;
  }
  return sum;
}

// Relative and absolute widths of the band of key distances kept around the k-th nearest (see
// CandidateSet).
inline constexpr float kRelativeBand = 1e-3f;
inline constexpr float kAbsoluteBandPerSquaredNorm = 1e-6f;

// Collects every database frame whose key distance lies within a narrow band above the k-th
// smallest key distance seen so far. Key distances are float and only order the database like
// distance() up to rounding, so the final top-k is chosen by distance() among these candidates:
// that makes the result equal the exhaustive search's, ties (smaller index first) included.
class CandidateSet final : public flann::ResultSet<float> {
 public:
  // relative_band: the share of the k-th distance added to the band; callers whose absolute
  // band is already a rigorous error bound pass 0.
  CandidateSet(std::size_t k, float absolute_band, float relative_band = kRelativeBand)
      : k_(k), absolute_band_(absolute_band), relative_band_(relative_band) {
    nearest_.reserve(k);
  }

  // FLANN reports indices within the tree searched; the tree's first database index.
  void set_offset(std::size_t offset) { offset_ = offset; }

  bool full() const override { return nearest_.size() == k_; }
  float worstDist() const override { return admit_below_; }

  void addPoint(float key_distance, std::size_t index) override {
    if (!(key_distance < admit_below_)) return;
    candidates_.emplace_back(key_distance, offset_ + index);
    if (nearest_.size() < k_) {
      nearest_.push_back(key_distance);
      std::push_heap(nearest_.begin(), nearest_.end());
    } else if (key_distance < nearest_.front()) {
      std::pop_heap(nearest_.begin(), nearest_.end());
      nearest_.back() = key_distance;
      std::push_heap(nearest_.begin(), nearest_.end());
    }
    if (nearest_.size() == k_) {
      const float kth = nearest_.front();
      bound_ = kth + kth * relative_band_ + absolute_band_;
      admit_below_ = std::nextafter(bound_, std::numeric_limits<float>::infinity());
      if (candidates_.size() > 4 * k_ + 64) prune();
    }
  }

  // Database indices of the candidates.
  std::vector<std::size_t> indices() {
    prune();
    std::vector<std::size_t> result;
    result.reserve(candidates_.size());
    for (const auto& candidate : candidates_) result.push_back(candidate.second);
    return result;
  }

 private:
  void prune() {
    std::erase_if(candidates_, [&](const auto& c) { return c.first > bound_; });
  }

  std::size_t k_;
  float absolute_band_;
  float relative_band_;
  std::size_t offset_ = 0;
  std::vector<float> nearest_;  // max-heap of the k smallest key distances
  float bound_ = std::numeric_limits<float>::infinity();
  float admit_below_ = std::numeric_limits<float>::infinity();
  std::vector<std::pair<float, std::size_t>> candidates_;
};

}  // namespace radarpr::retrieval_detail
