// A problem met each time a run opens the same sequence (before any work to inspect it, to run
// it, as another dataset's database) is one warning, not one per opening.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "tests/cli/cli_runner.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(WarningsOnce, AnUnwritableSyntheticCacheIsSaidOncePerFolder) {
  const fs::path folder = fs::temp_directory_path() / fmt::format("radarpr_warn_{}", ::getpid());
  fs::remove_all(folder);
  fs::create_directories(folder / "cache");
  // A file where the synthetic scans' cache folder would go: no scan can be cached.
  std::ofstream(folder / "cache" / "synthetic") << "not a folder";
  // Session 0 is opened three times (inspected, run alone, then as the pair's database).
  std::ofstream(folder / "config.json") << R"({
    "experiment": "warnings",
    "datasets": [
      {"name": "single",
       "query": {"type": "synthetic", "seed": 3, "session": 0, "scans": 60, "range_bins": 420,
                 "range_resolution_m": 0.238, "route_blocks_x": 1}},
      {"name": "pair",
       "query": {"type": "synthetic", "seed": 3, "session": 1, "scans": 40, "range_bins": 420,
                 "range_resolution_m": 0.238, "route_blocks_x": 1, "route_origin_block_x": 1},
       "database": {"type": "synthetic", "seed": 3, "session": 0, "scans": 60, "range_bins": 420,
                    "range_resolution_m": 0.238, "route_blocks_x": 1}}
    ],
    "descriptors": ["referee"],
    "protocol": {"exclude_recent_frames": 20, "revisit_radius_m": 10}
  })";
  const testing::CommandResult result = testing::run_cli(
      fmt::format("run {} --out {}", (folder / "config.json").string(), (folder / "out").string()),
      fmt::format("RADARPR_GNUPLOT=off RADARPR_CACHE_DIR={}", (folder / "cache").string()));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  // Two sessions, two cache folders, each named once.
  EXPECT_EQ(count(result.output, "warning: cannot cache synthetic scans in "), 2u) << result.output;
  fs::remove_all(folder);
}

}  // namespace
}  // namespace radarpr
