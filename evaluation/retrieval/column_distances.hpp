#pragma once

#include <cstddef>

// Internal to the blocked L2 search (blocked_l2_search.cpp): the distances of one column of its
// products, in a file of their own so that only this loop is compiled without trapping math.
namespace radarpr::retrieval_detail {

// For the queries r in [first, rows): keys[r] = max(query_norms[r] + database_norm - 2 dots[r], 0)
// rounded to float (dots: one database value's dot products with the queries). Returns whether
// any key lies below thresholds[r].
bool column_distances(const float* dots, const double* query_norms, double database_norm,
                      std::size_t first, std::size_t rows, const float* thresholds, float* keys);
bool column_distances(const double* dots, const double* query_norms, double database_norm,
                      std::size_t first, std::size_t rows, const float* thresholds, float* keys);

}  // namespace radarpr::retrieval_detail
