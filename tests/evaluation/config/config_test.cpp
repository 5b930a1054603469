#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "evaluation/config/config_error.hpp"
#include "evaluation/config/config_overrides.hpp"
#include "evaluation/config/experiment_config.hpp"

namespace radarpr {
namespace {

nlohmann::json minimal_config() {
  return nlohmann::json::parse(R"({
    "experiment": "unit",
    "datasets": [{"name": "town", "query": {"type": "synthetic", "seed": 3, "scans": 40}}],
    "descriptors": ["referee", {"name": "referee_r", "params": {"kernel": "box", "z_q": 3}}],
    "protocol": {"revisit_radius_m": 10, "labels": "retrieved_pair", "recall_at_k": [5, 1]}
  })");
}

// The key path the parser blames for `config`, or "" when it parses.
std::string blamed_path(const nlohmann::json& config) {
  try {
    parse_experiment_config(config);
  } catch (const ConfigError& error) {
    return error.key_path();
  }
  return "";
}

TEST(ExperimentConfig, ParsesDescriptorsProtocolAndDatasets) {
  const auto config = parse_experiment_config(minimal_config());
  EXPECT_EQ(config.name, "unit");
  ASSERT_EQ(config.descriptors.size(), 2u);
  EXPECT_EQ(config.descriptors[0].id, "referee");
  EXPECT_EQ(config.descriptors[1].id, "referee_r:kernel=box,z_q=3");
  EXPECT_EQ(config.protocol.revisit_radius_m, 10.0);
  EXPECT_EQ(config.protocol.labels, LabelRule::retrieved_pair);
  EXPECT_EQ(config.protocol.sweep, ThresholdSweep::exact);           // default
  EXPECT_EQ(config.protocol.exclude_recent_frames, 50);              // default
  EXPECT_EQ(config.protocol.recall_at_k, (std::vector<int>{1, 5}));  // sorted
  ASSERT_EQ(config.datasets.size(), 1u);
  EXPECT_FALSE(config.datasets[0].multi_session());
}

TEST(ExperimentConfig, AProtocolPresetSetsDefaultsThatKeysStillOverride) {
  auto config = minimal_config();
  config["protocol"] = {{"preset", "mulran_sc_evaluator"}, {"revisit_radius_m", 5}};
  auto parsed = parse_experiment_config(config);
  EXPECT_EQ(parsed.protocol.preset, ProtocolPreset::mulran_sc_evaluator);
  EXPECT_EQ(parsed.protocol.exclude_recent_frames, 49);
  EXPECT_EQ(parsed.protocol.radius_comparison, RadiusComparison::strict);
  EXPECT_EQ(parsed.protocol.sweep, ThresholdSweep::mulran_grid);
  EXPECT_EQ(parsed.protocol.revisit_radius_m, 5.0);
  // Results name the preset and its radius comparison.
  const nlohmann::json json = protocol_to_json(parsed.protocol);
  EXPECT_EQ(json.at("preset"), "mulran_sc_evaluator");
  EXPECT_EQ(json.at("radius_comparison"), "strict");

  config["protocol"] = {
      {"preset", "mulran_sc_evaluator"}, {"sweep", "exact"}, {"radius_comparison", "inclusive"}};
  parsed = parse_experiment_config(config);
  EXPECT_EQ(parsed.protocol.sweep, ThresholdSweep::exact);
  EXPECT_EQ(parsed.protocol.radius_comparison, RadiusComparison::inclusive);
  EXPECT_EQ(parsed.protocol.exclude_recent_frames, 49);

  config["protocol"] = {{"preset", "mulran"}};
  EXPECT_EQ(blamed_path(config), "protocol.preset");
  config["protocol"] = {{"radius_comparison", "<"}};
  EXPECT_EQ(blamed_path(config), "protocol.radius_comparison");
  // radarpr's own protocol names neither (its results stay as they were).
  const nlohmann::json plain = protocol_to_json(parse_experiment_config(minimal_config()).protocol);
  EXPECT_FALSE(plain.contains("preset"));
  EXPECT_FALSE(plain.contains("radius_comparison"));
}

TEST(ExperimentConfig, AHeadingLimitIsReadCheckedAndRecorded) {
  auto config = minimal_config();
  EXPECT_FALSE(parse_experiment_config(config).protocol.revisit_max_yaw_deg.has_value());
  EXPECT_FALSE(
      protocol_to_json(parse_experiment_config(config).protocol).contains("revisit_max_yaw_deg"));
  config["protocol"]["revisit_max_yaw_deg"] = 30;
  const auto parsed = parse_experiment_config(config);
  ASSERT_TRUE(parsed.protocol.revisit_max_yaw_deg.has_value());
  EXPECT_EQ(*parsed.protocol.revisit_max_yaw_deg, 30.0);
  EXPECT_EQ(protocol_to_json(parsed.protocol).at("revisit_max_yaw_deg"), 30.0);
  config["protocol"]["revisit_max_yaw_deg"] = nullptr;
  EXPECT_FALSE(parse_experiment_config(config).protocol.revisit_max_yaw_deg.has_value());
  for (const nlohmann::json& bad :
       {nlohmann::json(0), nlohmann::json(-10), nlohmann::json(181), nlohmann::json("30")}) {
    config["protocol"]["revisit_max_yaw_deg"] = bad;
    EXPECT_EQ(blamed_path(config), "protocol.revisit_max_yaw_deg") << bad.dump();
  }
}

TEST(ExperimentConfig, TyposAreNamedByTheirKeyPath) {
  auto config = minimal_config();
  config["protocol"]["revisit_radius"] = 5;
  EXPECT_EQ(blamed_path(config), "protocol.revisit_radius");

  config = minimal_config();
  config["descriptors"][1]["params"]["zq"] = 3;
  EXPECT_EQ(blamed_path(config), "descriptors[1].params.zq");

  config = minimal_config();
  config["datasets"][0]["query"]["sead"] = 3;
  EXPECT_EQ(blamed_path(config), "datasets[0].query.sead");

  config = minimal_config();
  config["experimnt"] = "x";
  EXPECT_EQ(blamed_path(config), "experimnt");
}

TEST(ExperimentConfig, BadValuesAreNamedByTheirKeyPath) {
  auto config = minimal_config();
  config["protocol"]["labels"] = "strict";
  EXPECT_EQ(blamed_path(config), "protocol.labels");

  config = minimal_config();
  config["protocol"]["revisit_radius_m"] = -1;
  EXPECT_EQ(blamed_path(config), "protocol.revisit_radius_m");

  config = minimal_config();
  config["descriptors"][0] = "referee_x";
  EXPECT_EQ(blamed_path(config), "descriptors[0]");

  config = minimal_config();
  config["descriptors"][1]["name"] = "nope";
  EXPECT_EQ(blamed_path(config), "descriptors[1].name");

  config = minimal_config();
  config["descriptors"][1]["params"]["kernel"] = "boxy";
  EXPECT_EQ(blamed_path(config), "descriptors[1].params.kernel");

  config = minimal_config();
  config["descriptors"].push_back("referee");  // listed twice
  EXPECT_EQ(blamed_path(config), "descriptors[2]");

  config = minimal_config();
  config["datasets"][0]["name"] = "../escape";
  EXPECT_EQ(blamed_path(config), "datasets[0].name");

  config = minimal_config();
  config["datasets"][0]["query"]["type"] = "nuscenes";  // not a known type
  EXPECT_EQ(blamed_path(config), "datasets[0].query.type");

  config = minimal_config();
  config.erase("descriptors");
  EXPECT_EQ(blamed_path(config), "descriptors");
}

// A typo must not ask for terabytes or a drive that never ends: each bound names its key.
TEST(ExperimentConfig, SyntheticSizesAreBoundedByTheirKeyPath) {
  const std::vector<std::pair<std::string, nlohmann::json>> too_big = {
      {"scans", 2'000'000},
      {"range_bins", 20'000'000},
      {"range_resolution_m", 50.0},  // 1680 bins x 50 m: far beyond any radar
      {"speed_mps", 1e20},           // laps without end
      {"route_blocks_x", 10'000},
      {"session", 5000},
      {"azimuths", 0},
      // A scan of a few cells gives every descriptor nearly one value for all scans.
      {"azimuths", 15},
      {"range_bins", 3}};
  for (const auto& [key, value] : too_big) {
    auto config = minimal_config();
    config["datasets"][0]["query"][key] = value;
    EXPECT_EQ(blamed_path(config), "datasets[0].query." + key) << key;
  }
  auto config = minimal_config();
  config["datasets"][0]["query"]["azimuths"] = 8000;  // 8000 x 3360 pixels a scan
  config["datasets"][0]["query"]["range_bins"] = 3360;
  EXPECT_EQ(blamed_path(config), "datasets[0].query.range_bins");
}

TEST(ConfigOverrides, SetChangesNestedValuesAndParsesJson) {
  auto config = minimal_config();
  apply_config_override(config, "protocol.revisit_radius_m=5");
  apply_config_override(config, "descriptors.1.params.kernel=gaussian");
  apply_config_override(config, "datasets.0.query.scans=60");
  apply_config_override(config, "protocol.sweep=linear100");  // a new key
  EXPECT_EQ(config["protocol"]["revisit_radius_m"], 5);
  EXPECT_EQ(config["descriptors"][1]["params"]["kernel"], "gaussian");
  EXPECT_EQ(config["datasets"][0]["query"]["scans"], 60);
  const auto parsed = parse_experiment_config(config);
  EXPECT_EQ(parsed.descriptors[1].id, "referee_r:z_q=3");
  EXPECT_EQ(parsed.protocol.sweep, ThresholdSweep::linear100);
}

TEST(ConfigOverrides, RejectsPathsThatDoNotExist) {
  auto config = minimal_config();
  EXPECT_THROW(apply_config_override(config, "protocl.labels=standard"), ConfigError);
  EXPECT_THROW(apply_config_override(config, "descriptors.7.name=x"), ConfigError);
  EXPECT_THROW(apply_config_override(config, "no_equals_sign"), ConfigError);
  EXPECT_THROW(apply_config_override(config, "experiment.sub=1"), ConfigError);
}

// Found by fuzzing (tests/fuzz/corpus/config/override_not_utf8.json): a --set value that is not
// UTF-8 became a config string, and the number check's message then failed to quote it (a JSON
// library error naming neither the --set nor the key).
TEST(ConfigOverrides, RefusesBytesThatAreNotUtf8) {
  for (const std::string assignment :
       {"protocol.revisit_radius_m=1\xff", "protocol.x\xc3=1", "descriptors.0=\xe2\x82"}) {
    auto config = minimal_config();
    try {
      apply_config_override(config, assignment);
      FAIL() << "expected an OverrideError";
    } catch (const OverrideError& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find("--set " + assignment), std::string::npos) << message;
      EXPECT_NE(message.find("not UTF-8"), std::string::npos) << message;
    }
  }
  auto config = minimal_config();
  apply_config_override(config, "experiment=r\xc3\xa9sum\xc3\xa9");  // UTF-8 text is fine
  EXPECT_EQ(config["experiment"], "r\xc3\xa9sum\xc3\xa9");
}

TEST(ExperimentConfigFile, ErrorsNameTheFile) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("radarpr_config_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto path = dir / "typo.json";
  auto config = minimal_config();
  config["protocol"]["lables"] = "standard";
  std::ofstream(path) << config.dump();
  try {
    load_experiment_config(path);
    FAIL() << "expected a ConfigError";
  } catch (const ConfigError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(path.string()), std::string::npos) << message;
    EXPECT_NE(message.find("protocol.lables"), std::string::npos) << message;
  }
  std::ofstream(dir / "broken.json") << "{\"experiment\": ";
  EXPECT_THROW(load_experiment_config(dir / "broken.json"), std::runtime_error);
  EXPECT_THROW(load_experiment_config(dir / "missing.json"), std::runtime_error);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace radarpr
