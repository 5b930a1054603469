// Plugin descriptors in every part of radarpr: an experiment config's "plugins", a run, the
// descriptor cache key, `radarpr list`, $RADARPR_PLUGINS and `radarpr bench`.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "descriptors/descriptor_registry.hpp"
#include "evaluation/config/config_error.hpp"
#include "evaluation/config/experiment_config.hpp"
#include "evaluation/descriptor_cache.hpp"
#include "evaluation/experiment_runner.hpp"
#include "tests/cli/cli_runner.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;
using testing::run_cli;

#define EXPECT_CONTAINS(text, part) \
  EXPECT_NE(std::string(text).find(part), std::string::npos) << "in: " << (text)

fs::path fresh_folder(const std::string& name) {
  const fs::path folder = fs::path(::testing::TempDir()) / name;
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

// A small town (one block, a forward and a reverse lap) at a coarse range, as in runner_test.
nlohmann::json small_experiment(const std::string& plugin) {
  nlohmann::json config = nlohmann::json::parse(R"({
    "experiment": "plugin_test",
    "datasets": [
      {"name": "town", "query": {"type": "synthetic", "seed": 11, "scans": 160,
        "range_bins": 840, "range_resolution_m": 0.119, "route_blocks_x": 1,
        "lap_pattern": "FR"}}
    ],
    "descriptors": ["range_histogram", "range_histogram:distance=l1", "referee"],
    "protocol": {"exclude_recent_frames": 30, "revisit_radius_m": 10, "recall_at_k": [1]}
  })");
  config["plugins"] = {plugin};
  return config;
}

TEST(PluginPipeline, AConfigLoadsItsPluginsRelativeToItsFolderAndRunsThem) {
  const fs::path folder = fresh_folder("radarpr_plugin_config");
  const fs::path plugin = RANGE_HISTOGRAM_TEST_PLUGIN_PATH;
  const fs::path config_path = folder / "experiment.json";
  std::ofstream(config_path) << small_experiment(fs::relative(plugin, folder).string()).dump(2);

  const ExperimentConfig config = load_experiment_config(config_path);
  ASSERT_EQ(config.plugins.size(), 1u);
  EXPECT_EQ(fs::canonical(config.plugins[0]), fs::canonical(plugin));
  ASSERT_EQ(config.descriptors.size(), 3u);
  EXPECT_EQ(config.descriptors[1].id, "range_histogram:distance=l1");

  const ExperimentRun run = run_experiment(config, /*show_progress=*/false);
  ASSERT_EQ(run.datasets.size(), 1u);
  ASSERT_EQ(run.datasets[0].descriptors.size(), 3u);
  for (std::size_t d = 0; d < 2; ++d) {
    const DescriptorRun& result = run.datasets[0].descriptors[d];
    EXPECT_EQ(result.rows, 1);
    EXPECT_EQ(result.cols, 10);  // the default bands
    EXPECT_TRUE(result.rotation_invariant);
    // Single session: the first 30 queries have no eligible frame.
    EXPECT_EQ(result.evaluation.metrics.queries, 160u - 30u);
  }
  fs::remove_all(folder);
}

TEST(PluginPipeline, AConfigNamingAMissingPluginFailsAtItsKey) {
  try {
    parse_experiment_config(small_experiment("no/such/plugin.so"), "/nonexistent-folder");
    ADD_FAILURE() << "the config was accepted";
  } catch (const ConfigError& error) {
    EXPECT_EQ(error.key_path(), "plugins[0]");
    EXPECT_CONTAINS(error.what(), "/nonexistent-folder/no/such/plugin.so: file not found");
  }
  nlohmann::json not_a_path = small_experiment("x");
  not_a_path["plugins"] = {42};
  EXPECT_THROW(parse_experiment_config(not_a_path), ConfigError);
}

TEST(PluginPipeline, TheCacheKeyOfAPluginDescriptorNamesThePluginBuild) {
  DescriptorCacheKey key{"range_histogram", "sequence", ""};
  const std::string built_in = key.text();
  EXPECT_EQ(built_in.find("plugin="), std::string::npos);
  key.plugin_build = "/p/librange_histogram.so 1000 bytes, modified 1";
  const std::string first = key.text();
  key.plugin_build = "/p/librange_histogram.so 1008 bytes, modified 2";  // rebuilt
  EXPECT_NE(first, key.text());
  EXPECT_CONTAINS(first, "plugin=/p/librange_histogram.so 1000 bytes");
}

TEST(PluginPipeline, ListShowsAPluginDescriptorWithTheBuiltIns) {
  const auto listed = run_cli(std::string("list --plugin ") + RANGE_HISTOGRAM_TEST_PLUGIN_PATH);
  ASSERT_EQ(listed.exit_code, 0) << listed.output;
  EXPECT_CONTAINS(listed.output, "range_histogram\n");
  EXPECT_CONTAINS(listed.output,
                  "from plugin " + fs::canonical(RANGE_HISTOGRAM_TEST_PLUGIN_PATH).string());
  EXPECT_CONTAINS(listed.output, "referee\n");

  const auto json = run_cli(std::string("list --json range_histogram:bands=8 --plugin=") +
                            RANGE_HISTOGRAM_TEST_PLUGIN_PATH);
  ASSERT_EQ(json.exit_code, 0) << json.output;
  const auto document = nlohmann::json::parse(json.output);
  ASSERT_EQ(document.size(), 1u);
  EXPECT_EQ(document[0]["id"], "range_histogram:bands=8");
  EXPECT_EQ(document[0]["origin"], "plugin");
  EXPECT_EQ(document[0]["sizes"][0]["shape"], nlohmann::json::array({1, 8}));
}

TEST(PluginPipeline, TheEnvironmentNamesPluginsForEveryCommand) {
  const auto listed =
      run_cli("list plugin_probe", std::string("RADARPR_PLUGINS=") + PROBE_PLUGIN_PATH + ":" +
                                       RANGE_HISTOGRAM_TEST_PLUGIN_PATH);
  ASSERT_EQ(listed.exit_code, 0) << listed.output;
  EXPECT_CONTAINS(listed.output, "plugin_probe\n");
}

TEST(PluginPipeline, TheCommandLineReportsAPluginThatFailsToLoad) {
  const auto missing = run_cli("list --plugin /nonexistent/libgone.so");
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_CONTAINS(missing.output, "radarpr: error: plugin /nonexistent/libgone.so: file not found");
  const auto wrong_version = run_cli(std::string("list --plugin ") + VERSION_MISMATCH_PLUGIN_PATH);
  EXPECT_EQ(wrong_version.exit_code, 1);
  EXPECT_CONTAINS(wrong_version.output, "major.minor must match");
  EXPECT_EQ(run_cli("list --plugin").exit_code, 2);
}

TEST(PluginPipeline, BenchMeasuresAPluginDescriptor) {
  const fs::path out = fresh_folder("radarpr_plugin_bench");
  // The plugin's extraction only, on synthetic scans: about a second.
  const auto result = run_cli(
      "bench --quick --force --filter '^extract/plugin_probe/' --data "
      "/nonexistent --out " +
      out.string() + " --plugin " + PROBE_PLUGIN_PATH);
  if (result.output.find("built without benchmarks") != std::string::npos) {
    GTEST_SKIP() << "radarpr built without benchmarks (RADARPR_BUILD_BENCHMARKS=OFF)";
  }
  ASSERT_EQ(result.exit_code, 0) << result.output;
  std::ifstream json_file(out / "bench.json");
  const nlohmann::json json = nlohmann::json::parse(json_file);
  std::vector<std::string> names;
  for (const auto& entry : json["results"]) names.push_back(entry["name"]);
  EXPECT_NE(std::find(names.begin(), names.end(), "extract/plugin_probe/400x3360"), names.end())
      << json["results"].dump();
  fs::remove_all(out);
}

}  // namespace
}  // namespace radarpr
