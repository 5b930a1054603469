// The session matrix figures: a heat map of Recall@1 and of ROC AUC per descriptor (query
// session down, database session across) and a box plot per metric, their data the pairs'
// values from summary.json; and their section of the report page.
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "datasets/cache_directory.hpp"
#include "evaluation/config/experiment_config.hpp"
#include "evaluation/experiment_runner.hpp"
#include "evaluation/report/report.hpp"
#include "evaluation/results/csv_file.hpp"
#include "evaluation/results/results_writer.hpp"
#include "tests/evaluation/report/small_results.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;
using testing::read_text;

TEST(MatrixFigures, HeatMapsAndBoxPlotsCarryThePairsValues) {
  nlohmann::json json = nlohmann::json::parse(R"({
    "experiment": "matrix_figures_test",
    "datasets": [{"kind": "session_matrix", "name": "town", "sessions": [],
                  "pairs": [{"query": "rain", "database": "clear"},
                            {"query": "clear", "database": "busy"}]}],
    "descriptors": ["referee", "referee_r"],
    "protocol": {"revisit_radius_m": 10, "recall_at_k": [1, 3]}
  })");
  const char* names[] = {"clear", "rain", "busy"};
  for (int s = 0; s < 3; ++s) {
    json["datasets"][0]["sessions"].push_back({{"name", names[s]},
                                               {"sequence",
                                                {{"type", "synthetic"},
                                                 {"seed", 5},
                                                 {"session", s},
                                                 {"scans", 20},
                                                 {"azimuths", 120},
                                                 {"range_bins", 210},
                                                 {"range_resolution_m", 0.476},
                                                 {"route_blocks_x", 1},
                                                 {"speed_mps", 40}}}});
  }
  override_cache_directory("off");
  const ExperimentConfig config = parse_experiment_config(json);
  const ExperimentRun run = run_experiment(config, false);
  override_cache_directory(std::nullopt);
  const fs::path root = testing::scratch_folder("matrix_figures");
  write_results(root / "run", config, run);
  const testing::ScopedEnvironment no_gnuplot("RADARPR_GNUPLOT", "off");
  write_report(root / "run", ReportOptions{});

  const fs::path figures = root / "run" / "figures";
  // rain -> clear is row 1 (query rain), column 0 (database clear).
  const std::string heat = read_text(figures / "matrix_town__referee__recall_at_1.csv");
  const auto& rain_clear = run.datasets[0].descriptors[0].evaluation.metrics;
  ASSERT_TRUE(rain_clear.recall_at_1.has_value());
  EXPECT_NE(heat.find(fmt::format("0,1,{}\n", *rain_clear.recall_at_1)), std::string::npos) << heat;
  EXPECT_NE(heat.find("0,0,NaN\n"), std::string::npos);  // the diagonal is blank
  EXPECT_NE(heat.find("1,2,NaN\n"), std::string::npos);  // busy -> rain: not a listed pair
  EXPECT_TRUE(fs::exists(figures / "matrix_town__referee_r__roc_auc.gp"));
  const std::string box = read_text(figures / "matrix_town__box__recall_at_1.csv");
  const auto& clear_busy = run.datasets[1].descriptors[1].evaluation.metrics;
  ASSERT_TRUE(clear_busy.recall_at_1.has_value());
  EXPECT_NE(box.find(fmt::format("1,{}\n", *clear_busy.recall_at_1)), std::string::npos) << box;
  const std::string page = read_text(root / "run" / "index.html");
  EXPECT_NE(page.find("Session matrices"), std::string::npos);
  EXPECT_NE(page.find("matrix_town__box__roc_auc"), std::string::npos);
  fs::remove_all(root);
}

}  // namespace
}  // namespace radarpr
