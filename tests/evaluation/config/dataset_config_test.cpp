// Config types of the real datasets: key validation with key paths, ${ENV} roots, and the
// configs/paper/ files.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "evaluation/config/config_error.hpp"
#include "evaluation/config/config_overrides.hpp"
#include "evaluation/config/environment_expansion.hpp"
#include "evaluation/config/experiment_config.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

nlohmann::json config_with(const nlohmann::json& query) {
  return {{"experiment", "unit"},
          {"datasets", {{{"name", "real"}, {"query", query}}}},
          {"descriptors", {"referee"}}};
}

// The key path the parser blames, or "" when the config parses.
std::string blamed_path(const nlohmann::json& config) {
  try {
    parse_experiment_config(config);
  } catch (const ConfigError& error) {
    return error.key_path();
  }
  return "";
}

TEST(DatasetConfig, EveryTypeParsesWithItsOwnKeys) {
  for (const auto& query : {
           nlohmann::json{{"type", "mulran"},
                          {"root", "/d"},
                          {"sequence", "KAIST03"},
                          {"polar", "polar_oxford_form"},
                          {"every_nth", 2},
                          {"start", 10},
                          {"end", 500}},
           nlohmann::json{{"type", "oxford"},
                          {"root", "/d"},
                          {"poses", "odometry"},
                          {"range_resolution_m", 0.0438},
                          {"max_pose_gap_s", 2}},
           nlohmann::json{{"type", "boreas"}, {"root", "/d"}, {"sequence", "boreas-x"}},
           nlohmann::json{{"type", "oord"}, {"root", "/d"}, {"azimuths", 400}},
           nlohmann::json{{"type", "radiate"}, {"root", "/d"}},
           nlohmann::json{{"type", "folder"},
                          {"root", "/d"},
                          {"range_resolution_m", 0.05},
                          {"scans", "png"},
                          {"poses", "gt.csv"},
                          {"layout", "oxford"},
                          {"position_frame", "local"}},
       }) {
    EXPECT_EQ(blamed_path(config_with(query)), "") << query.dump();
    // Parsing never touches the disk: "/d" does not exist.
    EXPECT_EQ(parse_experiment_config(config_with(query)).datasets[0].query.type, query["type"]);
  }
}

TEST(DatasetConfig, BadKeysAndValuesAreNamedByTheirKeyPath) {
  const nlohmann::json base{{"type", "mulran"}, {"root", "/d"}};
  auto with = [&](const std::string& key, const nlohmann::json& value) {
    nlohmann::json query = base;
    query[key] = value;
    return blamed_path(config_with(query));
  };
  EXPECT_EQ(with("polarr", "polar"), "datasets[0].query.polarr");    // typo
  EXPECT_EQ(with("poses", "gps"), "datasets[0].query.poses");        // oxford's key
  EXPECT_EQ(with("polar", "cartesian"), "datasets[0].query.polar");  // not a choice
  EXPECT_EQ(with("every_nth", 0), "datasets[0].query.every_nth");
  EXPECT_EQ(with("start", -1), "datasets[0].query.start");
  EXPECT_EQ(with("end", 0), "datasets[0].query.end");  // end must exceed start
  EXPECT_EQ(with("range_resolution_m", -0.1), "datasets[0].query.range_resolution_m");
  EXPECT_EQ(with("root", ""), "datasets[0].query.root");
  EXPECT_EQ(blamed_path(config_with({{"type", "folder"}, {"root", "/d"}})),
            "datasets[0].query.range_resolution_m");  // required for folders
  EXPECT_EQ(blamed_path(config_with({{"type", "mulran"}})), "datasets[0].query.root");
}

TEST(EnvironmentExpansion, ReplacesVariablesAndExplainsUnsetOnes) {
  ::setenv("RADARPR_TEST_DATA_ROOT", "/data/radar", 1);
  EXPECT_EQ(expand_environment_variables("${RADARPR_TEST_DATA_ROOT}/mulran", "k"),
            "/data/radar/mulran");
  EXPECT_EQ(expand_environment_variables("$HOME/x", "k"), "$HOME/x");  // only ${...}
  ::unsetenv("RADARPR_TEST_DATA_ROOT");
  try {
    expand_environment_variables("${RADARPR_TEST_DATA_ROOT}", "datasets[2].database.root");
    ADD_FAILURE();
  } catch (const ConfigError& error) {
    const std::string message = error.what();
    EXPECT_EQ(error.key_path(), "datasets[2].database.root");
    EXPECT_NE(message.find("environment variable RADARPR_TEST_DATA_ROOT is not set"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("export RADARPR_TEST_DATA_ROOT="), std::string::npos) << message;
    EXPECT_NE(message.find("--set datasets.2.database.root="), std::string::npos) << message;
  }
  EXPECT_THROW(expand_environment_variables("${UNTERMINATED", "k"), ConfigError);
  EXPECT_EQ(override_path("datasets[10].query.root"), "datasets.10.query.root");
}

TEST(EnvironmentExpansion, SetOverridesTheRootBeforeExpansion) {
  ::unsetenv("RADARPR_TEST_UNSET_ROOT");
  nlohmann::json config = config_with({{"type", "oxford"}, {"root", "${RADARPR_TEST_UNSET_ROOT}"}});
  EXPECT_EQ(blamed_path(config), "datasets[0].query.root");
  apply_config_override(config, "datasets.0.query.root=/data/oxford");
  EXPECT_EQ(blamed_path(config), "");
}

fs::path paper_configs() {
  return fs::path(RADARPR_SOURCE_DIR) / "configs" / "paper";
}

TEST(PaperConfigs, ParseWithRootsFromTheEnvironment) {
  for (const char* variable :
       {"RADARPR_MULRAN_ROOT", "RADARPR_OXFORD_ROOT", "RADARPR_BOREAS_ROOT", "RADARPR_OORD_ROOT"}) {
    ::setenv(variable, "/nonexistent", 1);
  }
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(paper_configs())) {
    if (entry.path().extension() != ".json") continue;
    ++files;
    SCOPED_TRACE(entry.path().string());
    const ExperimentConfig config = load_experiment_config(entry.path());
    EXPECT_EQ(config.protocol.revisit_radius_m, 20.0);  // the paper's radius
    ASSERT_FALSE(config.datasets.empty());
    const bool mulran = entry.path().filename().string().starts_with("mulran");
    for (const DatasetConfig& dataset : config.datasets) {
      EXPECT_EQ(dataset.multi_session(), !mulran) << dataset.name;
    }
    // Every root comes from a variable: unset them and the config names one.
    std::ifstream file(entry.path());
    const auto raw = nlohmann::json::parse(file);
    for (const auto& dataset : raw["datasets"]) {
      EXPECT_TRUE(dataset["query"]["root"].get<std::string>().starts_with("${RADARPR_"));
    }
  }
  EXPECT_EQ(files, 6u);

  // configs/paper_table.json: every row of the table on the same datasets.
  const ExperimentConfig table =
      load_experiment_config(paper_configs().parent_path() / "paper_table.json");
  std::vector<std::string> names;
  for (const DatasetConfig& dataset : table.datasets) names.push_back(dataset.name);
  EXPECT_EQ(names, (std::vector<std::string>{
                       "mulran_dcc", "mulran_kaist", "mulran_riverside", "oord_bellmouth_120120",
                       "oord_hydro_152402", "oord_hydro_160326", "oord_maree_164337",
                       "oord_twolochs_114037", "boreas_glen_shields", "oxford_2019_01_10"}));
  EXPECT_EQ(table.descriptors.size(), 7u);

  ::unsetenv("RADARPR_OORD_ROOT");
  try {
    load_experiment_config(paper_configs() / "oord.json");
    ADD_FAILURE();
  } catch (const ConfigError& error) {
    EXPECT_NE(std::string(error.what()).find("RADARPR_OORD_ROOT is not set"), std::string::npos);
    EXPECT_EQ(error.key_path(), "datasets[0].query.root");
  }
}

}  // namespace
}  // namespace radarpr
