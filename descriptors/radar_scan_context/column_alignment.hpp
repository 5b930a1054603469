#pragma once

#include <optional>
#include <span>

namespace radarpr {

// The column-shift cosine comparison of two scan contexts (descriptors.md §4).

// The best circular column shift of context `a` against context `b` and its similarity.
struct ColumnAlignment {
  int shift = 0;            // s in [0, sectors)
  double similarity = 0.0;  // sim(s), in [-1, 1]
};

// Both contexts are rings x sectors, row-major (row = ring, column = sector). Shift convention:
// a shifted by s is a_s[:, j] = a[:, (j - s) mod sectors], i.e. a's columns move s places towards
// higher sector indices, as referee_a_best_shift rolls its vectors. sim(s) is the mean, over the
// columns j that are non-zero both in a_s and in b, of cos(a_s[:, j], b[:, j]), computed in
// double. Returns the s maximising sim(s) (the smallest s among ties); empty when no shift has a
// single qualifying column pair. Throws std::invalid_argument when a size disagrees with
// rings x sectors, rings or sectors is < 1, or a value is not finite.
std::optional<ColumnAlignment> best_column_alignment(std::span<const float> a,
                                                     std::span<const float> b, int rings,
                                                     int sectors);

}  // namespace radarpr
