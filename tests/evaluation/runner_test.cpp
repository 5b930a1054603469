#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include "evaluation/config/experiment_config.hpp"
#include "evaluation/experiment_runner.hpp"
#include "evaluation/results/results_writer.hpp"
#include "evaluation/version.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

// A small town (one block, a forward and a reverse lap) at a coarse range so the test is quick.
nlohmann::json small_experiment() {
  return nlohmann::json::parse(R"({
    "experiment": "runner_test",
    "datasets": [
      {"name": "town", "query": {"type": "synthetic", "seed": 11, "scans": 240,
        "range_bins": 840, "range_resolution_m": 0.119, "route_blocks_x": 1,
        "lap_pattern": "FR"}},
      {"name": "town_2_sessions",
       "query": {"type": "synthetic", "seed": 11, "session": 1, "scans": 60,
        "range_bins": 840, "range_resolution_m": 0.119, "route_blocks_x": 1},
       "database": {"type": "synthetic", "seed": 11, "scans": 120,
        "range_bins": 840, "range_resolution_m": 0.119, "route_blocks_x": 1}}
    ],
    "descriptors": ["referee", "referee_r:kernel=box,z_q=3"],
    "protocol": {"exclude_recent_frames": 30, "revisit_radius_m": 10, "recall_at_k": [1, 5]}
  })");
}

std::string read_text(const fs::path& path) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

class RunnerTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    config_ = new ExperimentConfig(parse_experiment_config(small_experiment()));
    run_ = new ExperimentRun(run_experiment(*config_, /*show_progress=*/false));
  }
  static void TearDownTestSuite() {
    delete run_;
    delete config_;
  }
  static ExperimentConfig* config_;
  static ExperimentRun* run_;
};
ExperimentConfig* RunnerTest::config_ = nullptr;
ExperimentRun* RunnerTest::run_ = nullptr;

TEST_F(RunnerTest, EvaluatesEveryDatasetAndDescriptor) {
  ASSERT_EQ(run_->datasets.size(), 2u);
  const DatasetRun& single = run_->datasets[0];
  EXPECT_FALSE(single.multi_session);
  ASSERT_EQ(single.descriptors.size(), 2u);
  EXPECT_EQ(single.descriptors[0].rows, 50);
  EXPECT_EQ(single.descriptors[0].payload_bytes, 200u);  // 50 float32
  EXPECT_EQ(single.descriptors[0].paper_bytes, 528u);    // 50 x 8 + 128, the ReFeree paper's 528 B
  EXPECT_EQ(single.descriptors[1].rows, 840 / 80);
  // Single session: the first 30 queries have no eligible frame and are skipped.
  EXPECT_EQ(single.descriptors[0].evaluation.metrics.queries, 240u - 30u);
  const DatasetRun& multi = run_->datasets[1];
  EXPECT_TRUE(multi.multi_session);
  EXPECT_EQ(multi.descriptors[0].evaluation.metrics.queries, 60u);
}

// The synthetic town must be credible enough for a rotation-invariant descriptor to separate
// revisits (including the reverse lap) from non-revisits.
TEST_F(RunnerTest, RotationInvariantReFereeSeparatesSyntheticRevisits) {
  const Metrics& m = run_->datasets[0].descriptors[1].evaluation.metrics;
  ASSERT_GT(m.revisits, 50u);
  ASSERT_TRUE(m.roc_auc.has_value());
  // Chance is 0.5: on the streets of synthetic-v4 (the car in its lane, parking and furniture
  // beyond it) this small coarse town gives 0.85, Recall@1 0.81, with every revisit a reverse
  // one on the other side of the road.
  EXPECT_GT(*m.roc_auc, 0.7);
  ASSERT_TRUE(m.recall_at_1.has_value());
  EXPECT_GT(*m.recall_at_1, 0.6);
}

TEST_F(RunnerTest, ResultFilesRecordVersionProtocolAndDescriptor) {
  const fs::path out =
      fs::temp_directory_path() / fmt::format("radarpr_runner_test_{}", ::getpid()) / "results";
  fs::remove_all(out.parent_path());
  write_results(out, *config_, *run_);

  const auto summary = nlohmann::json::parse(read_text(out / "summary.json"));
  EXPECT_EQ(summary["radarpr_version"], std::string(radarpr_version()));
  EXPECT_EQ(summary["protocol"]["revisit_radius_m"], 10.0);
  EXPECT_EQ(summary["rows"].size(), 4u);
  EXPECT_EQ(summary["descriptors"][1], "referee_r:kernel=box,z_q=3");
  EXPECT_NE(read_text(out / "summary.md").find("| referee_r:kernel=box,z_q=3 |"),
            std::string::npos);
  // An id holding commas is quoted as one field.
  EXPECT_NE(read_text(out / "summary.csv").find(",\"referee_r:kernel=box,z_q=3\","),
            std::string::npos);

  // summary.csv: unique column names, and every row as wide as the header (ids are quoted and
  // hold commas, so count the fields outside quotes).
  std::ifstream csv(out / "summary.csv");
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(csv, line);) {
    if (line.empty()) continue;
    std::vector<std::string> fields(1);
    bool quoted = false;
    for (const char c : line) {
      if (c == '"') {
        quoted = !quoted;
      } else if (c == ',' && !quoted) {
        fields.emplace_back();
      } else {
        fields.back() += c;
      }
    }
    rows.push_back(fields);
  }
  ASSERT_EQ(rows.size(), 5u);
  const std::set<std::string> columns(rows[0].begin(), rows[0].end());
  EXPECT_EQ(columns.size(), rows[0].size()) << "a column name repeats in summary.csv";
  for (const auto& row : rows) EXPECT_EQ(row.size(), rows[0].size());

  // Plain CSV: the header on the first line, no comment line anywhere; what the file describes
  // is in metrics.json beside it.
  const fs::path folder = out / "town" / descriptor_folder_name("referee_r:kernel=box,z_q=3");
  for (const auto& [name, header] : std::vector<std::pair<std::string, std::string>>{
           {"matches.csv", "query,match,distance,"},
           {"curve.csv", "threshold,tp,fp,fn,tn,"},
           {"matching_graph.csv", "query,match,label,distance,"},
           {"../trajectory.csv", "session,frame,x,y,time_s\n"},
           {"../../summary.csv", "dataset,session,descriptor,label,"}}) {
    const std::string text = read_text(folder / name);
    EXPECT_EQ(text.rfind(header, 0), 0u) << name << " starts with " << text.substr(0, 40);
    EXPECT_EQ(text.find("\n#"), std::string::npos) << name;
  }
  const auto metrics = nlohmann::json::parse(read_text(folder / "metrics.json"));
  EXPECT_EQ(metrics["descriptor"], "referee_r:kernel=box,z_q=3");
  EXPECT_EQ(metrics["protocol"]["labels"], "standard");

  // matches.csv: the header, then one line per evaluated query.
  std::ifstream matches(folder / "matches.csv");
  std::size_t lines = 0;
  for (std::string line; std::getline(matches, line);) ++lines;
  EXPECT_EQ(lines, 1u + run_->datasets[0].descriptors[1].evaluation.results.size());
  fs::remove_all(out.parent_path());
}

// "out/" names the same folder as "out"; "/" and "." are refused before anything is written.
TEST_F(RunnerTest, ResultsFolderIsNormalisedAndChecked) {
  const fs::path root =
      fs::temp_directory_path() / fmt::format("radarpr_runner_slash_{}", ::getpid());
  fs::remove_all(root);
  write_results(root / "out/", *config_, *run_);
  EXPECT_TRUE(fs::exists(root / "out" / "summary.json"));
  EXPECT_EQ(resolve_results_folder(root / "out/"), resolve_results_folder(root / "out"));
  EXPECT_THROW(resolve_results_folder("/"), std::runtime_error);
  EXPECT_THROW(resolve_results_folder(root / "out" / "summary.json"), std::runtime_error);
  fs::remove_all(root);
}

// Results go only into their own folder, so a folder that holds anything else is never touched:
// not the working directory ("."), not a folder of the user's files.
TEST_F(RunnerTest, FoldersThatAreNotResultsAreNeverReplaced) {
  const fs::path root =
      fs::temp_directory_path() / fmt::format("radarpr_runner_keep_{}", ::getpid());
  fs::remove_all(root);
  fs::create_directories(root / "precious");
  std::ofstream(root / "precious" / "thesis.tex") << "years of work";
  EXPECT_THROW(write_results(root / "precious", *config_, *run_), std::runtime_error);
  EXPECT_TRUE(fs::exists(root / "precious" / "thesis.tex"));
  EXPECT_FALSE(fs::exists(root / "precious" / "summary.json"));
  EXPECT_THROW(resolve_results_folder("."), std::runtime_error);  // the build tree is not empty
  fs::create_directories(root / "empty");
  EXPECT_NO_THROW(write_results(root / "empty", *config_, *run_));
  // A summary.md that is not ours, or ours beside other files, keeps the folder safe.
  fs::create_directories(root / "notes");
  std::ofstream(root / "notes" / "summary.md") << "# my summary\n";
  EXPECT_THROW(write_results(root / "notes", *config_, *run_), std::runtime_error);
  fs::create_directories(root / "mixed");
  std::ofstream(root / "mixed" / "summary.md") << "# runner_test (radarpr 0.1.0)\n";
  std::ofstream(root / "mixed" / "thesis.tex") << "years of work";
  EXPECT_THROW(write_results(root / "mixed", *config_, *run_), std::runtime_error);
  EXPECT_TRUE(fs::exists(root / "mixed" / "thesis.tex"));
  fs::remove_all(root);
}

// A fresh clone holds the committed reference summary.md alone in results/<experiment>/: the
// README's first command reruns the experiment into that folder.
TEST_F(RunnerTest, ACommittedReferenceSummaryAloneIsReplaced) {
  const fs::path root =
      fs::temp_directory_path() / fmt::format("radarpr_runner_reference_{}", ::getpid());
  fs::remove_all(root);
  write_results(root / "run", *config_, *run_);
  fs::create_directories(root / "clone");
  fs::copy_file(root / "run" / "summary.md", root / "clone" / "summary.md");
  EXPECT_NO_THROW(write_results(root / "clone", *config_, *run_));
  EXPECT_TRUE(fs::exists(root / "clone" / "summary.json"));
  fs::remove_all(root);
}

// Rewriting replaces the files radarpr writes, never a file it did not write (a user's notes, an
// edited figure script), and leaves no staging folder beside the results.
TEST_F(RunnerTest, RewritingReplacesOnlyItsOwnFilesAndLeavesNothingAside) {
  const fs::path root =
      fs::temp_directory_path() / fmt::format("radarpr_runner_replace_{}", ::getpid());
  fs::remove_all(root);
  const fs::path out = root / "results";
  write_results(out, *config_, *run_);
  std::ofstream(out / "notes.txt") << "the user's own";
  std::ofstream(out / "summary.csv") << "damaged";
  write_results(out, *config_, *run_);
  EXPECT_TRUE(fs::exists(out / "notes.txt"));
  EXPECT_NE(read_text(out / "summary.csv"), "damaged");
  EXPECT_TRUE(fs::exists(out / "summary.json"));
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(root)) ++entries;
  EXPECT_EQ(entries, 1u);  // no .partial or .previous folder left behind
  fs::remove_all(root);
}

TEST(DescriptorFolderName, KeepsIdsReadableAndDistinct) {
  EXPECT_EQ(descriptor_folder_name("referee"), "referee");
  EXPECT_EQ(descriptor_folder_name("referee_r:kernel=box,z_q=3"), "referee_r__kernel=box_z_q=3");
}

}  // namespace
}  // namespace radarpr
