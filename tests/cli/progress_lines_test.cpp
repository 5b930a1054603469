// A run's progress lines on stderr: each dataset's header and each line under it say where the
// whole run is ("dataset 2/2, descriptor 2/2"), and a codebook's training says it started, how
// many scans it has read and how long it took, instead of staying silent.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "evaluation/progress.hpp"
#include "tests/cli/cli_runner.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

bool contains(const std::string& text, const std::string& what) {
  return text.find(what) != std::string::npos;
}

TEST(RunPosition, NamesTheDatasetAndDescriptorOfTheRun) {
  const RunPosition position{3, 6};
  EXPECT_EQ(position.text(), "dataset 3/6");
  EXPECT_EQ(position.suffix(5, 7), " (dataset 3/6, descriptor 5/7)");
  EXPECT_EQ(position.suffix(), " (dataset 3/6)");
  // A dataset outside a counted run: only the descriptor.
  EXPECT_EQ(RunPosition{}.suffix(), "");
  EXPECT_EQ(RunPosition{}.suffix(1, 2), " (descriptor 1/2)");
}

TEST(ProgressLines, SayWhereTheRunIsAndThatTrainingIsAlive) {
  const fs::path folder =
      fs::temp_directory_path() / fmt::format("radarpr_progress_{}", ::getpid());
  fs::remove_all(folder);
  fs::create_directories(folder);
  std::ofstream(folder / "config.json") << R"({
    "experiment": "progress",
    "datasets": [
      {"name": "pair",
       "query": {"type": "synthetic", "seed": 3, "session": 1, "scans": 60, "range_bins": 420,
                 "range_resolution_m": 0.238, "route_blocks_x": 1, "route_origin_block_x": 1},
       "database": {"type": "synthetic", "seed": 3, "session": 0, "scans": 80, "range_bins": 420,
                    "range_resolution_m": 0.238, "route_blocks_x": 1}},
      {"name": "single",
       "query": {"type": "synthetic", "seed": 3, "session": 0, "scans": 80, "range_bins": 420,
                 "range_resolution_m": 0.238, "route_blocks_x": 1}}
    ],
    "descriptors": ["referee", "open_radvlad:bin_dim=10,clusters=4"],
    "protocol": {"exclude_recent_frames": 20, "revisit_radius_m": 10}
  })";
  const testing::CommandResult result =
      testing::run_cli(fmt::format("run {} --out {} --no-cache", (folder / "config.json").string(),
                                   (folder / "out").string()),
                       "RADARPR_GNUPLOT=off");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const std::string& log = result.output;
  EXPECT_TRUE(contains(log, "dataset pair (1/2): synthetic(seed=3,session=1) (60 scans) against"))
      << log;
  EXPECT_TRUE(contains(log, "dataset single (2/2): synthetic(seed=3,session=0) (80 scans)")) << log;
  EXPECT_TRUE(contains(log, "  extracting synthetic(seed=3,session=1) (dataset 1/2): 60/60 ("))
      << log;
  EXPECT_TRUE(contains(log, "  evaluating referee (dataset 1/2, descriptor 1/2)\n")) << log;
  EXPECT_TRUE(contains(log,
                       "  evaluating open_radvlad:bin_dim=10,clusters=4 (dataset 2/2, "
                       "descriptor 2/2)\n"))
      << log;
  // Training: where it is, then the time it took and the scans it read (all 80 of the database
  // session: this codebook samples none out).
  EXPECT_TRUE(contains(log,
                       "  training open_radvlad:bin_dim=10,clusters=4 (dataset 1/2, descriptor "
                       "2/2) on synthetic(seed=3,session=0) (80 scans)\n"))
      << log;
  // Then, every scan read, what the silent wait that follows is (the codebook's k-means).
  EXPECT_TRUE(contains(log,
                       "  training open_radvlad:bin_dim=10,clusters=4: all 80 scans read, now "
                       "learning from them\n"))
      << log;
  EXPECT_TRUE(contains(log, "  trained open_radvlad:bin_dim=10,clusters=4 in ")) << log;
  EXPECT_TRUE(contains(log, " s (80 of 80 scans read)\n")) << log;
  fs::remove_all(folder);
}

}  // namespace
}  // namespace radarpr
