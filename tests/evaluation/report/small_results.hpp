#pragma once

// A small finished run on disk, the input every report test starts from: a one-block synthetic
// town at a coarse range (single and multi session, two descriptors) so that a test process
// makes it in about a second.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "evaluation/config/experiment_config.hpp"
#include "evaluation/experiment_runner.hpp"
#include "evaluation/results/results_writer.hpp"

namespace radarpr::testing {

inline nlohmann::json small_report_experiment(const std::string& name = "report_test") {
  nlohmann::json config = nlohmann::json::parse(R"({
    "datasets": [
      {"name": "town", "query": {"type": "synthetic", "seed": 11, "scans": 160,
        "range_bins": 840, "range_resolution_m": 0.119, "route_blocks_x": 1,
        "lap_pattern": "FR"}},
      {"name": "town_2_sessions",
       "query": {"type": "synthetic", "seed": 11, "session": 1, "scans": 50,
        "range_bins": 840, "range_resolution_m": 0.119, "route_blocks_x": 1},
       "database": {"type": "synthetic", "seed": 11, "scans": 100,
        "range_bins": 840, "range_resolution_m": 0.119, "route_blocks_x": 1}}
    ],
    "descriptors": ["referee", "referee_r:kernel=box,z_q=3"],
    "protocol": {"exclude_recent_frames": 30, "revisit_radius_m": 10, "recall_at_k": [1, 5]}
  })");
  config["experiment"] = name;
  return config;
}

// A fresh folder of this test process under the system temp folder (removed first).
inline std::filesystem::path scratch_folder(const std::string& what) {
  const auto folder = std::filesystem::temp_directory_path() /
                      fmt::format("radarpr_report_test_{}_{}", what, ::getpid());
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder;
}

// Runs the small experiment and writes its results (no report) to `folder`.
inline void write_small_results(const std::filesystem::path& folder,
                                const std::string& name = "report_test") {
  const ExperimentConfig config = parse_experiment_config(small_report_experiment(name));
  write_results(folder, config, run_experiment(config, /*show_progress=*/false));
}

// A copy of the finished run in `root`/run, at `root`/`name`, that a test may report on or damage.
inline std::filesystem::path copy_of_run(const std::filesystem::path& root,
                                         const std::string& name) {
  const std::filesystem::path copy = root / name;
  std::filesystem::remove_all(copy);
  std::filesystem::copy(root / "run", copy, std::filesystem::copy_options::recursive);
  return copy;
}

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

// Sets an environment variable for one scope, restoring the previous value after.
class ScopedEnvironment {
 public:
  ScopedEnvironment(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name); old != nullptr) old_ = old;
    ::setenv(name, value, 1);
  }
  ~ScopedEnvironment() {
    if (old_) {
      ::setenv(name_, old_->c_str(), 1);
    } else {
      ::unsetenv(name_);
    }
  }
  ScopedEnvironment(const ScopedEnvironment&) = delete;
  ScopedEnvironment& operator=(const ScopedEnvironment&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_;
};

}  // namespace radarpr::testing
