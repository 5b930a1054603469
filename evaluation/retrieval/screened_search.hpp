#pragma once

#include <cstddef>
#include <vector>

#include "descriptors/descriptor.hpp"
#include "descriptors/screened_distances.hpp"
#include "evaluation/retrieval/retrieval.hpp"

namespace radarpr::retrieval_detail {

// RetrievalMethod::exhaustive for a PreparedDistances that is also ScreenedDistances: every pair's
// score in bulk, then distance() only for the database values whose score lies within twice the
// score error of the k-th best score - a set that holds the exact k nearest, ties included, so
// the result equals the plain exhaustive search's. Queries are taken in groups that share each
// block of database values while it is in cache. Same contract as retrieve_nearest.
std::vector<std::vector<Neighbour>> retrieve_screened(const PreparedDistances& prepared,
                                                      const ScreenedDistances& screen,
                                                      std::size_t query_count,
                                                      const std::vector<std::size_t>& eligible_ends,
                                                      std::size_t k);

}  // namespace radarpr::retrieval_detail
