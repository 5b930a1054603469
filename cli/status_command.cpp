#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "cli/verb.hpp"
#include "evaluation/study/slurm_scripts.hpp"
#include "evaluation/study/unit_runner.hpp"

namespace radarpr::cli {
namespace {

constexpr const char* kStatusDescription =
    R"(list the units of a plan: done, missing or failed

Per phase, how many units of the plan folder DIR are done (outputs present, with a matching
fingerprint), failed (DIR/units/ID.failed.txt holds the cause) or missing (not run, or still
running), then the ids of those not done, with the cause of each failure and the unit's index in
DIR/PHASE.units (its Slurm array index). With DIR/slurm/ (plan --slurm), ends with the sbatch
command per phase that runs those indices again. Exit code 0 when every unit is done, 1
otherwise.)";

struct StatusOptions {
  std::string folder;
};

// The lines of DIR/PHASE.units (what the phase's job array indexes), by unit id.
std::map<std::string, std::size_t> array_indices(const PlanFolder& folder, UnitPhase phase) {
  std::map<std::string, std::size_t> indices;
  std::ifstream file(folder.root / (std::string(to_string(phase)) + ".units"));
  std::string id;
  for (std::size_t line = 0; std::getline(file, id); ++line) indices.emplace(id, line);
  return indices;
}

// "0-3,7,9-10": indices in increasing order as sbatch --array takes them.
std::string array_ranges(const std::vector<std::size_t>& sorted) {
  std::vector<std::string> parts;
  for (std::size_t i = 0; i < sorted.size();) {
    std::size_t j = i;
    while (j + 1 < sorted.size() && sorted[j + 1] == sorted[j] + 1) ++j;
    parts.push_back(j == i ? fmt::format("{}", sorted[i])
                           : fmt::format("{}-{}", sorted[i], sorted[j]));
    i = j + 1;
  }
  return fmt::format("{}", fmt::join(parts, ","));
}

int status(const StatusOptions& options) {
  const PlanFolder folder{options.folder};
  const ExperimentConfig config = load_plan_config(folder);
  const auto units = plan_units(config, UnitCosts::skip);
  std::map<std::pair<std::string, std::string>, std::size_t> counts;
  std::map<UnitPhase, std::map<std::string, std::size_t>> indices;
  std::map<UnitPhase, std::vector<std::size_t>> to_rerun;
  std::vector<std::string> lines;
  std::size_t not_done = 0;
  for (const auto& unit : units) {
    const UnitState state = unit_state(config, folder, unit);
    ++counts[{std::string(to_string(unit.phase)), std::string(to_string(state))}];
    if (state == UnitState::done) continue;
    ++not_done;
    std::string line = fmt::format("{} {}", to_string(state), unit.id);
    if (!indices.count(unit.phase)) indices[unit.phase] = array_indices(folder, unit.phase);
    if (const auto index = indices[unit.phase].find(unit.id); index != indices[unit.phase].end()) {
      line += fmt::format(" [{} {}]", to_string(unit.phase), index->second);
      to_rerun[unit.phase].push_back(index->second);
    }
    if (state == UnitState::failed) {
      std::ifstream file(folder.failure(unit.id));
      std::string cause;
      std::getline(file, cause);
      line += ": " + cause;
    }
    lines.push_back(line);
  }
  for (UnitPhase each : kUnitPhases) {
    const std::string phase(to_string(each));
    fmt::print("{}: {} done, {} failed, {} missing\n", phase, counts[{phase, "done"}],
               counts[{phase, "failed"}], counts[{phase, "missing"}]);
  }
  for (const auto& line : lines) fmt::print("{}\n", line);
  // The job arrays of plan --slurm index PHASE.units: the indices not done, ready to resubmit
  // (units done meanwhile are skipped by run-unit, so a missing one still running does no harm).
  const std::filesystem::path slurm = folder.root / "slurm";
  std::error_code error;
  if (!to_rerun.empty() && std::filesystem::is_directory(slurm, error)) {
    fmt::print(
        "to run them on Slurm, in order, each after the one before (--dependency=afterok:JOB):\n");
    for (auto& [phase, list] : to_rerun) {
      std::sort(list.begin(), list.end());
      fmt::print("  (cd {} && sbatch --array={} {}.sbatch)\n", shell_quote(slurm.string()),
                 array_ranges(list), to_string(phase));
    }
  }
  return not_done == 0 ? 0 : 1;
}

VerbAction define_status(CLI::App& verb) {
  auto options = std::make_shared<StatusOptions>();
  verb.add_option("DIR", options->folder, "a plan folder (radarpr plan --out)")->required();
  return [options] { return status(*options); };
}

}  // namespace

Verb status_verb() {
  return {"status", kStatusDescription, define_status};
}

}  // namespace radarpr::cli
