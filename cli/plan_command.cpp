#include <filesystem>
#include <memory>
#include <optional>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "cli/common_options.hpp"
#include "cli/number_options.hpp"
#include "cli/verb.hpp"
#include "evaluation/config/experiment_config.hpp"
#include "evaluation/study/slurm_scripts.hpp"
#include "evaluation/study/unit_runner.hpp"

namespace radarpr::cli {
namespace {

constexpr const char* kPlanDescription =
    R"(cut an experiment into units of work for a cluster (see docs/cluster.md)

Writes the plan folder DIR: config.json (CONFIG as resolved, --set applied), plan.json (the
manifest: per phase its units, each with a stable id, its inputs and outputs and an estimated
cost), units/ (their outputs) and cache/ (the descriptor values they share). Phase "values":
per session of a session matrix and descriptor, its descriptor values (a trainable descriptor:
one unit per database session, which trains once and encodes every session paired with it).
Phase "evaluate": per pair and descriptor, and per ordinary dataset. Also PHASE.units (the ids,
one per line) and run_local.sh (the units on this machine with xargs -P, then the merge). Prints
the number of units and the estimated CPU time; nothing is computed. Then run the units (radarpr
run-unit, the scripts --slurm writes, or DIR/run_local.sh), check them (radarpr status) and write
the results (radarpr merge): the same files `radarpr run CONFIG` writes in one process.)";

struct PlanOptions {
  std::string config;
  std::string out;
  std::vector<std::string> overrides;
  bool slurm = false;
  SlurmOptions slurm_options;
  std::optional<long long> cpus_per_task;
  std::optional<long long> max_parallel;
};

int plan(PlanOptions& options) {
  const ExperimentConfig config = load_experiment_config(options.config, options.overrides);
  const PlanFolder folder{std::filesystem::absolute(options.out).lexically_normal()};
  if (options.cpus_per_task) {
    options.slurm_options.cpus_per_task = static_cast<int>(*options.cpus_per_task);
  }
  if (options.max_parallel) {
    options.slurm_options.max_parallel = static_cast<int>(*options.max_parallel);
  }
  options.slurm_options.radarpr = std::filesystem::read_symlink("/proc/self/exe");
  if (options.slurm) check_slurm_options(options.slurm_options);
  // Relative plugin paths of the config resolve against its folder, for every unit.
  const auto units = write_plan(
      config, std::filesystem::absolute(options.config).lexically_normal().parent_path(), folder);
  std::size_t values = 0;
  double seconds = 0.0;
  for (const auto& unit : units) {
    if (unit.phase == UnitPhase::values) ++values;
    seconds += unit.estimated_cpu_seconds;
  }
  fmt::print(
      "plan: {} ({} units: {} values, {} evaluate; estimated CPU time {:.1f} h = {:.0f} s)\n",
      folder.manifest().string(), units.size(), values, units.size() - values, seconds / 3600.0,
      seconds);
  write_local_runner(folder, units, options.slurm_options.radarpr);
  fmt::print("local: sh {} [P] runs the units P at a time, then the merge\n",
             (folder.root / "run_local.sh").string());
  if (options.slurm) {
    write_slurm_scripts(folder, units, options.slurm_options);
    fmt::print("slurm: {} (submit with sh {})\n", (folder.root / "slurm").string(),
               (folder.root / "slurm" / "submit.sh").string());
  }
  return 0;
}

VerbAction define_plan(CLI::App& verb) {
  auto options = std::make_shared<PlanOptions>();
  add_config_argument(verb, options->config)->required();
  verb.add_option("--out", options->out, "the plan folder (on a filesystem every node sees)")
      ->type_name("DIR")
      ->required();
  add_set_option(verb, options->overrides);
  verb.add_flag("--slurm", options->slurm,
                "also write DIR/slurm/: an sbatch job array per phase, merge.sbatch, submit.sh");
  verb.add_option("--partition", options->slurm_options.partition, "sbatch --partition")
      ->type_name("NAME");
  verb.add_option("--time", options->slurm_options.time, "sbatch --time of one unit")
      ->type_name("TIME");
  verb.add_option("--mem", options->slurm_options.mem, "sbatch --mem of one unit")
      ->type_name("SIZE");
  verb.add_option("--account", options->slurm_options.account, "sbatch --account")
      ->type_name("NAME");
  add_whole_number_option(verb, "--cpus-per-task", options->cpus_per_task, {1, 1024}, "N",
                          "sbatch --cpus-per-task: the threads of one unit")
      ->default_str("1");
  add_whole_number_option(verb, "--max-parallel", options->max_parallel, {0, 1000000}, "P",
                          "at most P tasks of an array at once (--array=0-K%P; 0: no limit)")
      ->default_str("0");
  return [options] { return plan(*options); };
}

}  // namespace

Verb plan_verb() {
  return {"plan", kPlanDescription, define_plan};
}

}  // namespace radarpr::cli
