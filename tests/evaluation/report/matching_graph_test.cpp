// The matching graph's drawing: x and y at one scale, the threshold named in the key, TP lines
// translucent under the FP lines, a top view beside the 3-D one, and a missed revisit joined to
// the loop frame it should have found rather than the one it retrieved.
#include <gtest/gtest.h>

#include "evaluation/report/figure_files.hpp"

namespace radarpr {
namespace {

bool contains(const std::string& text, const std::string& what) {
  return text.find(what) != std::string::npos;
}

// A single session going east along y = 0 and back along y = 2: frame f at x = f (0..9), then
// frame 10 + i at x = 9 - i. Query 15 (x = 4, y = 2) missed its revisit; it retrieved frame 0.
DatasetTrajectory out_and_back() {
  DatasetTrajectory trajectory;
  for (std::size_t f = 0; f < 20; ++f) {
    trajectory.query.push_back(
        {f, f < 10 ? static_cast<double>(f) : static_cast<double>(19 - f), f < 10 ? 0.0 : 2.0});
  }
  return trajectory;
}

ResultRow missed_row() {
  ResultRow row;
  row.graph = {{15, 0, "fn", 4.0, 2.0, 0.0, 0.0}, {16, 3, "tp", 3.0, 2.0, 3.0, 0.0}};
  return row;
}

TEST(MatchingGraph, AMissedRevisitIsJoinedToItsNearestEligibleLoopFrame) {
  MatchingGraphContext context;
  context.include_missed = true;
  context.revisit_radius_m = 5.0;
  context.exclude_recent_frames = 3;
  const FigureFiles figure =
      matching_graph_figure("graph_x", "x", missed_row(), out_and_back(), context);
  // From (4, 2, frame 15) to frame 4 at (4, 0): dx 0, dy -2, dz -11; not to frame 0.
  EXPECT_TRUE(contains(figure.csv, "4,2,15,0,-2,-11,fn\n")) << figure.csv;
  // Frames newer than the recency window are not eligible, however near: excluding the 12 most
  // recent, frame 3 at (3, 0) is the nearest eligible one within the radius.
  context.exclude_recent_frames = 12;
  const FigureFiles older =
      matching_graph_figure("graph_x", "x", missed_row(), out_and_back(), context);
  EXPECT_TRUE(contains(older.csv, "4,2,15,-1,-2,-12,fn\n")) << older.csv;
  // Without include_missed the FN is not drawn.
  context.include_missed = false;
  EXPECT_FALSE(contains(
      matching_graph_figure("graph_x", "x", missed_row(), out_and_back(), context).csv, ",fn\n"));
}

TEST(MatchingGraph, ScriptsShowOneScaleTheThresholdAndTranslucentTrueMatches) {
  MatchingGraphContext context;
  context.threshold_text = "F1-max threshold: d \u2264 0.0012";
  const std::string graph =
      matching_graph_figure("graph_x", "x", missed_row(), out_and_back(), context).script;
  EXPECT_TRUE(contains(graph, "set view equal xy\n")) << graph;
  EXPECT_TRUE(contains(graph, "splot ")) << graph;
  EXPECT_TRUE(contains(graph, "set key title 'F1-max threshold: d \u2264 0.0012'")) << graph;
  // TP translucent (#AARRGGBB), FP opaque red drawn after it.
  EXPECT_TRUE(contains(graph, "lc rgb '#a01a9641' title 'TP (1)'")) << graph;
  EXPECT_TRUE(contains(graph, "title 'trajectory'")) << graph;
  // A multi session: one legend entry per session's trajectory, in two styles.
  ResultRow multi = missed_row();
  multi.multi_session = true;
  DatasetTrajectory sessions = out_and_back();
  sessions.database = sessions.query;
  const std::string two = matching_graph_figure("graph_y", "y", multi, sessions, context).script;
  EXPECT_TRUE(contains(two, "with lines lw 4 lc rgb '#c8c8c8' title 'database trajectory'")) << two;
  EXPECT_TRUE(contains(two, "with lines lw 1 dt 2 lc rgb '#404040' title 'query trajectory'"))
      << two;
  // Ticks 1-2-5 apart, at most 4 intervals: the corner labels do not collide.
  EXPECT_TRUE(contains(graph, "set xtics 5\nset ytics 5, 5\n")) << graph;
  EXPECT_TRUE(contains(two, "set zlabel 'frame (database, then query session)'")) << two;
  // In the paper column its 8 pt labels are large beside the plot: the y labels and the axis
  // names further out, and the frame axis named short, clear of the key.
  MatchingGraphContext paper = context;
  paper.style = FigureStyle::paper;
  const std::string column = matching_graph_figure("graph_y", "y", multi, sessions, paper).script;
  EXPECT_TRUE(contains(column, "set view equal xy\n")) << column;
  EXPECT_TRUE(contains(column, "set ytics offset 2.5,0\nset xlabel offset -3,-1\n")) << column;
  EXPECT_TRUE(contains(column, "set zlabel 'frame' rotate parallel")) << column;
  EXPECT_FALSE(contains(graph, "set xlabel offset")) << graph;
  context.top_view = true;
  const std::string top =
      matching_graph_figure("graphxy_x", "x", missed_row(), out_and_back(), context).script;
  EXPECT_TRUE(contains(top, "set size ratio -1\n")) << top;
  EXPECT_TRUE(contains(top, "\nplot ")) << top;
  EXPECT_FALSE(contains(top, "splot")) << top;
}

}  // namespace
}  // namespace radarpr
