// The synthetic benchmark configs (configs/synthetic/, configs/paper_table_synthetic.json) and
// `radarpr simulate`, whose output the `folder` loader reads back.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "datasets/real/folder_dataset.hpp"
#include "datasets/synthetic/synthetic_sequence.hpp"
#include "evaluation/experiment_config.hpp"
#include "tests/datasets/dataset_tree.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kWorlds = {
    "city", "campus", "riverside", "offroad_sessions", "suburban_sessions", "city_sessions"};

nlohmann::json read_json(const fs::path& path) {
  std::ifstream file(path);
  return nlohmann::json::parse(file);
}

fs::path configs() {
  return fs::path(RADARPR_SOURCE_DIR) / "configs";
}

TEST(SyntheticConfigs, ThePaperTableRunsTheSixWorlds) {
  const nlohmann::json table = read_json(configs() / "paper_table_synthetic.json");
  ASSERT_EQ(table["datasets"].size(), kWorlds.size());
  for (std::size_t i = 0; i < kWorlds.size(); ++i) {
    const nlohmann::json world = read_json(configs() / "synthetic" / (kWorlds[i] + ".json"));
    ASSERT_EQ(world["datasets"].size(), 1u) << kWorlds[i];
    EXPECT_EQ(table["datasets"][i], world["datasets"][0]) << kWorlds[i];
    EXPECT_EQ(world["protocol"]["revisit_radius_m"], table["protocol"]["revisit_radius_m"]);
    EXPECT_NO_THROW(load_experiment_config(configs() / "synthetic" / (kWorlds[i] + ".json"), {}));
  }
}

// Queries with a database scan within 20 m (single session: 50 or more scans older).
int revisits(const DatasetConfig& dataset) {
  const auto query = open_sequence(dataset.query);
  const auto database = dataset.database ? open_sequence(*dataset.database) : nullptr;
  const auto& q = query->records();
  const auto& d = database ? database->records() : q;
  int count = 0;
  for (std::size_t i = 0; i < q.size(); ++i) {
    const std::size_t end = database ? d.size() : (i >= 50 ? i - 49 : 0);
    for (std::size_t j = 0; j < end; ++j) {
      if (std::hypot(q[i].pose.x - d[j].pose.x, q[i].pose.y - d[j].pose.y) <= 20.0) {
        ++count;
        break;
      }
    }
  }
  return count;
}

TEST(SyntheticConfigs, EveryWorldHasRevisitsAndNewPlaces) {
  // Counted by brute force; `radarpr inspect` prints the same numbers. Multi-session queries
  // are partly over new ground, so ROC AUC is defined (some queries are true negatives).
  const ExperimentConfig config =
      load_experiment_config(configs() / "paper_table_synthetic.json", {});
  std::vector<int> counts;
  for (const DatasetConfig& dataset : config.datasets) counts.push_back(revisits(dataset));
  fmt::print(
      "revisits: city {}, campus {}, riverside {}, offroad {}, suburban {}, city sessions {}\n",
      counts[0], counts[1], counts[2], counts[3], counts[4], counts[5]);
  // Single sessions: 550 queries after the 50-frame exclusion, most of the later laps.
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_GT(counts[i], 200) << kWorlds[i];
    EXPECT_LT(counts[i], 550) << kWorlds[i];
  }
  for (std::size_t i = 3; i < 6; ++i) {
    EXPECT_GT(counts[i], 60) << kWorlds[i];
    EXPECT_LT(counts[i], 240) << kWorlds[i];
  }
}

TEST(SyntheticConfigs, SimulateWritesWhatTheFolderLoaderReads) {
  test::TempTree tree;
  const fs::path config_path = tree.write("tiny.json", R"({
    "experiment": "tiny",
    "datasets": [{"name": "pair",
      "query": {"type": "synthetic", "world": "campus", "radar": "tiny", "seed": 5, "session": 1,
                "scans": 6, "weather": "rain"},
      "database": {"type": "synthetic", "world": "campus", "radar": "tiny", "seed": 5,
                   "scans": 4}}],
    "descriptors": ["referee"],
    "protocol": {}
  })");
  const fs::path out = tree.path("out");
  const std::string command = fmt::format("\"{}\" simulate \"{}\" --out \"{}\" --quiet --threads 2",
                                          RADARPR_CLI_PATH, config_path.string(), out.string());
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  ASSERT_TRUE(fs::exists(out / "pair" / "query" / "poses.csv"));
  ASSERT_TRUE(fs::exists(out / "pair" / "database" / "poses.csv"));

  const ExperimentConfig config = load_experiment_config(config_path, {});
  const auto generated = open_sequence(config.datasets[0].query);
  FolderOptions options;
  options.common.root = out / "pair";
  options.common.sequence = "query";
  options.common.range_resolution_m = 0.238;
  const auto loaded = open_folder(options);
  ASSERT_EQ(loaded->size(), 6u);
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(loaded->records()[i].timestamp_ns, generated->records()[i].timestamp_ns);
    EXPECT_NEAR(loaded->records()[i].pose.x, generated->records()[i].pose.x, 1e-6);
    EXPECT_EQ(cv::norm(loaded->load_image(i).power, generated->load_image(i).power, cv::NORM_INF),
              0.0)
        << i;
  }
  // A config without synthetic sequences writes nothing and says so.
  const fs::path real = tree.write("real.json", R"({
    "experiment": "real",
    "datasets": [{"name": "f", "query": {"type": "folder", "root": "/nonexistent",
                  "range_resolution_m": 0.05}}],
    "descriptors": ["referee"], "protocol": {}
  })");
  const std::string refused =
      fmt::format("\"{}\" simulate \"{}\" --out \"{}\" --quiet > /dev/null 2>&1", RADARPR_CLI_PATH,
                  real.string(), out.string());
  EXPECT_NE(std::system(refused.c_str()), 0);
}

}  // namespace
}  // namespace radarpr
