#include "evaluation/report/point_labels.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace radarpr {
namespace {

// A marker's half width and half height, in characters and lines (the screen style's 1.8-size
// circle is about 1.5 characters across).
constexpr double kMarkerHalfChars = 0.9;
constexpr double kMarkerHalfLines = 0.5;
// A label line's text is a little less than a line tall.
constexpr double kTextHalfLines = 0.45;

struct Box {
  double left, right, bottom, top;  // characters, lines
  // The area two boxes share (characters x lines).
  double overlap(const Box& other) const {
    const double width = std::min(right, other.right) - std::max(left, other.left);
    const double height = std::min(top, other.top) - std::max(bottom, other.bottom);
    return width > 0.0 && height > 0.0 ? width * height : 0.0;
  }
  double area() const { return (right - left) * (top - bottom); }
};

Box marker_box(const LabelledPoint& point, const LabelGrid& grid) {
  const double x = point.x * grid.width_chars, y = point.y * grid.height_lines;
  return {x - kMarkerHalfChars, x + kMarkerHalfChars, y - kMarkerHalfLines, y + kMarkerHalfLines};
}

Box label_box(const LabelledPoint& point, const LabelPlacement& place, const LabelGrid& grid) {
  const double x = point.x * grid.width_chars + place.dx_chars;
  const double y = point.y * grid.height_lines + place.dy_lines;
  const auto chars = static_cast<double>(point.chars);
  return place.left_of_point ? Box{x - chars, x, y - kTextHalfLines, y + kTextHalfLines}
                             : Box{x, x + chars, y - kTextHalfLines, y + kTextHalfLines};
}

// The places tried, in order: right then left of the point, level with it, then just below, then
// a line further up and down. No further: a label far from its point would name another.
std::vector<LabelPlacement> candidates() {
  std::vector<LabelPlacement> places;
  for (const double dy : {0.4, -0.6, 1.4, -1.6}) {
    places.push_back({0.9, dy, false});
    places.push_back({-0.9, dy, true});
  }
  return places;
}

}  // namespace

std::vector<LabelPlacement> place_point_labels(const std::vector<LabelledPoint>& labels,
                                               const std::vector<LabelledPoint>& markers,
                                               const LabelGrid& grid) {
  std::vector<Box> marker_boxes;
  for (const auto& marker : markers) marker_boxes.push_back(marker_box(marker, grid));
  const Box plot{0.0, grid.width_chars, 0.0, grid.height_lines};
  std::vector<Box> placed;
  std::vector<LabelPlacement> result;
  for (const auto& label : labels) {
    LabelPlacement best = candidates().front();
    double best_cost = std::numeric_limits<double>::max();
    for (const auto& place : candidates()) {
      const Box box = label_box(label, place, grid);
      // Text outside the plot is cut off or collides with the tick labels: only when nothing
      // else will do. Text over a marker hides a point: worse than over another label.
      double cost = 1000.0 * (box.area() - box.overlap(plot));
      for (const Box& other : marker_boxes) cost += 2.0 * box.overlap(other);
      for (const Box& other : placed) cost += box.overlap(other);
      if (cost < best_cost) {
        best = place;
        best_cost = cost;
      }
      if (cost == 0.0) break;
    }
    placed.push_back(label_box(label, best, grid));
    result.push_back(best);
  }
  return result;
}

}  // namespace radarpr
