// The figures' look, from their scripts: keys outside the plot, an explicit palette, a neutral
// F1-max marker, and the AUC-against-size means worked by hand.
#include <gtest/gtest.h>

#include <set>

#include "evaluation/report/figure_files.hpp"
#include "evaluation/results/auc_size.hpp"
#include "evaluation/results/paper_tables.hpp"

namespace radarpr {
namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// Two 3-point sweeps; the F1-max at the middle threshold.
const std::vector<SweepPoint> kCurve = {
    {0.1, 1.0, 0.2, 0.0, 0.33}, {0.5, 0.8, 0.6, 0.2, 0.69}, {0.9, 0.5, 1.0, 0.7, 0.67}};

std::vector<CurveSeries> two_series(int second_dash) {
  return {{"a", &kCurve, 0.5, 0.69, 0.8, 0, 1}, {"b", &kCurve, 0.5, 0.69, 0.7, 11, second_dash}};
}

TEST(ReportFigureStyle, PaletteHasTwelveDistinctColoursWithoutBlack) {
  const auto& palette = figure_palette();
  EXPECT_GE(palette.size(), 10u);
  EXPECT_EQ(std::set<std::string>(palette.begin(), palette.end()).size(), palette.size());
  for (const auto& colour : palette) EXPECT_NE(colour, "#000000");
}

TEST(ReportFigureStyle, CurveKeysSitOutsideAndTheF1MarkerIsBlack) {
  for (const auto& figure : {pr_figure("pr_x", "x", two_series(1)),
                             roc_figure("roc_x", "x", two_series(1), KeyPlace::below)}) {
    const std::string& gp = figure.script;
    EXPECT_TRUE(gp.find("set key outside right") != std::string::npos ||
                gp.find("set key at screen 0.5") != std::string::npos)
        << gp;
    EXPECT_EQ(gp.find("opaque"), std::string::npos) << gp;
    // Each series in its palette colour, line and F1-max point alike (series b: index 11).
    EXPECT_EQ(count(gp, "lc rgb '" + figure_palette()[0] + "'"), 2u) << gp;
    EXPECT_EQ(count(gp, "lc rgb '" + figure_palette()[11] + "'"), 2u) << gp;
    // One key entry for the F1-max points: a black marker drawn from no data.
    EXPECT_EQ(count(gp, "title 'F1-max'"), 1u) << gp;
    EXPECT_NE(gp.find("NaN with points pt 7 ps 1.6 lc rgb 'black' title 'F1-max'"),
              std::string::npos)
        << gp;
  }
  // Below the plot: placed by hand, with a bottom margin that keeps the axis label clear.
  const std::string below = roc_figure("r", "x", two_series(1), KeyPlace::below).script;
  EXPECT_NE(below.find("set key at screen 0.5, screen "), std::string::npos) << below;
  EXPECT_NE(below.find("set bmargin at screen "), std::string::npos) << below;
}

// Colour, dash type and marker per series, markers at a different interval per series so that
// identical curves (series a and b share kCurve) both stay visible; thick lines.
TEST(ReportFigureStyle, EachSeriesHasItsDashTypeMarkerAndMarkerInterval) {
  const std::string gp = pr_figure("pr_x", "x", two_series(3)).script;
  EXPECT_EQ(
      count(gp, "with linespoints lw 3 dt 1 pt 4 ps 1.2 pi 2 lc rgb '" + figure_palette()[0] + "'"),
      1u)
      << gp;
  EXPECT_EQ(count(gp, "with linespoints lw 3 dt 3 pt 8 ps 1.2 pi 5 lc rgb '" +
                          figure_palette()[11] + "'"),
            1u)
      << gp;
}

// ROC: a square plot with the chance diagonal, named in the key; PR neither.
TEST(ReportFigureStyle, RocIsSquareWithTheChanceDiagonal) {
  const std::string roc = roc_figure("roc_x", "x", two_series(1)).script;
  EXPECT_NE(roc.find("set size square"), std::string::npos) << roc;
  EXPECT_NE(roc.find("plot x with lines lw 1.5 dt 2 lc rgb 'gray60' title 'chance'"),
            std::string::npos)
      << roc;
  const std::string pr = pr_figure("pr_x", "x", two_series(1)).script;
  EXPECT_EQ(pr.find("set size square"), std::string::npos) << pr;
  EXPECT_EQ(pr.find("chance"), std::string::npos) << pr;
}

TEST(ReportFigureStyle, CurvesDropPointsWithinAThousandthButKeepTheEnds) {
  // PR points (recall, precision): the 2nd and 3rd lie within 1e-3 of the 1st in both
  // coordinates (|0.5008 - 0.5| = 0.0008): dropped. The 4th moves 0.1: kept. The 5th is within
  // 1e-3 of the 4th but is the end: kept. Rows: 1st, 4th, 5th, then the F1-max block.
  const std::vector<SweepPoint> curve = {{0.1, 1.0, 0.5, 0.0, 0.6},
                                         {0.2, 0.9996, 0.5004, 0.0, 0.6},
                                         {0.3, 0.9992, 0.5008, 0.0, 0.6},
                                         {0.4, 0.9, 0.6, 0.0, 0.7},
                                         {0.5, 0.8995, 0.6005, 0.0, 0.7}};
  const FigureFiles figure = pr_figure("pr", "x", {{"a", &curve, 0.2, 0.6, std::nullopt, 0, 1}});
  EXPECT_EQ(figure.csv,
            "recall,precision,threshold,series\n0.5,1,0.1,\"a\"\n0.6,0.9,0.4,\"a\"\n"
            "0.6005,0.8995,0.5,\"a\"\n\n\n0.5004,0.9996,0.2,\"a\"\n");
}

// Descriptors a (2 single datasets, 1 multi) and b (2 single, one AUC n/a).
RunResults hand_run() {
  RunResults run;
  run.descriptors = {"a", "b"};
  auto row = [](const char* dataset, bool multi, const char* id, double bytes,
                std::optional<double> auc) {
    ResultRow r;
    r.dataset = dataset;
    r.multi_session = multi;
    r.descriptor = id;
    r.label = std::string("label ") + id;
    r.payload_bytes = bytes;
    r.roc_auc = auc;
    return r;
  };
  run.rows = {row("d1", false, "a", 100, 0.8), row("d1", false, "b", 40, std::nullopt),
              row("d2", false, "a", 100, 0.6), row("d2", false, "b", 40, 0.9),
              row("d3", true, "a", 100, 0.7),  row("d3", true, "b", 40, 0.5)};
  return run;
}

TEST(ReportAucSize, MeansPerSessionKindWorkedByHand) {
  const auto points = auc_size_points(hand_run());
  ASSERT_EQ(points.size(), 4u);  // single a, single b, multi a, multi b
  // a single: (0.8 + 0.6) / 2 = 0.7 over 2 of 2; b single: 0.9 alone, 1 of 2 (d1 is n/a).
  EXPECT_FALSE(points[0].multi_session);
  EXPECT_EQ(points[0].descriptor, "a");
  EXPECT_NEAR(*points[0].mean_auc, 0.7, 1e-12);
  EXPECT_EQ(points[0].datasets_averaged, 2u);
  EXPECT_EQ(points[1].descriptor, "b");
  EXPECT_NEAR(*points[1].mean_auc, 0.9, 1e-12);
  EXPECT_EQ(points[1].datasets_averaged, 1u);
  EXPECT_EQ(points[1].datasets_run, 2u);
  EXPECT_EQ(points[1].descriptor_index, 1u);
  EXPECT_TRUE(points[3].multi_session);
  EXPECT_NEAR(*points[3].mean_auc, 0.5, 1e-12);

  // Single session averages 2 and 1 datasets: said, naming b; the multi session is even.
  const auto note = auc_size_unequal_note(points);
  ASSERT_TRUE(note.has_value());
  EXPECT_NE(note->find("single session: label a 2 of 2, label b 1 of 2"), std::string::npos)
      << *note;
  EXPECT_EQ(note->find("multi session"), std::string::npos) << *note;
  auto even = points;
  even[1].datasets_averaged = 2;
  EXPECT_FALSE(auc_size_unequal_note(even).has_value());

  const Table table = auc_size_table(points);
  ASSERT_EQ(table.rows.size(), 4u);
  EXPECT_EQ(table.rows[1][0].text, "label b");
  EXPECT_EQ(table.rows[1][3].text, "0.900");
  EXPECT_EQ(table.rows[1][4].text, "1 of 2");
  EXPECT_EQ(table.rows[0][2].text, "100");
}

TEST(ReportAucSize, FigureNamesDescriptorsInTheKeyAndFitsTheAxisToTheData) {
  const auto points = auc_size_points(hand_run());
  const FigureFiles figure = auc_size_figure("auc_vs_size", points);
  const std::string& gp = figure.script;
  EXPECT_EQ(count(gp, "title 'label a'"), 1u) << gp;  // once, not per session kind
  // Every point named beside it (a: single and multi; b: single): three labels.
  EXPECT_EQ(count(gp, "set label 1"), 3u) << gp;
  EXPECT_NE(gp.find("set label 10 'label a' at "), std::string::npos) << gp;
  // Decades written as powers of ten, 2 and 5 as minor labels.
  EXPECT_NE(gp.find("\"10\u00b2\" 100"), std::string::npos) << gp;
  EXPECT_NE(gp.find("\"2\" 20, \"5\" 50"), std::string::npos) << gp;
  EXPECT_NE(gp.find("title 'multi session (mean over datasets)'"), std::string::npos);
  EXPECT_NE(gp.find("set key outside"), std::string::npos);
  // Means 0.5 .. 0.9: floor((0.5 - 0.03) * 20) / 20 = 0.45, ceil((0.9 + 0.03) * 20) / 20 = 0.95.
  EXPECT_NE(gp.find("set yrange [0.45:0.95]"), std::string::npos) << gp;
  EXPECT_NE(figure.caption.find("mean over its datasets"), std::string::npos);
  // The csv says the means are uneven, as a comment gnuplot skips.
  EXPECT_NE(figure.csv.find("\n# note: the mean ROC AUCs are over different numbers"),
            std::string::npos)
      << figure.csv;
  EXPECT_NE(figure.csv.find("\n40,0.9,single,\"label b\",1,2\n"), std::string::npos) << figure.csv;
}

}  // namespace
}  // namespace radarpr
