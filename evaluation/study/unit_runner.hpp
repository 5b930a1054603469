#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "evaluation/config/experiment_config.hpp"
#include "evaluation/experiment_runner.hpp"
#include "evaluation/study/study_plan.hpp"

namespace radarpr {

// Writes a plan folder for `config`: config.json (the config as resolved, --set applied),
// plan.json (the manifest) and the empty units/ and cache/ folders. Refuses a folder that holds
// something other than a plan of the same experiment.
std::vector<StudyUnit> write_plan(const ExperimentConfig& config,
                                  const std::filesystem::path& config_folder,
                                  const PlanFolder& folder);

// The config a plan folder was written for; relative plugin paths resolve against the folder of
// the original config, which plan.json names. Points the descriptor cache at the plan's cache/.
ExperimentConfig load_plan_config(const PlanFolder& folder);

// What a unit's outputs are checked against: the radarpr build, the config and the unit's id.
std::string unit_fingerprint(const ExperimentConfig& config, const StudyUnit& unit);

enum class UnitState { done, missing, failed };
std::string_view to_string(UnitState state);
UnitState unit_state(const ExperimentConfig& config, const PlanFolder& folder,
                     const StudyUnit& unit);

struct UnitOutcome {
  bool skipped = false;  // its outputs existed with a matching fingerprint
  double seconds = 0.0;
};

// Runs one unit: values units fill the plan's cache (and stamp units/<id>.done.json), evaluate
// units write units/<id>.json. Every output is written atomically; on failure the unit's
// failure file (units/<id>.failed.txt) says why and the exception is rethrown.
UnitOutcome run_unit(const ExperimentConfig& config, const PlanFolder& folder,
                     const StudyUnit& unit, bool show_progress);

// The run the units of a finished plan add up to, as `radarpr run` would hold it in one process.
// Throws std::runtime_error listing the units that are not done.
ExperimentRun merge_units(const ExperimentConfig& config, const PlanFolder& folder,
                          const std::vector<StudyUnit>& units);

}  // namespace radarpr
