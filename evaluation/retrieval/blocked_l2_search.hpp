#pragma once

#include <cstddef>
#include <vector>

#include "descriptors/descriptor.hpp"
#include "evaluation/retrieval/l2_rows.hpp"
#include "evaluation/retrieval/retrieval.hpp"

namespace radarpr::retrieval_detail {

// The length every exhaustive_l2 value shares. Throws std::invalid_argument naming the first
// database or query value of another length, or when the values are empty: checked before any
// distance() runs, since a descriptor's distance() may take equal lengths for granted.
std::size_t common_dimension(const std::vector<DescriptorValue>& database,
                             const std::vector<DescriptorValue>& queries);

// RetrievalMethod::exhaustive_l2: squared L2 distances |q|^2 + |d|^2 - 2 q.d from float matrix
// products over blocks of queries and database values (never an N x N matrix), then the database
// values within a rounding band of the k-th nearest re-ranked by distance(), so the result
// equals the exhaustive search's. Same contract as retrieve_nearest.
std::vector<std::vector<Neighbour>> retrieve_exhaustive_l2(
    const Descriptor& descriptor, const std::vector<DescriptorValue>& database,
    const std::vector<DescriptorValue>& queries, const std::vector<std::size_t>& eligible_ends,
    std::size_t k);

// The same over rows read where they lie (lengths equal and at least 1, eligible ends within the
// database: checked by the callers). Holds at most a few blocks of rows at a time besides the
// query block being searched, whatever the database's size.
std::vector<std::vector<Neighbour>> retrieve_exhaustive_l2(
    const Descriptor& descriptor, const L2Rows& database, const L2Rows& queries,
    const std::vector<std::size_t>& eligible_ends, std::size_t k);

}  // namespace radarpr::retrieval_detail
