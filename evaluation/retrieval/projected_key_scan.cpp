#include "evaluation/retrieval/projected_key_scan.hpp"

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <atomic>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

#include "datasets/cpu_features.hpp"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define RADARPR_PROJECTED_SCAN_AVX2 1
#endif

namespace radarpr::retrieval_detail {
namespace {

using RowMatrixD = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
constexpr std::size_t kFirstStage = ProjectedKeyScan::kFirstStage;
constexpr std::size_t kHead = ProjectedKeyScan::kHead;
constexpr std::size_t kBoxAxes = ProjectedKeyScan::kBoxAxes;

// The covariance is estimated from at most this many keys (evenly spread): the axes only need
// to be good, not exact, for the bounds to reject well; distances never depend on them.
constexpr std::size_t kCovarianceRows = 16384;
// Beyond this the eigen-decomposition and the projection (dimension^2 per key) cost more than
// they save; the keys are then only centred, and the bounds use their first coordinates.
constexpr std::size_t kMaxRotatedDimension = 128;
// Queries go in groups of 8, one per vector lane, and blocks of kQueryBlock queries pass over
// the leaves together, so that a leaf is read once per block while it is in the cache.
constexpr std::size_t kLanes = 8;
constexpr std::size_t kQueryBlock = 256;
// The leaves each query of a group visits first, nearest first, to bring its admission limit
// down before the other leaves are judged.
constexpr std::size_t kNearestLeavesPerLane = 4;

// A box bound b (kBoxAxes gaps) and a key's whole distance d (dimension terms) are sums of
// non-negative terms computed in float: each within (terms + 1) u of the exact value, and the
// exact b is at most the exact d. So a computed d is at least the computed b times
// 1 - (dimension + kBoxAxes + 2) u; twice that margin, for safety, before a box may reject.
float box_bound_margin(std::size_t dimension) {
  const double unit_roundoff = std::numeric_limits<float>::epsilon() / 2.0;
  return static_cast<float>(1.0 -
                            2.0 * static_cast<double>(dimension + kBoxAxes + 2) * unit_roundoff);
}

// The queries of one group, lane by lane, and what the kernels read and update.
struct LaneGroup {
  alignas(32) float head[kHead][kLanes] = {};  // [coordinate][lane]
  alignas(32) float admit[kLanes] = {};        // admit below this; -1 = the lane takes no key
  std::size_t end[kLanes] = {};
  std::size_t max_end = 0;
  const float* query[kLanes] = {};
  CandidateSet* candidates[kLanes] = {};

  void refresh_admits() {
    for (std::size_t lane = 0; lane < kLanes; ++lane) {
      admit[lane] = candidates[lane] ? candidates[lane]->worstDist() : -1.0f;
    }
  }
};

// What the kernels read of the database, in leaf order.
struct LeafData {
  const float* head;
  const float* keys;
  const std::uint32_t* original;
  std::size_t dimension;
};

// A key that passed both bounds for `lane`: its whole distance decides.
void admit_survivor(LaneGroup& group, std::size_t lane, std::size_t position, float head_distance,
                    const LeafData& data) {
  const std::size_t index = data.original[position];
  if (index >= group.end[lane]) return;
  float distance = head_distance;
  if (data.dimension > kHead) {
    // Never below head_distance: the bound stays a bound of what is compared.
    distance += squared_l2(group.query[lane] + kHead, data.keys + position * data.dimension + kHead,
                           data.dimension - kHead);
  }
  ++ProjectedKeyScan::full_distances_in_thread();
  group.candidates[lane]->addPoint(distance, index);
  group.admit[lane] = group.candidates[lane]->worstDist();
}

// Plain loops over the lanes: what every CPU runs (vectorised by the compiler where it can).
void box_bounds_portable(const LaneGroup& group, const float* low, const float* high,
                         float* bounds) {
  for (std::size_t lane = 0; lane < kLanes; ++lane) bounds[lane] = 0.0f;
  for (std::size_t d = 0; d < kBoxAxes; ++d) {
    for (std::size_t lane = 0; lane < kLanes; ++lane) {
      const float q = group.head[d][lane];
      const float gap = std::max(std::max(low[d] - q, q - high[d]), 0.0f);
      bounds[lane] += gap * gap;
    }
  }
}

// The lanes (bit per lane) whose box bound, times `margin`, is below their admission limit.
unsigned box_admits_portable(const LaneGroup& group, const float* low, const float* high,
                             float margin) {
  alignas(32) float bounds[kLanes];
  box_bounds_portable(group, low, high, bounds);
  unsigned lanes = 0;
  for (std::size_t lane = 0; lane < kLanes; ++lane) {
    if (bounds[lane] * margin < group.admit[lane]) lanes |= 1u << lane;
  }
  return lanes;
}

void scan_portable(LaneGroup& group, const LeafData& data, std::size_t begin, std::size_t end) {
  for (std::size_t j = begin; j < end; ++j) {
    const float* coordinates = data.head + j * kHead;
    std::array<float, kLanes> sum{};
    for (std::size_t d = 0; d < kFirstStage; ++d) {
      for (std::size_t lane = 0; lane < kLanes; ++lane) {
        const float difference = group.head[d][lane] - coordinates[d];
        sum[lane] += difference * difference;
      }
    }
    bool any = false;
    for (std::size_t lane = 0; lane < kLanes; ++lane) any |= sum[lane] < group.admit[lane];
    if (!any) continue;
    for (std::size_t d = kFirstStage; d < kHead; ++d) {
      for (std::size_t lane = 0; lane < kLanes; ++lane) {
        const float difference = group.head[d][lane] - coordinates[d];
        sum[lane] += difference * difference;
      }
    }
    for (std::size_t lane = 0; lane < kLanes; ++lane) {
      if (sum[lane] < group.admit[lane]) admit_survivor(group, lane, j, sum[lane], data);
    }
  }
}

#ifdef RADARPR_PROJECTED_SCAN_AVX2
// The same with 8-float vectors and fused multiply-adds, for CPUs that have them (checked at run
// time). Fused sums round differently from the portable ones; both are within the candidate
// band, and the final ranking by distance() is exact either way.
// Squared distance from each of the group's 8 queries to the box [low, high] on its first axes.
__attribute__((target("avx2,fma"))) inline __m256 box_gap_sums(const LaneGroup& group,
                                                               const float* low,
                                                               const float* high) {
  __m256 sum = _mm256_setzero_ps();
  for (std::size_t d = 0; d < kBoxAxes; ++d) {
    const __m256 q = _mm256_load_ps(group.head[d]);
    const __m256 below = _mm256_sub_ps(_mm256_broadcast_ss(low + d), q);
    const __m256 above = _mm256_sub_ps(q, _mm256_broadcast_ss(high + d));
    const __m256 gap = _mm256_max_ps(_mm256_max_ps(below, above), _mm256_setzero_ps());
    sum = _mm256_fmadd_ps(gap, gap, sum);
  }
  return sum;
}

__attribute__((target("avx2,fma"))) void box_bounds_avx2(const LaneGroup& group, const float* low,
                                                         const float* high, float* bounds) {
  _mm256_storeu_ps(bounds, box_gap_sums(group, low, high));
}

__attribute__((target("avx2,fma"))) unsigned box_admits_avx2(const LaneGroup& group,
                                                             const float* low, const float* high,
                                                             float margin) {
  const __m256 scaled = _mm256_mul_ps(box_gap_sums(group, low, high), _mm256_set1_ps(margin));
  return static_cast<unsigned>(
      _mm256_movemask_ps(_mm256_cmp_ps(scaled, _mm256_load_ps(group.admit), _CMP_LT_OQ)));
}

// The first bound of one key: two chains of multiply-adds, so that four keys in flight keep the
// pipeline full.
__attribute__((target("avx2,fma"))) inline __m256 first_stage(const __m256* query,
                                                              const float* coordinates) {
  __m256 even = _mm256_setzero_ps();
  __m256 odd = _mm256_setzero_ps();
  for (std::size_t d = 0; d < kFirstStage; d += 2) {
    const __m256 a = _mm256_sub_ps(query[d], _mm256_broadcast_ss(coordinates + d));
    const __m256 b = _mm256_sub_ps(query[d + 1], _mm256_broadcast_ss(coordinates + d + 1));
    even = _mm256_fmadd_ps(a, a, even);
    odd = _mm256_fmadd_ps(b, b, odd);
  }
  return _mm256_add_ps(even, odd);
}

// A key that passed the first bound for some lane: the second bound, then the whole distance.
__attribute__((target("avx2,fma"))) void second_stage(LaneGroup& group, const __m256* query,
                                                      __m256& admit, const LeafData& data,
                                                      std::size_t j, __m256 sum) {
  const float* coordinates = data.head + j * kHead;
  for (std::size_t d = kFirstStage; d < kHead; ++d) {
    const __m256 difference = _mm256_sub_ps(query[d], _mm256_broadcast_ss(coordinates + d));
    sum = _mm256_fmadd_ps(difference, difference, sum);
  }
  int passed = _mm256_movemask_ps(_mm256_cmp_ps(sum, admit, _CMP_LT_OQ));
  if (passed == 0) return;
  alignas(32) float sums[kLanes];
  _mm256_store_ps(sums, sum);
  while (passed != 0) {
    const auto lane = static_cast<std::size_t>(__builtin_ctz(static_cast<unsigned>(passed)));
    passed &= passed - 1;
    admit_survivor(group, lane, j, sums[lane], data);
  }
  admit = _mm256_load_ps(group.admit);
}

__attribute__((target("avx2,fma"))) bool below(__m256 sum, __m256 admit) {
  return _mm256_movemask_ps(_mm256_cmp_ps(sum, admit, _CMP_LT_OQ)) != 0;
}

// Four keys per step (one branch for all of them), each then judged in order against the
// admission limits the earlier ones left.
__attribute__((target("avx2,fma"))) void scan_avx2(LaneGroup& group, const LeafData& data,
                                                   std::size_t begin, std::size_t end) {
  __m256 query[kHead];
  for (std::size_t d = 0; d < kHead; ++d) query[d] = _mm256_load_ps(group.head[d]);
  __m256 admit = _mm256_load_ps(group.admit);
  std::size_t j = begin;
  for (; j + 4 <= end; j += 4) {
    const float* coordinates = data.head + j * kHead;
    const __m256 s0 = first_stage(query, coordinates);
    const __m256 s1 = first_stage(query, coordinates + kHead);
    const __m256 s2 = first_stage(query, coordinates + 2 * kHead);
    const __m256 s3 = first_stage(query, coordinates + 3 * kHead);
    const __m256 any = _mm256_or_ps(
        _mm256_or_ps(_mm256_cmp_ps(s0, admit, _CMP_LT_OQ), _mm256_cmp_ps(s1, admit, _CMP_LT_OQ)),
        _mm256_or_ps(_mm256_cmp_ps(s2, admit, _CMP_LT_OQ), _mm256_cmp_ps(s3, admit, _CMP_LT_OQ)));
    if (_mm256_movemask_ps(any) == 0) continue;
    if (below(s0, admit)) second_stage(group, query, admit, data, j, s0);
    if (below(s1, admit)) second_stage(group, query, admit, data, j + 1, s1);
    if (below(s2, admit)) second_stage(group, query, admit, data, j + 2, s2);
    if (below(s3, admit)) second_stage(group, query, admit, data, j + 3, s3);
  }
  for (; j < end; ++j) {
    const __m256 sum = first_stage(query, data.head + j * kHead);
    if (below(sum, admit)) second_stage(group, query, admit, data, j, sum);
  }
}

std::atomic<bool> vector_kernels_allowed{true};

bool cpu_has_avx2_fma() {
  static const bool available = cpu_features().avx2 && cpu_features().fma;
  return available && vector_kernels_allowed.load(std::memory_order_relaxed);
}
#endif

void box_bounds(const LaneGroup& group, const float* low, const float* high, float* bounds) {
#ifdef RADARPR_PROJECTED_SCAN_AVX2
  if (cpu_has_avx2_fma()) return box_bounds_avx2(group, low, high, bounds);
#endif
  box_bounds_portable(group, low, high, bounds);
}

unsigned box_admits(const LaneGroup& group, const float* low, const float* high, float margin) {
#ifdef RADARPR_PROJECTED_SCAN_AVX2
  if (cpu_has_avx2_fma()) return box_admits_avx2(group, low, high, margin);
#endif
  return box_admits_portable(group, low, high, margin);
}

void scan(LaneGroup& group, const LeafData& data, std::size_t begin, std::size_t end) {
#ifdef RADARPR_PROJECTED_SCAN_AVX2
  if (cpu_has_avx2_fma()) return scan_avx2(group, data, begin, end);
#endif
  scan_portable(group, data, begin, end);
}

std::atomic<std::size_t> scans_built{0};

}  // namespace

void ProjectedKeyScan::allow_vector_kernels(bool allowed) {
#ifdef RADARPR_PROJECTED_SCAN_AVX2
  vector_kernels_allowed = allowed;
#else
  (void)allowed;
#endif
}

std::size_t ProjectedKeyScan::built_in_process() {
  return scans_built.load();
}

std::size_t& ProjectedKeyScan::full_distances_in_thread() {
  static thread_local std::size_t count = 0;
  return count;
}

std::size_t& ProjectedKeyScan::visited_keys_in_thread() {
  static thread_local std::size_t count = 0;
  return count;
}

float ProjectedKeyScan::projection_error(float max_squared_norm) {
  // Each projected coordinate is rounded once: the error vector of a key is at most u |y|, so a
  // distance moves by at most 2 u M and its square by at most 2 d (2 u M) + (2 u M)^2 <= 9 u M^2
  // for d <= 2 M (M = the largest norm). Margin for the double arithmetic before the rounding.
  const double unit_roundoff = std::numeric_limits<float>::epsilon() / 2.0;
  return static_cast<float>(16.0 * unit_roundoff * max_squared_norm);
}

ProjectedKeyScan::ProjectedKeyScan(const float* keys, std::size_t rows, std::size_t dimension)
    : rows_(rows), dimension_(dimension), mean_(dimension, 0.0) {
  scans_built.fetch_add(1);
  if (rows > std::numeric_limits<std::uint32_t>::max()) {
    throw std::invalid_argument("retrieve_nearest: at most 2^32 - 1 database values, got " +
                                std::to_string(rows));
  }
  for (std::size_t i = 0; i < rows; ++i) {
    for (std::size_t d = 0; d < dimension; ++d) mean_[d] += keys[i * dimension + d];
  }
  for (double& m : mean_) m /= static_cast<double>(std::max<std::size_t>(rows, 1));

  axes_.assign(dimension * dimension, 0.0);
  if (dimension <= kMaxRotatedDimension && rows > 1) {
    const std::size_t stride = std::max<std::size_t>(1, rows / kCovarianceRows);
    const auto sampled = static_cast<Eigen::Index>((rows + stride - 1) / stride);
    RowMatrixD centred(sampled, static_cast<Eigen::Index>(dimension));
    for (Eigen::Index s = 0; s < sampled; ++s) {
      const float* key = keys + static_cast<std::size_t>(s) * stride * dimension;
      for (std::size_t d = 0; d < dimension; ++d) {
        centred(s, static_cast<Eigen::Index>(d)) = key[d] - mean_[d];
      }
    }
    const Eigen::MatrixXd covariance = centred.transpose() * centred;
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(covariance);
    // Eigenvalues come in increasing order: the largest spread first means the last first.
    for (std::size_t a = 0; a < dimension; ++a) {
      const auto column = static_cast<Eigen::Index>(dimension - 1 - a);
      for (std::size_t d = 0; d < dimension; ++d) {
        axes_[a * dimension + d] = solver.eigenvectors()(static_cast<Eigen::Index>(d), column);
      }
    }
  } else {
    for (std::size_t d = 0; d < dimension; ++d) axes_[d * dimension + d] = 1.0;
  }

  projected_ = project(keys, rows);
  for (std::size_t i = 0; i < rows; ++i) {
    const float* key = projected_.data() + i * dimension;
    float norm = 0.0f;
    for (std::size_t d = 0; d < dimension; ++d) norm += key[d] * key[d];
    max_squared_norm_ = std::max(max_squared_norm_, norm);
  }
  build_leaves();
}

std::vector<float> ProjectedKeyScan::project(const float* keys, std::size_t rows) const {
  std::vector<float> projected(rows * dimension_);
  const auto dimension = static_cast<Eigen::Index>(dimension_);
  const Eigen::Map<const RowMatrixD> axes(axes_.data(), dimension, dimension);
  constexpr std::size_t kRowsPerProduct = 4096;
  RowMatrixD centred;
  RowMatrixD result;
  for (std::size_t begin = 0; begin < rows; begin += kRowsPerProduct) {
    const std::size_t end = std::min(rows, begin + kRowsPerProduct);
    centred.resize(static_cast<Eigen::Index>(end - begin), dimension);
    for (std::size_t i = begin; i < end; ++i) {
      for (std::size_t d = 0; d < dimension_; ++d) {
        centred(static_cast<Eigen::Index>(i - begin), static_cast<Eigen::Index>(d)) =
            keys[i * dimension_ + d] - mean_[d];
      }
    }
    result.noalias() = centred * axes.transpose();
    for (std::size_t i = begin; i < end; ++i) {
      for (std::size_t d = 0; d < dimension_; ++d) {
        projected[i * dimension_ + d] = static_cast<float>(
            result(static_cast<Eigen::Index>(i - begin), static_cast<Eigen::Index>(d)));
      }
    }
  }
  return projected;
}

void ProjectedKeyScan::build_leaves() {
  const std::size_t box_axes = std::min(dimension_, kBoxAxes);
  std::vector<std::uint32_t> order(rows_);
  std::iota(order.begin(), order.end(), std::uint32_t{0});
  auto coordinate = [&](std::uint32_t index, std::size_t axis) {
    return projected_[static_cast<std::size_t>(index) * dimension_ + axis];
  };
  // Median splits along the box axis of the largest spread, until leaves hold kLeafSize keys.
  std::vector<std::pair<std::size_t, std::size_t>> pending{{0, rows_}};
  while (!pending.empty()) {
    const auto [begin, end] = pending.back();
    pending.pop_back();
    if (end - begin <= kLeafSize || box_axes == 0) {
      std::sort(order.begin() + static_cast<std::ptrdiff_t>(begin),
                order.begin() + static_cast<std::ptrdiff_t>(end));
      leaves_.push_back({begin, end, order[begin]});
      continue;
    }
    std::size_t split_axis = 0;
    float widest = -1.0f;
    for (std::size_t axis = 0; axis < box_axes; ++axis) {
      const auto [low, high] = std::minmax_element(
          order.begin() + static_cast<std::ptrdiff_t>(begin),
          order.begin() + static_cast<std::ptrdiff_t>(end), [&](std::uint32_t a, std::uint32_t b) {
            return coordinate(a, axis) < coordinate(b, axis);
          });
      const float spread = coordinate(*high, axis) - coordinate(*low, axis);
      if (spread > widest) {
        widest = spread;
        split_axis = axis;
      }
    }
    const std::size_t middle = begin + (end - begin) / 2;
    std::nth_element(order.begin() + static_cast<std::ptrdiff_t>(begin),
                     order.begin() + static_cast<std::ptrdiff_t>(middle),
                     order.begin() + static_cast<std::ptrdiff_t>(end),
                     [&](std::uint32_t a, std::uint32_t b) {
                       return coordinate(a, split_axis) < coordinate(b, split_axis);
                     });
    pending.emplace_back(middle, end);
    pending.emplace_back(begin, middle);
  }

  original_ = std::move(order);
  head_.assign(rows_ * kHead, 0.0f);
  keys_.resize(rows_ * dimension_);
  const std::size_t head_axes = std::min(dimension_, kHead);
  for (std::size_t position = 0; position < rows_; ++position) {
    const float* key =
        projected_.data() + static_cast<std::size_t>(original_[position]) * dimension_;
    std::copy_n(key, dimension_, keys_.data() + position * dimension_);
    std::copy_n(key, head_axes, head_.data() + position * kHead);
  }
  box_low_.assign(leaves_.size() * kBoxAxes, 0.0f);
  box_high_.assign(leaves_.size() * kBoxAxes, 0.0f);
  for (std::size_t l = 0; l < leaves_.size(); ++l) {
    for (std::size_t axis = 0; axis < box_axes; ++axis) {
      float low = std::numeric_limits<float>::infinity();
      float high = -std::numeric_limits<float>::infinity();
      for (std::size_t position = leaves_[l].begin; position < leaves_[l].end; ++position) {
        low = std::min(low, head_[position * kHead + axis]);
        high = std::max(high, head_[position * kHead + axis]);
      }
      box_low_[l * kBoxAxes + axis] = low;
      box_high_[l * kBoxAxes + axis] = high;
    }
  }
}

void ProjectedKeyScan::collect(const float* projected_queries, const std::vector<std::size_t>& ends,
                               std::vector<CandidateSet>& candidates) const {
  const LeafData data{head_.data(), keys_.data(), original_.data(), dimension_};
  const float margin = box_bound_margin(dimension_);
  alignas(32) float bounds[kLanes];
  // Scans `leaf` for the lanes of `group` whose box bound is below their admission limit.
  auto visit = [&](LaneGroup& group, std::size_t leaf_index) {
    const unsigned lanes = box_admits(group, box_low_.data() + leaf_index * kBoxAxes,
                                      box_high_.data() + leaf_index * kBoxAxes, margin);
    if (lanes == 0) return;
    // The other lanes sit this leaf out: their box bound proves no key of it could be admitted.
    alignas(32) float saved[kLanes];
    std::copy(group.admit, group.admit + kLanes, saved);
    for (std::size_t lane = 0; lane < kLanes; ++lane) {
      if ((lanes & (1u << lane)) == 0) group.admit[lane] = -1.0f;
    }
    // Keys of a leaf are in index order: those beyond the group's last eligible key are cut.
    const Leaf& leaf = leaves_[leaf_index];
    const auto* first = original_.data() + leaf.begin;
    const auto* last = std::lower_bound(first, original_.data() + leaf.end, group.max_end);
    ProjectedKeyScan::visited_keys_in_thread() += static_cast<std::size_t>(last - first);
    scan(group, data, leaf.begin, leaf.begin + static_cast<std::size_t>(last - first));
    // The scanned lanes' limits were kept up to date by the scan; the others are restored.
    for (std::size_t lane = 0; lane < kLanes; ++lane) {
      if ((lanes & (1u << lane)) == 0) group.admit[lane] = saved[lane];
    }
  };

  const std::size_t queries = ends.size();
  std::vector<LaneGroup> groups;
  // Per lane, the kNearestLeavesPerLane smallest (bound, leaf) pairs seen so far, in order.
  using Nearest = std::array<std::pair<float, std::size_t>, kNearestLeavesPerLane>;
  std::array<Nearest, kLanes> nearest_by_lane;
  std::vector<std::uint8_t> visited_first;  // [group * leaves + leaf]
  for (std::size_t block = 0; block < queries; block += kQueryBlock) {
    const std::size_t block_end = std::min(queries, block + kQueryBlock);
    groups.assign((block_end - block + kLanes - 1) / kLanes, LaneGroup{});
    visited_first.assign(groups.size() * leaves_.size(), 0);
    for (std::size_t g = 0; g < groups.size(); ++g) {
      LaneGroup& group = groups[g];
      for (std::size_t lane = 0; lane < kLanes; ++lane) {
        const std::size_t q = block + g * kLanes + lane;
        if (q >= block_end || ends[q] == 0) continue;
        group.end[lane] = std::min(ends[q], rows_);
        group.query[lane] = projected_queries + q * dimension_;
        group.candidates[lane] = &candidates[q];
        for (std::size_t d = 0; d < std::min(dimension_, kHead); ++d) {
          group.head[d][lane] = group.query[lane][d];
        }
        group.max_end = std::max(group.max_end, group.end[lane]);
      }
      group.refresh_admits();
      if (group.max_end == 0) continue;
      // Each lane's nearest leaves first (by its own box bound).
      const std::pair<float, std::size_t> none{std::numeric_limits<float>::infinity(),
                                               leaves_.size()};
      for (Nearest& lane_nearest : nearest_by_lane) lane_nearest.fill(none);
      for (std::size_t l = 0; l < leaves_.size(); ++l) {
        if (leaves_[l].first_index >= group.max_end) continue;
        box_bounds(group, box_low_.data() + l * kBoxAxes, box_high_.data() + l * kBoxAxes, bounds);
        for (std::size_t lane = 0; lane < kLanes; ++lane) {
          Nearest& lane_nearest = nearest_by_lane[lane];
          if (!(bounds[lane] < lane_nearest.back().first)) continue;
          lane_nearest.back() = {bounds[lane], l};
          std::sort(lane_nearest.begin(), lane_nearest.end());
        }
      }
      std::uint8_t* first_of_group = visited_first.data() + g * leaves_.size();
      for (std::size_t lane = 0; lane < kLanes; ++lane) {
        if (group.candidates[lane] == nullptr) continue;
        for (const auto& [bound, l] : nearest_by_lane[lane]) {
          if (l == leaves_.size() || first_of_group[l] != 0) continue;
          first_of_group[l] = 1;
          visit(group, l);
        }
      }
    }
    // Then every other leaf, each read once for the whole block.
    for (std::size_t l = 0; l < leaves_.size(); ++l) {
      for (std::size_t g = 0; g < groups.size(); ++g) {
        if (leaves_[l].first_index >= groups[g].max_end) continue;
        if (visited_first[g * leaves_.size() + l] != 0) continue;
        visit(groups[g], l);
      }
    }
  }
}

}  // namespace radarpr::retrieval_detail
