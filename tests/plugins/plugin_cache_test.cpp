// The descriptor cache key of a plugin descriptor names the plugin file's build (path, size,
// modification time): a rebuilt plugin recomputes its values while built-ins still come from the
// cache. Through the radarpr program, one process per run, as a user would rebuild and re-run.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/cli/cli_runner.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;
using testing::run_cli;

// Where each descriptor's query values came from in a run: "cache" or "extracted".
std::map<std::string, std::string> values_from(const fs::path& out) {
  std::ifstream file(out / "timing.json");
  const nlohmann::json timing = nlohmann::json::parse(file);
  std::map<std::string, std::string> from;
  for (const auto& row : timing["rows"]) from[row["descriptor"]] = row["values_from"]["query"];
  return from;
}

TEST(PluginCache, ARebuiltPluginRecomputesItsValuesAndBuiltInsStayCached) {
  // The process id: two checkouts' suites may run at the same time.
  const fs::path folder =
      fs::path(::testing::TempDir()) / ("radarpr_plugin_cache_" + std::to_string(::getpid()));
  fs::remove_all(folder);
  fs::create_directories(folder);
  // A copy of the plugin, so that touching it leaves the build tree alone.
  const fs::path plugin = folder / "librange_histogram_copy.so";
  fs::copy_file(RANGE_HISTOGRAM_TEST_PLUGIN_PATH, plugin);
  nlohmann::json config = nlohmann::json::parse(R"({
    "experiment": "plugin_cache_test",
    "datasets": [
      {"name": "town", "query": {"type": "synthetic", "seed": 11, "scans": 120,
        "range_bins": 840, "range_resolution_m": 0.119, "route_blocks_x": 1,
        "lap_pattern": "FR"}}
    ],
    "descriptors": ["range_histogram", "referee"],
    "protocol": {"exclude_recent_frames": 30, "revisit_radius_m": 10, "recall_at_k": [1]}
  })");
  config["plugins"] = {plugin.string()};
  const fs::path config_path = folder / "experiment.json";
  std::ofstream(config_path) << config.dump(2);
  auto run = [&](const std::string& name) {
    const fs::path out = folder / name;
    const auto result = run_cli("run " + config_path.string() + " --quiet --cache-dir " +
                                (folder / "cache").string() + " --out " + out.string());
    EXPECT_EQ(result.exit_code, 0) << result.output;
    return values_from(out);
  };

  using Sources = std::map<std::string, std::string>;
  EXPECT_EQ(run("first"), (Sources{{"range_histogram", "extracted"}, {"referee", "extracted"}}));
  // Unchanged: both from the cache (so the next check is not passing for another reason).
  EXPECT_EQ(run("again"), (Sources{{"range_histogram", "cache"}, {"referee", "cache"}}));
  // "Rebuilt": the same bytes, a new modification time.
  fs::last_write_time(plugin, fs::last_write_time(plugin) - std::chrono::hours(1));
  EXPECT_EQ(run("rebuilt"), (Sources{{"range_histogram", "extracted"}, {"referee", "cache"}}));
  fs::remove_all(folder);
}

}  // namespace
}  // namespace radarpr
