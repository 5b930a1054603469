// A study cut into units (plan), run unit by unit with the local runner (xargs -P), checked
// (status) and merged: the merged results folder is the one `radarpr run` writes in one process,
// byte for byte except the measured times; units skip when done, and a failing unit leaves no
// output and says why.
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include <unistd.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/cli/cli_runner.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

using testing::run_cli;
using testing::run_command_line;

std::string read_file(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::stringstream content;
  content << file.rdbuf();
  return content.str();
}

// Three sessions of a small town (6 ordered pairs), three descriptors, one of them trainable.
constexpr const char* kStudyConfig = R"({
  "experiment": "study_cli_test",
  "datasets": [{"kind": "session_matrix", "name": "town", "sessions": [
    {"name": "clear", "sequence": {"type": "synthetic", "seed": 5, "session": 0, "scans": 24,
      "azimuths": 120, "range_bins": 210, "range_resolution_m": 0.476, "route_blocks_x": 1,
      "speed_mps": 40}},
    {"name": "rain", "sequence": {"type": "synthetic", "seed": 5, "session": 1, "scans": 20,
      "azimuths": 120, "range_bins": 210, "range_resolution_m": 0.476, "route_blocks_x": 1,
      "speed_mps": 40, "weather": "rain"}},
    {"name": "parked", "sequence": {"type": "synthetic", "seed": 5, "session": 2, "scans": 22,
      "azimuths": 120, "range_bins": 210, "range_resolution_m": 0.476, "route_blocks_x": 1,
      "speed_mps": 40, "parked_car_churn": 0.8}}]},
    {"name": "plain", "query": {"type": "synthetic", "seed": 5, "scans": 30, "azimuths": 120,
      "range_bins": 210, "range_resolution_m": 0.476, "route_blocks_x": 1, "speed_mps": 40}}],
  "descriptors": ["referee", "referee_r",
    {"name": "open_radvlad", "params": {"min_bin": 10, "bin_dim": 8, "clusters": 4,
      "max_iterations": 5}}],
  "protocol": {"exclude_recent_frames": 5, "revisit_radius_m": 10, "recall_at_k": [1, 3]}
})";

// The run-specific fields of a metrics.json: how long extraction and training took, and whether
// the values were extracted by this process or read from the cache.
std::string without_measurements(const std::string& text) {
  nlohmann::json json = nlohmann::json::parse(text);
  json.erase("extract_ms_per_scan");
  json.erase("values_from");
  json.erase("training");
  return json.dump(2);
}

class StudyCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / fmt::format("radarpr_study_cli_test_{}", ::getpid());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    std::ofstream(dir_ / "study.json") << kStudyConfig;
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  fs::path dir_;
};

TEST_F(StudyCliTest, PlanRunUnitsMergeEqualsOneProcess) {
  const auto single = run_cli(fmt::format("run {} --out {} --cache-dir {} --quiet",
                                          path("study.json"), path("single"), path("cache1")));
  ASSERT_EQ(single.exit_code, 0) << single.output;

  const auto plan =
      run_cli(fmt::format("plan {} --out {} --slurm --partition debug --mem 2G "
                          "--cpus-per-task 2 --max-parallel 3",
                          path("study.json"), path("plan")));
  ASSERT_EQ(plan.exit_code, 0) << plan.output;
  // train: 3 codebooks (one per database session); values: 3 sessions, each in one pass;
  // evaluate: 6 pairs x 3 + the plain dataset.
  EXPECT_NE(plan.output.find("25 units: 3 train, 3 values, 19 evaluate"), std::string::npos)
      << plan.output;
  const auto manifest = nlohmann::json::parse(read_file(dir_ / "plan" / "plan.json"));
  ASSERT_EQ(manifest["phases"].size(), 3u);
  EXPECT_EQ(manifest["phases"][0]["units"].size(), 3u);
  EXPECT_EQ(manifest["phases"][1]["units"].size(), 3u);
  std::set<std::string> ids;
  for (const auto& phase : manifest["phases"]) {
    for (const auto& unit : phase["units"]) {
      ids.insert(unit["id"].get<std::string>());
      EXPECT_FALSE(unit["outputs"].empty());
      EXPECT_GT(unit["estimated_cpu_seconds"].get<double>(), 0.0);
    }
  }
  EXPECT_EQ(ids.size(), 25u);
  EXPECT_TRUE(ids.count("values.town.clear"));
  EXPECT_TRUE(
      ids.count("train.town.clear.open_radvlad__bin_dim=8_clusters=4_max_iterations=5_min_bin=10"));
  EXPECT_TRUE(ids.count("evaluate.town.rain.clear.referee"));
  const std::string values_sbatch = read_file(dir_ / "plan" / "slurm" / "values.sbatch");
  EXPECT_NE(values_sbatch.find("#SBATCH --array=0-2%3"), std::string::npos) << values_sbatch;
  EXPECT_NE(values_sbatch.find("#SBATCH --cpus-per-task=2"), std::string::npos);
  EXPECT_NE(values_sbatch.find("#SBATCH --partition=debug"), std::string::npos);
  EXPECT_NE(values_sbatch.find("#SBATCH --mem=2G"), std::string::npos);
  const std::string submit = read_file(dir_ / "plan" / "slurm" / "submit.sh");
  EXPECT_NE(submit.find("--dependency=afterok:"), std::string::npos);

  auto status = run_cli("status " + path("plan"));
  EXPECT_EQ(status.exit_code, 1);
  EXPECT_NE(status.output.find("values: 0 done, 0 failed, 3 missing"), std::string::npos)
      << status.output;
  // Evaluating before the values exist fails, names the cause and writes no output.
  const auto early =
      run_cli(fmt::format("run-unit {} evaluate.town.rain.clear.referee --quiet", path("plan")));
  EXPECT_EQ(early.exit_code, 1);
  EXPECT_NE(early.output.find("not in the descriptor cache"), std::string::npos) << early.output;
  EXPECT_FALSE(fs::exists(dir_ / "plan" / "units" / "evaluate.town.rain.clear.referee.json"));
  status = run_cli("status " + path("plan"));
  // The unit's line in evaluate.units is its index in the Slurm job array.
  std::size_t index = 0;
  {
    std::ifstream listed(dir_ / "plan" / "evaluate.units");
    std::string id;
    while (std::getline(listed, id) && id != "evaluate.town.rain.clear.referee") ++index;
  }
  EXPECT_NE(status.output.find(fmt::format(
                "failed evaluate.town.rain.clear.referee [evaluate {}]: the values of ", index)),
            std::string::npos)
      << status.output;
  EXPECT_NE(status.output.find("sbatch --array=0-2 values.sbatch)"), std::string::npos)
      << status.output;
  EXPECT_NE(status.output.find("sbatch --array=0-18 evaluate.sbatch)"), std::string::npos)
      << status.output;
  // A values unit before the train units: the codebooks it encodes with are not there yet.
  const auto untrained = run_cli(fmt::format("run-unit {} values.town.rain --quiet", path("plan")));
  EXPECT_EQ(untrained.exit_code, 1);
  EXPECT_NE(untrained.output.find("run the train units first"), std::string::npos)
      << untrained.output;
  EXPECT_FALSE(fs::exists(dir_ / "plan" / "units" / "values.town.rain.done.json"));
  EXPECT_EQ(run_cli("run-unit " + path("plan") + " no.such.unit").exit_code, 1);
  const auto refused = run_cli("merge " + path("plan") + " --out " + path("merged"));
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_NE(refused.output.find("are not done"), std::string::npos) << refused.output;

  const auto local = run_command_line(
      fmt::format("PATH=/usr/bin:/bin sh {} 2 2>&1", (dir_ / "plan" / "run_local.sh").string()));
  ASSERT_EQ(local.exit_code, 0) << local.output;
  status = run_cli("status " + path("plan"));
  EXPECT_EQ(status.exit_code, 0) << status.output;
  EXPECT_NE(status.output.find("evaluate: 19 done, 0 failed, 0 missing"), std::string::npos);
  const auto again =
      run_cli(fmt::format("run-unit {} evaluate.town.rain.clear.referee --quiet", path("plan")));
  EXPECT_EQ(again.exit_code, 0);
  EXPECT_NE(again.output.find("done already, skipped"), std::string::npos) << again.output;

  // run_local.sh merged into the plan's results/; merge again elsewhere.
  EXPECT_TRUE(fs::exists(dir_ / "plan" / "results" / "summary.md"));
  const auto merged = run_cli("merge " + path("plan") + " --out " + path("merged"));
  ASSERT_EQ(merged.exit_code, 0) << merged.output;
  std::size_t compared = 0;
  for (const auto& entry : fs::recursive_directory_iterator(dir_ / "single")) {
    if (!entry.is_regular_file()) continue;
    const fs::path relative = fs::relative(entry.path(), dir_ / "single");
    const std::string name = relative.filename().string();
    const std::string top = relative.begin()->string();
    // Measured times and the machine (timing.json, summary.csv's extraction time), and the
    // figures drawn from the same data by gnuplot.
    if (name == "summary.json" || name == "timing.json" || name == "summary.csv" ||
        top == "figures" || name == "index.html") {
      continue;
    }
    ASSERT_TRUE(fs::exists(dir_ / "merged" / relative)) << relative;
    const std::string expected = read_file(entry.path());
    const std::string actual = read_file(dir_ / "merged" / relative);
    if (name == "metrics.json") {
      EXPECT_EQ(without_measurements(actual), without_measurements(expected)) << relative;
    } else {
      EXPECT_EQ(actual, expected) << relative;
    }
    ++compared;
  }
  // summary.md, 3 tables x 3 formats, matrix tables, 7 datasets' trajectories, 21 x 4 files.
  EXPECT_GE(compared, 1u + 9u + 2u + 7u + 21u * 4u);
}

}  // namespace
}  // namespace radarpr
