#include "evaluation/retrieval/column_distances.hpp"

#include <algorithm>

namespace radarpr::retrieval_detail {
namespace {

// Two passes, each vectorised: the distances, then the comparison (a branch per key in one loop
// would keep it scalar).
template <typename Dot>
bool distances(const Dot* dots, const double* query_norms, double database_norm, std::size_t first,
               std::size_t rows, const float* thresholds, float* keys) {
  for (std::size_t r = first; r < rows; ++r) {
    const double squared = query_norms[r] + database_norm - 2.0 * static_cast<double>(dots[r]);
    keys[r] = static_cast<float>(std::max(squared, 0.0));
  }
  int any = 0;
  for (std::size_t r = first; r < rows; ++r) any |= keys[r] < thresholds[r];
  return any != 0;
}

}  // namespace

bool column_distances(const float* dots, const double* query_norms, double database_norm,
                      std::size_t first, std::size_t rows, const float* thresholds, float* keys) {
  return distances(dots, query_norms, database_norm, first, rows, thresholds, keys);
}

bool column_distances(const double* dots, const double* query_norms, double database_norm,
                      std::size_t first, std::size_t rows, const float* thresholds, float* keys) {
  return distances(dots, query_norms, database_norm, first, rows, thresholds, keys);
}

}  // namespace radarpr::retrieval_detail
