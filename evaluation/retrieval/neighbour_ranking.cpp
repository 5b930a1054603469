#include "evaluation/retrieval/neighbour_ranking.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace radarpr::retrieval_detail {

bool nearer(const Neighbour& a, const Neighbour& b) {
  return a.distance < b.distance || (a.distance == b.distance && a.index < b.index);
}

double checked_distance(double distance, std::size_t query_index, std::size_t database_index) {
  if (std::isnan(distance)) {
    throw std::runtime_error("retrieve_nearest: the descriptor's distance between query " +
                             std::to_string(query_index) + " and database value " +
                             std::to_string(database_index) + " is NaN");
  }
  return distance;
}

std::vector<Neighbour> rank_by_distance(const Descriptor& descriptor, const DescriptorValue& query,
                                        const std::vector<DescriptorValue>& database,
                                        const std::vector<std::size_t>& candidates, std::size_t k,
                                        std::size_t query_index) {
  std::vector<Neighbour> ranked;
  ranked.reserve(candidates.size());
  for (const std::size_t index : candidates) {
    ranked.push_back(
        {index, checked_distance(descriptor.distance(query, database[index]), query_index, index)});
  }
  const std::size_t kept = std::min(k, ranked.size());
  std::partial_sort(ranked.begin(), ranked.begin() + static_cast<std::ptrdiff_t>(kept),
                    ranked.end(), nearer);
  ranked.resize(kept);
  return ranked;
}

}  // namespace radarpr::retrieval_detail
