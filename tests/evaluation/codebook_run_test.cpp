// Codebook files in runs: one run trains Open-RadVLAD and saves its codebook, the next loads it
// and gets the same values without training; results record the codebook's SHA-256, and cached
// values of a loaded codebook are keyed by that hash.
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "datasets/cache_directory.hpp"
#include "datasets/npy_file.hpp"
#include "datasets/sha256.hpp"
#include "evaluation/config/experiment_config.hpp"
#include "evaluation/experiment_runner.hpp"
#include "evaluation/results/results_writer.hpp"
#include "evaluation/safe_name.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

// A fresh folder holding the codebook, the results and the descriptor cache of one test.
class Workspace {
 public:
  Workspace()
      : root_(fs::temp_directory_path() / ("radarpr_codebook_run_" + std::to_string(::getpid()))) {
    fs::remove_all(root_);
    fs::create_directories(root_);
    override_cache_directory(root_ / "cache");
  }
  ~Workspace() {
    override_cache_directory(std::nullopt);
    std::error_code ignored;
    fs::remove_all(root_, ignored);
  }
  fs::path operator/(const std::string& name) const { return root_ / name; }

 private:
  fs::path root_;
};

ExperimentConfig config_with(const std::string& descriptor) {
  return parse_experiment_config(nlohmann::json::parse(R"({
    "experiment": "codebook_run_test",
    "datasets": [
      {"name": "single", "query": {"type": "synthetic", "seed": 3, "scans": 40,
        "azimuths": 120, "range_bins": 210, "range_resolution_m": 0.476, "route_blocks_x": 1}}
    ],
    "descriptors": [")" + descriptor + R"("],
    "protocol": {"exclude_recent_frames": 10}
  })"));
}

nlohmann::json summary_row_of(const fs::path& out, const ExperimentConfig& config,
                              const ExperimentRun& run) {
  write_results(out, config, run);
  std::ifstream in(out / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(in);
  for (const auto& row : summary.at("rows")) return row;
  return nullptr;
}

TEST(CodebookRun, TrainOnceSaveThenLoadGivesTheSameResultsAndRecordsTheHash) {
  const Workspace workspace;
  const std::string file = (workspace / "cb.npy").string();
  const std::string small = "open_radvlad:bin_dim=16,clusters=4,min_bin=4";

  const ExperimentConfig saving = config_with(small + ",save_codebook=" + file);
  const ExperimentRun trained = run_experiment(saving, false);
  const DescriptorRun& trained_run = trained.datasets.at(0).descriptors.at(0);
  ASSERT_TRUE(trained_run.training.has_value());
  ASSERT_TRUE(trained_run.codebook.has_value());
  const std::string hash = sha256_hex(NpyFile::open(file).bytes());
  EXPECT_EQ(trained_run.codebook->sha256, hash);
  EXPECT_EQ(trained_run.codebook->saved_to, file);
  EXPECT_EQ(trained_run.codebook->loaded_from, "");
  // Saving trains in every run, so the file is always written: its values are not cached.
  fs::remove(file);
  EXPECT_FALSE(run_experiment(saving, false).datasets.at(0).descriptors.at(0).query_values_cached);
  EXPECT_EQ(sha256_hex(NpyFile::open(file).bytes()), hash);

  const ExperimentConfig loading = config_with(small + ",codebook=" + file);
  const ExperimentRun loaded = run_experiment(loading, false);
  const DescriptorRun& loaded_run = loaded.datasets.at(0).descriptors.at(0);
  EXPECT_FALSE(loaded_run.training.has_value());  // nothing trained
  ASSERT_TRUE(loaded_run.codebook.has_value());
  EXPECT_EQ(loaded_run.codebook->sha256, hash);
  EXPECT_EQ(loaded_run.codebook->loaded_from, file);
  ASSERT_EQ(loaded_run.evaluation.results.size(), trained_run.evaluation.results.size());
  for (std::size_t i = 0; i < loaded_run.evaluation.results.size(); ++i) {
    EXPECT_EQ(loaded_run.evaluation.results[i].match, trained_run.evaluation.results[i].match);
    EXPECT_EQ(loaded_run.evaluation.results[i].distance,
              trained_run.evaluation.results[i].distance);
  }

  const nlohmann::json row = summary_row_of(workspace / "loaded", loading, loaded);
  EXPECT_EQ(row.at("codebook").at("sha256"), hash);
  EXPECT_EQ(row.at("codebook").at("loaded_from"), file);
  EXPECT_TRUE(row.at("codebook").at("saved_to").is_null());
  std::ifstream metrics_in(workspace / "loaded" / "single" / descriptor_folder_name(loaded_run.id) /
                           "metrics.json");
  ASSERT_TRUE(metrics_in.good());
  EXPECT_EQ(nlohmann::json::parse(metrics_in).at("codebook").at("sha256"), hash);

  // A second load is served from the cache; another codebook in the same file is not.
  EXPECT_TRUE(run_experiment(loading, false).datasets.at(0).descriptors.at(0).query_values_cached);
  const ExperimentConfig other_seed = config_with(small + ",save_codebook=" + file + ",seed=7");
  run_experiment(other_seed, false);
  const std::string other_hash = sha256_hex(NpyFile::open(file).bytes());
  ASSERT_NE(other_hash, hash);
  const ExperimentRun reloaded = run_experiment(config_with(small + ",codebook=" + file), false);
  EXPECT_FALSE(reloaded.datasets.at(0).descriptors.at(0).query_values_cached);
  EXPECT_EQ(reloaded.datasets.at(0).descriptors.at(0).codebook->sha256, other_hash);
}

TEST(CodebookRun, DescriptorsWithoutACodebookCarryNoCodebookKey) {
  const Workspace workspace;
  const ExperimentConfig config = config_with("referee");
  const ExperimentRun run = run_experiment(config, false);
  EXPECT_FALSE(run.datasets.at(0).descriptors.at(0).codebook.has_value());
  EXPECT_FALSE(summary_row_of(workspace / "out", config, run).contains("codebook"));
}

}  // namespace
}  // namespace radarpr
