#include <algorithm>
#include <memory>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "cli/common_options.hpp"
#include "cli/verb.hpp"
#include "evaluation/study/unit_runner.hpp"

namespace radarpr::cli {
namespace {

constexpr const char* kRunUnitDescription =
    R"(run units of a plan (see radarpr plan --help)

Runs each unit ID of the plan folder DIR in turn. A unit whose outputs exist with the fingerprint
of this radarpr build and the plan's config is skipped. Outputs are written to a temporary file
and renamed into place, so a killed or failed unit leaves none of its outputs half-written; a
failure is recorded in DIR/units/ID.failed.txt (radarpr status lists it) and stops the command
with exit code 1 and the cause. Units of the "evaluate" phase read the values the "values" phase
put into DIR/cache/: run that phase first.)";

struct RunUnitOptions {
  std::string folder;
  std::vector<std::string> ids;
  bool quiet = false;
  std::optional<long long> threads;
};

int run_unit(const RunUnitOptions& options) {
  const PlanFolder folder{options.folder};
  ExperimentConfig config = load_plan_config(folder);
  if (options.threads) config.threads = static_cast<int>(*options.threads);
  const auto units = plan_units(config, UnitCosts::skip);
  for (const auto& id : options.ids) {
    const auto it = std::find_if(units.begin(), units.end(),
                                 [&](const StudyUnit& unit) { return unit.id == id; });
    if (it == units.end()) {
      throw std::runtime_error(
          fmt::format("{}: the plan has no unit {} (radarpr status {} lists "
                      "them)",
                      folder.root.string(), id, folder.root.string()));
    }
    const UnitOutcome outcome = radarpr::run_unit(config, folder, *it, !options.quiet);
    if (outcome.skipped) {
      fmt::print("{}: done already, skipped\n", id);
    } else {
      fmt::print("{}: done ({:.1f} s)\n", id, outcome.seconds);
    }
  }
  return 0;
}

VerbAction define_run_unit(CLI::App& verb) {
  auto options = std::make_shared<RunUnitOptions>();
  verb.add_option("DIR", options->folder, "a plan folder (radarpr plan --out)")->required();
  verb.add_option("ID", options->ids, "unit ids, as plan.json and DIR/slurm/*.units list them")
      ->required();
  verb.add_flag("--quiet", options->quiet, "no progress on stderr");
  add_threads_option(verb, options->threads);
  return [options] { return run_unit(*options); };
}

}  // namespace

Verb run_unit_verb() {
  return {"run-unit", kRunUnitDescription, define_run_unit};
}

}  // namespace radarpr::cli
