// Where the AUC-against-size figure names its points: beside each, inside the plot, clear of the
// other points and labels; a near tie's labels apart, a long label at the right edge to the left
// of its point, a point at the top named below it.
#include <gtest/gtest.h>

#include "evaluation/report/point_labels.hpp"

namespace radarpr {
namespace {

const LabelGrid kGrid{30.0, 16.0};

TEST(PointLabels, AClearPointIsNamedOnItsRightLevelWithIt) {
  const std::vector<LabelledPoint> points{{0.3, 0.5, 7}};
  const auto places = place_point_labels(points, points, kGrid);
  ASSERT_EQ(places.size(), 1u);
  EXPECT_FALSE(places[0].left_of_point);
  EXPECT_DOUBLE_EQ(places[0].dx_chars, 0.9);
  EXPECT_DOUBLE_EQ(places[0].dy_lines, 0.4);
}

TEST(PointLabels, ALabelThatWouldRunPastTheRightEdgeGoesLeft) {
  // 26 of 30 characters across: "RadVLAD-DS" would end at 37.
  const std::vector<LabelledPoint> points{{26.2 / 30.0, 0.5, 10}};
  const auto places = place_point_labels(points, points, kGrid);
  EXPECT_TRUE(places[0].left_of_point);
  EXPECT_LT(places[0].dx_chars, 0.0);
}

TEST(PointLabels, APointAtTheTopIsNamedBelowIt) {
  const std::vector<LabelledPoint> points{{0.3, 1.0, 7}};
  EXPECT_LT(place_point_labels(points, points, kGrid)[0].dy_lines, 0.0);
}

// RadVLAD-DS (0.821) and RadarSC (0.818) of the synthetic paper table: a quarter of a decade
// apart, the first label ran over the second point.
TEST(PointLabels, ANearTiesLabelsStayClearOfEachOtherAndOfThePoints) {
  const std::vector<LabelledPoint> points{{0.467, 0.489, 10}, {0.54, 0.481, 7}};
  const auto places = place_point_labels(points, points, LabelGrid{85.0, 33.0});
  // Each label's span in characters and lines.
  struct Span {
    double left, right, bottom, top;
  };
  std::vector<Span> spans;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double x = points[i].x * 85.0 + places[i].dx_chars;
    const double y = points[i].y * 33.0 + places[i].dy_lines;
    const auto chars = static_cast<double>(points[i].chars);
    spans.push_back(places[i].left_of_point ? Span{x - chars, x, y - 0.45, y + 0.45}
                                            : Span{x, x + chars, y - 0.45, y + 0.45});
  }
  const auto apart = [](const Span& a, const Span& b) {
    return a.right <= b.left || b.right <= a.left || a.top <= b.bottom || b.top <= a.bottom;
  };
  EXPECT_TRUE(apart(spans[0], spans[1]));
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (const auto& point : points) {
      const Span marker{point.x * 85.0 - 0.9, point.x * 85.0 + 0.9, point.y * 33.0 - 0.5,
                        point.y * 33.0 + 0.5};
      EXPECT_TRUE(apart(spans[i], marker) || (&point == &points[i])) << i;
    }
  }
}

}  // namespace
}  // namespace radarpr
