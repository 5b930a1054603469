// A session matrix run as a plan's units does the work of one process, not more: each trainable
// descriptor is trained once per database session (N trainings), each session is decoded once for
// all of its descriptors and codebooks (N extractions), and evaluating decodes nothing.
#include <atomic>
#include <cstddef>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "datasets/cache_directory.hpp"
#include "evaluation/config/experiment_config.hpp"
#include "evaluation/study/study_plan.hpp"
#include "evaluation/study/unit_runner.hpp"
#include "tests/evaluation/counting_sequence.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

// Four sessions of one small town (coarse scans), ReFeree, R-ReFeree and a small Open-RadVLAD.
nlohmann::json four_session_study() {
  nlohmann::json json = nlohmann::json::parse(R"({
    "experiment": "study_units_test",
    "datasets": [{"kind": "session_matrix", "name": "town", "sessions": []}],
    "descriptors": ["referee", "referee_r",
      {"name": "open_radvlad", "params": {"min_bin": 10, "bin_dim": 8, "clusters": 4,
        "max_iterations": 5}}],
    "protocol": {"revisit_radius_m": 10, "recall_at_k": [1, 3]}
  })");
  const nlohmann::json base = nlohmann::json::parse(R"({"type": "synthetic", "seed": 5,
      "scans": 20, "azimuths": 120, "range_bins": 210, "range_resolution_m": 0.476,
      "route_blocks_x": 1, "speed_mps": 40})");
  const std::map<std::string, nlohmann::json> sessions = {
      {"clear", {{"session", 0}}},
      {"rain", {{"session", 1}, {"weather", "rain"}}},
      {"busy", {{"session", 2}, {"traffic", 0.9}}},
      {"parked", {{"session", 3}, {"parked_car_churn", 0.8}}}};
  for (const auto& [name, changes] : sessions) {
    nlohmann::json sequence = base;
    sequence.update(changes);
    json["datasets"][0]["sessions"].push_back({{"name", name}, {"sequence", sequence}});
  }
  return json;
}

// A fresh plan folder, also the process's cache (as load_plan_config makes it).
class ScopedPlanFolder {
 public:
  ScopedPlanFolder()
      : folder_{fs::temp_directory_path() /
                ("radarpr_study_units_test_" + std::to_string(::getpid()))} {
    fs::remove_all(folder_.root);
    fs::create_directories(folder_.units());
    fs::create_directories(folder_.cache());
    override_cache_directory(folder_.cache());
  }
  ~ScopedPlanFolder() {
    override_cache_directory(std::nullopt);
    std::error_code ignored;
    fs::remove_all(folder_.root, ignored);
  }
  const PlanFolder& folder() const { return folder_; }

 private:
  PlanFolder folder_;
};

TEST(StudyUnits, TrainOncePerDatabaseSessionAndDecodeEachSessionOnce) {
  const ScopedPlanFolder plan;
  ExperimentConfig config = parse_experiment_config(four_session_study());
  std::atomic<std::size_t> loads{0};
  std::size_t scans = 0;
  for (auto& session : config.matrices[0].sessions) {
    scans += open_sequence(session.sequence)->size();
    testing::count_loads(session.sequence, loads);
  }
  const auto units = plan_units(config, UnitCosts::skip);
  std::map<UnitPhase, std::size_t> per_phase;
  for (const auto& unit : units) ++per_phase[unit.phase];
  EXPECT_EQ(per_phase[UnitPhase::train], 4u);      // one codebook per database session
  EXPECT_EQ(per_phase[UnitPhase::values], 4u);     // one pass per session
  EXPECT_EQ(per_phase[UnitPhase::evaluate], 36u);  // 12 ordered pairs x 3 descriptors

  std::map<UnitPhase, std::size_t> decoded;
  for (UnitPhase phase : kUnitPhases) {
    const std::size_t before = loads.load();
    for (const auto& unit : units) {
      if (unit.phase == phase) {
        EXPECT_FALSE(run_unit(config, plan.folder(), unit, false).skipped) << unit.id;
      }
    }
    decoded[phase] = loads.load() - before;
  }
  // Each training reads its database session's scans once; the values units decode every
  // session once for both ReFeree variants and all four codebooks; evaluation reads values only.
  EXPECT_EQ(decoded[UnitPhase::train], scans);
  EXPECT_EQ(decoded[UnitPhase::values], scans);
  EXPECT_EQ(decoded[UnitPhase::evaluate], 0u);
  for (const auto& unit : units) {
    EXPECT_EQ(unit_state(config, plan.folder(), unit), UnitState::done) << unit.id;
    if (unit.phase == UnitPhase::train) {
      EXPECT_TRUE(fs::exists(plan.folder().trained(unit.id))) << unit.id;
    }
  }
}

// An evaluate unit reads its values through memory maps: a truncated or damaged values file is a
// failure that names the file (and what is wrong with it), leaves no result and is recorded as
// failed; once the file is deleted, the values unit runs again and the evaluate unit succeeds.
TEST(StudyUnits, ADamagedValuesFileFailsTheEvaluateUnitNamingTheFile) {
  const ScopedPlanFolder plan;
  nlohmann::json json = four_session_study();
  json["descriptors"] = {"referee"};
  json["datasets"][0]["pairs"] = {{{"query", "rain"}, {"database", "clear"}}};
  const ExperimentConfig config = parse_experiment_config(json);
  const auto units = plan_units(config, UnitCosts::skip);
  const StudyUnit* evaluate = nullptr;
  for (const auto& unit : units) {
    if (unit.phase == UnitPhase::evaluate) {
      evaluate = &unit;
    } else {
      run_unit(config, plan.folder(), unit, false);
    }
  }
  ASSERT_NE(evaluate, nullptr);
  std::vector<fs::path> entries;
  for (const auto& file : fs::recursive_directory_iterator(plan.folder().cache() / "descriptors")) {
    if (file.path().extension() == ".npy") entries.push_back(file.path());
  }
  ASSERT_EQ(entries.size(), 2u);  // the two sessions' ReFeree values
  for (const std::uintmax_t cut : {std::uintmax_t{8}, fs::file_size(entries[0]) - 3}) {
    for (const auto& entry : entries) fs::resize_file(entry, cut);
    try {
      run_unit(config, plan.folder(), *evaluate, false);
      ADD_FAILURE() << "an evaluate unit used values files cut to " << cut << " bytes";
    } catch (const std::runtime_error& error) {
      const std::string message = error.what();
      const bool names_an_entry = message.find(entries[0].string()) != std::string::npos ||
                                  message.find(entries[1].string()) != std::string::npos;
      EXPECT_TRUE(names_an_entry) << message;
      EXPECT_NE(message.find("unusable"), std::string::npos) << message;
      auto sidecar_of = [](fs::path values) { return values.replace_extension(".json").string(); };
      const bool says_what_to_delete =
          message.find("delete " + sidecar_of(entries[0]) + " and " + entries[0].string()) !=
              std::string::npos ||
          message.find("delete " + sidecar_of(entries[1]) + " and " + entries[1].string()) !=
              std::string::npos;
      EXPECT_TRUE(says_what_to_delete) << message;
    }
    EXPECT_EQ(unit_state(config, plan.folder(), *evaluate), UnitState::failed);
    EXPECT_FALSE(fs::exists(plan.folder().result(evaluate->id)));
  }
  for (const auto& entry : entries) fs::remove(entry);
  for (const auto& unit : units) {
    if (unit.phase == UnitPhase::values) {
      EXPECT_EQ(unit_state(config, plan.folder(), unit), UnitState::missing) << unit.id;
      EXPECT_FALSE(run_unit(config, plan.folder(), unit, false).skipped) << unit.id;
    }
  }
  EXPECT_FALSE(run_unit(config, plan.folder(), *evaluate, false).skipped);
  EXPECT_EQ(unit_state(config, plan.folder(), *evaluate), UnitState::done);
}

// The plan's estimate follows what a search costs: a KD-tree search of ReFeree's 50 floats costs
// far less per pair than an exhaustive search of Open-RadVLAD's 32,768, whose evaluate units
// dominate a study (docs/cluster.md).
TEST(StudyUnits, TheEstimateOfAnExhaustiveSearchGrowsWithItsValues) {
  nlohmann::json json = four_session_study();
  json["descriptors"] = nlohmann::json::parse(
      R"(["referee", {"name": "open_radvlad", "params": {"clusters": 64, "bin_dim": 512}}])");
  const ExperimentConfig config = parse_experiment_config(json);
  std::map<std::string, const StudyUnit*> evaluate;
  const auto units = plan_units(config, UnitCosts::estimate);
  for (const auto& unit : units) {
    if (unit.phase == UnitPhase::evaluate) evaluate[unit.id] = &unit;
  }
  const StudyUnit* referee = evaluate.at("evaluate.town.rain.clear.referee");
  const StudyUnit* vlad = nullptr;
  for (const auto& [id, unit] : evaluate) {
    if (id.rfind("evaluate.town.rain.clear.open_radvlad", 0) == 0) vlad = unit;
  }
  ASSERT_NE(vlad, nullptr);
  EXPECT_EQ(referee->comparisons, vlad->comparisons);
  EXPECT_GT(referee->estimated_cpu_seconds, 0.0);
  EXPECT_GT(vlad->estimated_cpu_seconds, 50.0 * referee->estimated_cpu_seconds);
}

}  // namespace
}  // namespace radarpr
