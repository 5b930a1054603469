#pragma once

#include <cstddef>

namespace radarpr {

// The outcome of searching one query against its eligible database.
struct QueryResult {
  std::size_t query = 0;  // index in the query sequence
  std::size_t match = 0;  // index of the top-1 database frame
  double distance = 0.0;  // descriptor distance to the top-1 frame
  bool correct = false;   // the top-1 frame lies within the revisit radius of the query
  bool revisit = false;   // some eligible database frame lies within the revisit radius
  // 1-based rank of the first frame within the radius among the top-K retrieved (K = the
  // largest Recall@K asked for); 0 when none is.
  std::size_t first_correct_rank = 0;
};

}  // namespace radarpr
