#pragma once

#include <cstddef>
#include <vector>

#include "descriptors/descriptor.hpp"
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

}  // namespace radarpr::retrieval_detail
