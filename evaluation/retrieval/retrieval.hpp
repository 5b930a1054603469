#pragma once

#include <cstddef>
#include <vector>

#include "descriptors/descriptor.hpp"
#include "evaluation/retrieval/l2_rows.hpp"

namespace radarpr {

struct Neighbour {
  std::size_t index = 0;  // database index
  double distance = 0.0;  // descriptor.distance(query, database[index])
};

// For each query i, the k database values nearest to queries[i] among database[0,
// eligible_ends[i]), nearest first (ties: smaller index first); fewer when fewer are eligible,
// none when eligible_ends[i] == 0. The strategy is the descriptor's retrieval method:
// - kdtree: exact FLANN KD-trees over the search keys (over aligned blocks of the growing
//   single-session prefix) where a sample of queries shows they touch few keys, else a scan of
//   every key that rejects most of them by cheap lower bounds on their principal axes
//   (ProjectedKeyScan); either way the result equals the exhaustive search's.
// - key_then_rerank: the rerank_candidates() nearest keys found the same way, re-ranked by
//   distance(); at most min(k, rerank_candidates()) neighbours.
// - exhaustive: the descriptor's prepare_distances() against every eligible value (screened by
//   their scores first where they offer them: ScreenedDistances; the same result).
// - exhaustive_l2: blocked float matrix products, the nearest re-checked with distance(); equals
//   the exhaustive search's.
// Single session passes the same vector twice. Runs on every core.
std::vector<std::vector<Neighbour>> retrieve_nearest(const Descriptor& descriptor,
                                                     const std::vector<DescriptorValue>& database,
                                                     const std::vector<DescriptorValue>& queries,
                                                     const std::vector<std::size_t>& eligible_ends,
                                                     std::size_t k);

// retrieve_nearest for an exhaustive_l2 descriptor over values read where they lie (a
// memory-mapped matrix, L2Rows): the database is streamed a block at a time and let go of again,
// so memory does not grow with its size. The same checks (throwing std::invalid_argument, also
// for another retrieval method or values of different lengths) and the same result as
// retrieve_nearest on the same values.
std::vector<std::vector<Neighbour>> retrieve_nearest_l2(
    const Descriptor& descriptor, const L2Rows& database, const L2Rows& queries,
    const std::vector<std::size_t>& eligible_ends, std::size_t k);

}  // namespace radarpr
