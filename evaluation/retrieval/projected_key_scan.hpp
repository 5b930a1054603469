#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "evaluation/retrieval/candidate_set.hpp"

namespace radarpr::retrieval_detail {

// An exact search of search keys that skips most of the database after a few multiplications.
// The keys are moved to their principal axes (centred on the database mean, rotated by the
// eigenvectors of its covariance): distances do not change, and the leading axes carry most of
// the spread. Squared distances over leading axes are lower bounds of the whole squared distance:
// - the database is cut into leaves of about kLeafSize keys by median splits along the leading
//   kBoxAxes axes; the distance from a query to a leaf's bounding box bounds every key in it, so
//   a leaf whose bound reaches the query's admission limit (its k-th nearest so far plus the
//   candidate band) is skipped whole;
// - in a leaf that is visited, a key whose distance over the first kFirstStage axes reaches the
//   limit is rejected, then one whose distance over kHead axes does; the others get their whole
//   distance.
// Each query first visits the few leaves nearest to it, so that its limit is nearly final before
// the others are judged. Queries go 8 at a time (one per vector lane), so a leaf is scanned when
// any of the 8 needs it. Measured on ReFeree values of two synthetic drives (50 floats, 10^5
// scans each, top-1, each query against the other drive): a group of 8 queries scans about 57%
// of the keys, and 4 keys in 1000 need their whole distance; 0.7-1 ns per (query, key) pair on
// one core, against 11 ns for the plain scan of the keys it replaces.
// Nothing is approximate: a key that is skipped could not have been admitted, whatever the order
// (see the bound margins in the .cpp), so the candidates equal those of a plain scan of the
// projected keys; the projection's rounding changes a squared distance by less than
// projection_error(), which the caller's band must cover.
class ProjectedKeyScan {
 public:
  static constexpr std::size_t kFirstStage = 10;
  static constexpr std::size_t kHead = 16;  // leading coordinates stored with every key
  static constexpr std::size_t kBoxAxes = 8;
  static constexpr std::size_t kLeafSize = 64;

  // `keys`: rows x dimension floats, row-major, finite. Copies what it needs.
  ProjectedKeyScan(const float* keys, std::size_t rows, std::size_t dimension);

  std::size_t dimension() const { return dimension_; }
  // The keys on the principal axes, rows x dimension, row-major.
  std::vector<float> project(const float* keys, std::size_t rows) const;
  // The database keys as project() gives them.
  const std::vector<float>& projected_database() const { return projected_; }
  // The largest change of a squared distance between keys of squared norms (after centring) at
  // most max_squared_norm caused by rounding their projections to float.
  static float projection_error(float max_squared_norm);
  // The largest squared norm of the projected database keys.
  float max_squared_norm() const { return max_squared_norm_; }

  // For every query q (row q of `projected_queries`, as project() gives them), adds to
  // candidates[q] (addPoint, database indices) every database key in [0, ends[q]) that a scan of
  // all of them would leave among its candidates (in some order). Safe to call from several
  // threads at once.
  void collect(const float* projected_queries, const std::vector<std::size_t>& ends,
               std::vector<CandidateSet>& candidates) const;

  // Whether the AVX2 kernels may run where the CPU has them (the default); tests turn them off
  // to check the portable kernels too. Affects every scan of the process.
  static void allow_vector_kernels(bool allowed);

  // Diagnostics, for measurements and tests: scans built in this process so far (retrieval
  // chose this over the KD-trees), and, for the scans of this thread, keys whose whole distance
  // was computed and keys in visited leaves.
  static std::size_t built_in_process();
  static std::size_t& full_distances_in_thread();
  static std::size_t& visited_keys_in_thread();

 private:
  struct Leaf {
    std::size_t begin = 0;  // positions in leaf order
    std::size_t end = 0;
    std::size_t first_index = 0;  // the smallest database index in the leaf
  };
  void build_leaves();

  std::size_t rows_ = 0;
  std::size_t dimension_ = 0;
  std::vector<double> mean_;
  std::vector<double> axes_;      // dimension x dimension, row a = axis a (largest spread first)
  std::vector<float> projected_;  // rows x dimension, database order
  float max_squared_norm_ = 0.0f;
  // In leaf order: each leaf's keys by increasing database index.
  std::vector<Leaf> leaves_;
  std::vector<float> box_low_;           // leaves x kBoxAxes
  std::vector<float> box_high_;          // leaves x kBoxAxes
  std::vector<std::uint32_t> original_;  // leaf position -> database index
  std::vector<float> head_;              // rows x kHead (zero-padded)
  std::vector<float> keys_;              // rows x dimension
};

}  // namespace radarpr::retrieval_detail
