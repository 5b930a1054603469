#pragma once

#include <cstddef>

namespace radarpr {

// An optional second face of a descriptor's PreparedDistances (found by dynamic_cast, so the
// plugin interface is unchanged): a score per pair, cheap in bulk, that orders the database like
// the distance up to a known error. An exhaustive search then computes distance() only for the
// pairs whose score lies within twice the error of the k-th best score, and still returns the
// exact k nearest (evaluation/retrieval/screened_search.hpp).
//
// Contract: for a fixed query q there is a score s(q, j) such that distance(q, j) never grows
// when s(q, j) grows, and |scores(q, ...)[j] - s(q, j)| <= score_error(q) for every database
// value j.
class ScreenedDistances {
 public:
  virtual ~ScreenedDistances() = default;
  // At most this many queries per scores() call (they share each load of the database).
  static constexpr std::size_t kMaxQueries = 4;
  // Scores of queries[0, query_count) against database values [begin, end): query i's into
  // scores[i * (end - begin) + (j - begin)]. Larger is nearer. `begin` is a multiple of 8.
  // Thread-safe.
  virtual void scores(const std::size_t* queries, std::size_t query_count, std::size_t begin,
                      std::size_t end, float* scores) const = 0;
  // The bound on a score's error for `query`; not finite when the scores do not order this
  // query's distances (the search then computes every distance of it).
  virtual double score_error(std::size_t query) const = 0;
};

}  // namespace radarpr
