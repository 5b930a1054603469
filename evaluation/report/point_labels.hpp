#pragma once

#include <cstddef>
#include <vector>

namespace radarpr {

// The plot area in units of its label text: how many label characters fit across it and how
// many label lines fit up it (measured on the drawn figures of each style).
struct LabelGrid {
  double width_chars = 85.0;
  double height_lines = 34.0;
};

// A point to name: where it is in the plot (fractions of the x and y ranges, 0..1) and its
// label's length in characters.
struct LabelledPoint {
  double x = 0.0;
  double y = 0.0;
  std::size_t chars = 0;
};

// Where a label goes, as gnuplot's `offset char dx,dy` from its point: left-aligned to the right
// of the point, or right-aligned to its left.
struct LabelPlacement {
  double dx_chars = 0.9;
  double dy_lines = 0.4;
  bool left_of_point = false;
};

// A place for each label in turn, the first that is clear: beside its point on the right, else on
// the left (a label that would run past the plot's right edge goes there), else just below, else
// a line further up or down, each inside the plot and clear of every point's marker (`markers`,
// in the same coordinates; the labelled points among them) and of the labels placed before it.
// When none is clear (a crowd), the one that covers the least of markers and labels.
std::vector<LabelPlacement> place_point_labels(const std::vector<LabelledPoint>& labels,
                                               const std::vector<LabelledPoint>& markers,
                                               const LabelGrid& grid);

}  // namespace radarpr
