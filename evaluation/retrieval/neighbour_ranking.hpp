#pragma once

#include <cstddef>
#include <vector>

#include "descriptors/descriptor.hpp"
#include "evaluation/retrieval/retrieval.hpp"

// Internal to the retrieval strategies: the final, exact ordering by the descriptor's distance.
namespace radarpr::retrieval_detail {

// Nearest first; equal distances: the smaller database index first.
bool nearer(const Neighbour& a, const Neighbour& b);

// `distance`, or a runtime_error naming the pair when it is NaN.
double checked_distance(double distance, std::size_t query_index, std::size_t database_index);

// Orders candidates by distance(), ties by smaller index, and keeps the k nearest.
std::vector<Neighbour> rank_by_distance(const Descriptor& descriptor, const DescriptorValue& query,
                                        const std::vector<DescriptorValue>& database,
                                        const std::vector<std::size_t>& candidates, std::size_t k,
                                        std::size_t query_index);

}  // namespace radarpr::retrieval_detail
