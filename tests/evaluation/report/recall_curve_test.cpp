// The Recall@N curves: their data equals the ranks in matches.csv (N = 1 equal to the summary's
// Recall@1), they reach the configured N, and a curve whose rankings end early stops there with
// the reason on the page.
#include <gtest/gtest.h>

#include "evaluation/report/recall_curve_figure.hpp"
#include "evaluation/report/report.hpp"
#include "evaluation/results/csv_file.hpp"
#include "tests/evaluation/report/small_results.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

TEST(RecallCurve, TheDataEqualsTheRanksInMatchesAndStartsAtTheSummarysRecallAt1) {
  const fs::path root = testing::scratch_folder("recall_curve");
  testing::write_small_results(root / "run");
  const testing::ScopedEnvironment no_gnuplot("RADARPR_GNUPLOT", "off");
  write_report(root / "run", {});
  const auto summary = nlohmann::json::parse(testing::read_text(root / "run" / "summary.json"));
  const CsvFile curve(root / "run" / "figures" / "recall_at_n_town.csv");
  for (const auto& row : summary["rows"]) {
    if (row["dataset"] != "town") continue;
    // The run ranked 25 frames (the default report.recall_curve_n, above its Recall@5).
    EXPECT_EQ(row["ranked_frames"].get<std::size_t>(), 25u);
    const CsvFile matches(root / "run" / "town" / descriptor_folder_name(row["descriptor"]) /
                          "matches.csv");
    std::vector<std::size_t> ranks;
    for (std::size_t i = 0; i < matches.row_count(); ++i) {
      if (matches.text(i, matches.column("revisit")) == "1") {
        ranks.push_back(matches.index(i, matches.column("first_correct_rank")));
      }
    }
    ASSERT_FALSE(ranks.empty());
    std::vector<double> expected;
    for (std::size_t n = 1; n <= 25; ++n) {
      const auto found = std::count_if(ranks.begin(), ranks.end(),
                                       [&](std::size_t r) { return r >= 1 && r <= n; });
      expected.push_back(static_cast<double>(found) / static_cast<double>(ranks.size()));
    }
    std::vector<double> drawn;
    for (std::size_t i = 0; i < curve.row_count(); ++i) {
      if (curve.text(i, curve.column("series")) == row["label"].get<std::string>()) {
        EXPECT_EQ(curve.index(i, curve.column("n")), drawn.size() + 1);
        drawn.push_back(curve.number(i, curve.column("recall_at_n")));
      }
    }
    ASSERT_EQ(drawn.size(), expected.size()) << row["label"];
    for (std::size_t n = 0; n < drawn.size(); ++n) EXPECT_DOUBLE_EQ(drawn[n], expected[n]) << n;
    EXPECT_DOUBLE_EQ(drawn.front(), row["recall_at_1"].get<double>());
    EXPECT_GT(drawn.back(), drawn.front());  // deeper ranks find more revisits
  }
  const std::string page = testing::read_text(root / "run" / "index.html");
  EXPECT_NE(page.find("figures/recall_at_n_town.csv"), std::string::npos);
  EXPECT_NE(page.find("figures/recall_at_n_town_2_sessions.csv"), std::string::npos);
  fs::remove_all(root);
}

ResultRow row_with_ranks(std::optional<std::size_t> ranked_frames) {
  ResultRow row;
  row.label = "d";
  // Four revisit queries first correct at ranks 1, 3, 12 and never; one query without a revisit.
  row.ranks = {{true, 1}, {true, 3}, {true, 12}, {true, 0}, {false, 0}};
  row.ranked_frames = ranked_frames;
  return row;
}

TEST(RecallCurve, ACurveStopsWhereItsRankingsEnd) {
  const RecallCurve full = recall_at_n(row_with_ranks(25), 25, 10);
  ASSERT_EQ(full.recall.size(), 25u);
  EXPECT_FALSE(full.stops_early);
  EXPECT_DOUBLE_EQ(full.recall[0], 0.25);
  EXPECT_DOUBLE_EQ(full.recall[2], 0.5);
  EXPECT_DOUBLE_EQ(full.recall[11], 0.75);
  // A key-then-rerank descriptor that ranked 10 candidates: the curve ends at N = 10.
  const RecallCurve cut = recall_at_n(row_with_ranks(10), 25, 10);
  EXPECT_EQ(cut.recall.size(), 10u);
  EXPECT_TRUE(cut.stops_early);
  // Results written before the depth was recorded: the run's largest Recall@K.
  EXPECT_EQ(recall_at_n(row_with_ranks(std::nullopt), 25, 5).recall.size(), 5u);
  // No revisit query: undefined, nothing drawn.
  ResultRow none;
  none.ranks = {{false, 0}};
  EXPECT_TRUE(recall_at_n(none, 25, 10).recall.empty());

  const std::string gp =
      recall_at_n_figure("recall_at_n_x", "x", {{"full", full, 0, 1}, {"cut", cut, 1, 2}}, 25,
                         FigureStyle::screen)
          .script;
  EXPECT_NE(gp.find("title 'cut (ranks end at N = 10)'"), std::string::npos) << gp;
  EXPECT_NE(gp.find("title 'full'"), std::string::npos) << gp;
  EXPECT_NE(gp.find("set xrange [0.5:25.5]"), std::string::npos) << gp;
}

// radar_scan_context re-ranks the `candidates` its ring key hands over: its ranks end there, and
// the page says so where the curve stops.
TEST(RecallCurve, AReRankingDescriptorsCurveStopsAtItsCandidatesAndThePageSaysWhy) {
  const fs::path root = testing::scratch_folder("recall_rerank");
  nlohmann::json config = testing::small_report_experiment("rerank");
  config["datasets"] = nlohmann::json::array({config["datasets"][0]});
  config["descriptors"] = {"referee", "radar_scan_context:candidates=3"};
  const ExperimentConfig parsed = parse_experiment_config(config);
  write_results(root / "run", parsed, run_experiment(parsed, /*show_progress=*/false));
  const testing::ScopedEnvironment no_gnuplot("RADARPR_GNUPLOT", "off");
  write_report(root / "run", {});
  const auto summary = nlohmann::json::parse(testing::read_text(root / "run" / "summary.json"));
  std::string reranked;
  for (const auto& row : summary["rows"]) {
    const bool rerank = row["descriptor"].get<std::string>().starts_with("radar_scan_context");
    EXPECT_EQ(row["ranked_frames"].get<std::size_t>(), rerank ? 3u : 25u);
    if (rerank) reranked = row["label"].get<std::string>();
  }
  const CsvFile curve(root / "run" / "figures" / "recall_at_n_town.csv");
  std::size_t rows = 0;
  for (std::size_t i = 0; i < curve.row_count(); ++i) {
    rows += curve.text(i, curve.column("series")) == reranked ? 1 : 0;
  }
  EXPECT_EQ(rows, 3u);
  const std::string page = testing::read_text(root / "run" / "index.html");
  EXPECT_NE(page.find(reranked + " at N = 3; these descriptors re-rank only the candidates"),
            std::string::npos)
      << page;
  fs::remove_all(root);
}

}  // namespace
}  // namespace radarpr
