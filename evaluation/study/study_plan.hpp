#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evaluation/config/experiment_config.hpp"
#include "evaluation/session_matrix_values.hpp"

namespace radarpr {

// The phases of a plan, run in order: a unit of a later phase reads what the earlier one wrote.
enum class UnitPhase {
  values,    // descriptor values of sessions (and the training they need) into the plan's cache
  evaluate,  // one pair x descriptor (or a whole ordinary dataset) into units/<id>.json
};
std::string_view to_string(UnitPhase phase);

// One unit of work of a plan. Its id is stable: it names what the unit computes, never a
// position, so a re-plan of the same config gives the same ids.
struct StudyUnit {
  std::string id;
  UnitPhase phase = UnitPhase::values;
  // What it computes: descriptor values of a matrix (jobs), a matrix pair x descriptor, or an
  // ordinary dataset whole.
  std::optional<std::size_t> matrix;
  std::optional<std::size_t> pair;        // evaluate: the pair of `matrix`
  std::optional<std::size_t> dataset;     // an ordinary dataset (index in config.datasets)
  std::optional<std::size_t> descriptor;  // index in config.descriptors
  std::vector<MatrixValueJob> jobs;       // the values it needs (evaluate) or computes (values)
  std::size_t scans_described = 0;        // scans decoded for extraction, for the estimate
  std::size_t scans_trained = 0;
  std::size_t comparisons = 0;  // query x database pairs searched (evaluate)
  double estimated_cpu_seconds = 0.0;
};

// How much plan_units works out. The cost estimate opens every session to count its scans;
// running, checking and merging units needs only the units themselves, and a task that opened
// every session of a study for its estimate would pay that once per unit.
enum class UnitCosts { estimate, skip };

// The units of `config`, phase by phase, in a fixed order (the same ids and work either way).
std::vector<StudyUnit> plan_units(const ExperimentConfig& config,
                                  UnitCosts costs = UnitCosts::estimate);

// What a plan folder holds.
struct PlanFolder {
  std::filesystem::path root;
  std::filesystem::path manifest() const { return root / "plan.json"; }
  std::filesystem::path config() const { return root / "config.json"; }
  std::filesystem::path cache() const { return root / "cache"; }
  std::filesystem::path units() const { return root / "units"; }
  std::filesystem::path result(const std::string& id) const { return units() / (id + ".json"); }
  std::filesystem::path stamp(const std::string& id) const { return units() / (id + ".done.json"); }
  std::filesystem::path failure(const std::string& id) const {
    return units() / (id + ".failed.txt");
  }
};

// The manifest (plan.json): per phase its units with their inputs, outputs and estimated cost.
nlohmann::json plan_manifest(const ExperimentConfig& config, const PlanFolder& folder,
                             const std::vector<StudyUnit>& units,
                             const std::filesystem::path& config_folder);

// Writes `bytes` to `path` through a temporary file in the same folder and a rename: readers see
// the whole file or none, and a failure leaves nothing behind. Throws std::runtime_error.
void write_file_atomically(const std::filesystem::path& path, const std::string& bytes);

}  // namespace radarpr
