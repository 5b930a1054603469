#include <fstream>
#include <map>
#include <memory>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "cli/verb.hpp"
#include "evaluation/study/unit_runner.hpp"

namespace radarpr::cli {
namespace {

constexpr const char* kStatusDescription =
    R"(list the units of a plan: done, missing or failed

Per phase, how many units of the plan folder DIR are done (outputs present, with a matching
fingerprint), failed (DIR/units/ID.failed.txt holds the cause) or missing (not run, or still
running), then the ids of those not done, with the cause of each failure. Exit code 0 when every
unit is done, 1 otherwise.)";

struct StatusOptions {
  std::string folder;
};

int status(const StatusOptions& options) {
  const PlanFolder folder{options.folder};
  const ExperimentConfig config = load_plan_config(folder);
  const auto units = plan_units(config, UnitCosts::skip);
  std::map<std::pair<std::string, std::string>, std::size_t> counts;
  std::vector<std::string> lines;
  std::size_t not_done = 0;
  for (const auto& unit : units) {
    const UnitState state = unit_state(config, folder, unit);
    ++counts[{std::string(to_string(unit.phase)), std::string(to_string(state))}];
    if (state == UnitState::done) continue;
    ++not_done;
    std::string line = fmt::format("{} {}", to_string(state), unit.id);
    if (state == UnitState::failed) {
      std::ifstream file(folder.failure(unit.id));
      std::string cause;
      std::getline(file, cause);
      line += ": " + cause;
    }
    lines.push_back(line);
  }
  for (const char* phase : {"values", "evaluate"}) {
    fmt::print("{}: {} done, {} failed, {} missing\n", phase, counts[{phase, "done"}],
               counts[{phase, "failed"}], counts[{phase, "missing"}]);
  }
  for (const auto& line : lines) fmt::print("{}\n", line);
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
