#include "evaluation/study/slurm_scripts.hpp"

#include <algorithm>
#include <stdexcept>

#include <sys/stat.h>

#include <fmt/format.h>

namespace radarpr {
namespace {

namespace fs = std::filesystem;

void make_executable(const fs::path& path) {
  fs::permissions(path, fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec,
                  fs::perm_options::add);
}

std::string sbatch_header(const std::string& job_name, const SlurmOptions& options) {
  std::string text = "#!/bin/bash\n";
  text += fmt::format("#SBATCH --job-name={}\n", job_name);
  text += fmt::format("#SBATCH --cpus-per-task={}\n", options.cpus_per_task);
  if (!options.partition.empty())
    text += fmt::format("#SBATCH --partition={}\n", options.partition);
  if (!options.time.empty()) text += fmt::format("#SBATCH --time={}\n", options.time);
  if (!options.mem.empty()) text += fmt::format("#SBATCH --mem={}\n", options.mem);
  if (!options.account.empty()) text += fmt::format("#SBATCH --account={}\n", options.account);
  return text;
}

// The phases that have units, with their units' ids, in plan order.
std::vector<std::pair<std::string, std::string>> phase_lists(const std::vector<StudyUnit>& units) {
  std::vector<std::pair<std::string, std::string>> phases;
  for (UnitPhase phase : {UnitPhase::values, UnitPhase::evaluate}) {
    std::string ids;
    for (const auto& unit : units) {
      if (unit.phase == phase) ids += unit.id + "\n";
    }
    if (!ids.empty()) phases.emplace_back(std::string(to_string(phase)), ids);
  }
  return phases;
}

}  // namespace

std::vector<fs::path> write_local_runner(const PlanFolder& folder,
                                         const std::vector<StudyUnit>& units,
                                         const fs::path& radarpr) {
  const std::string root = fs::absolute(folder.root).lexically_normal().string();
  const std::string program = shell_quote(radarpr.string());
  std::vector<fs::path> written;
  std::string local = fmt::format(
      "#!/bin/sh\n"
      "# Runs the plan on this machine: each phase's units (listed in PHASE.units beside this\n"
      "# script), P at a time (default: the number of processors), then the merge into results/\n"
      "# beside this script. Usage: run_local.sh [P]\n"
      "set -eu\n"
      "parallel=${{1:-$(nproc)}}\n"
      "plan={}\n",
      shell_quote(root));
  for (const auto& [name, ids] : phase_lists(units)) {
    write_file_atomically(folder.root / (name + ".units"), ids);
    written.push_back(folder.root / (name + ".units"));
    local += fmt::format(
        "xargs -P \"$parallel\" -n 1 {} run-unit --quiet \"$plan\" < \"$plan/{}.units\"\n", program,
        name);
  }
  local += fmt::format("{} merge \"$plan\" --out \"$plan/results\"\n", program);
  write_file_atomically(folder.root / "run_local.sh", local);
  make_executable(folder.root / "run_local.sh");
  written.push_back(folder.root / "run_local.sh");
  return written;
}

std::string shell_quote(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) {
    if (c == '\'') {
      quoted += "'\\''";
    } else {
      quoted += c;
    }
  }
  return quoted + "'";
}

void check_slurm_options(const SlurmOptions& options) {
  const std::pair<const char*, const std::string*> values[] = {{"--partition", &options.partition},
                                                               {"--time", &options.time},
                                                               {"--mem", &options.mem},
                                                               {"--account", &options.account}};
  for (const auto& [name, value] : values) {
    for (char c : *value) {
      if (c == '\n' || c == '\r' || c == '\'' || c == '"' || c == ' ' || c == '\t' || c == '#') {
        throw std::invalid_argument(
            fmt::format("{} '{}': an sbatch option value holds no space, quote, '#' or line break",
                        name, *value));
      }
    }
  }
  if (options.cpus_per_task < 1) throw std::invalid_argument("--cpus-per-task must be >= 1");
  if (options.max_parallel < 0) throw std::invalid_argument("--max-parallel must be >= 0");
}

std::vector<fs::path> write_slurm_scripts(const PlanFolder& folder,
                                          const std::vector<StudyUnit>& units,
                                          const SlurmOptions& options) {
  check_slurm_options(options);
  const fs::path slurm = folder.root / "slurm";
  const fs::path logs = folder.root / "logs";
  fs::create_directories(slurm);
  fs::create_directories(logs);
  const std::string root = fs::absolute(folder.root).lexically_normal().string();
  const std::string program = shell_quote(options.radarpr.string());
  std::vector<fs::path> written;
  std::vector<std::string> phases;
  for (const auto& [name, ids] : phase_lists(units)) {
    const auto count = static_cast<std::size_t>(std::count(ids.begin(), ids.end(), '\n'));
    phases.push_back(name);
    std::string script = sbatch_header("radarpr-" + name, options);
    script += fmt::format(
        "#SBATCH --array=0-{}{}\n", count - 1,
        options.max_parallel > 0 ? fmt::format("%{}", options.max_parallel) : std::string());
    // %A: the array's job id, %a: the task's index: one log per task.
    script += fmt::format("#SBATCH --output={}/logs/{}-%A_%a.log\n", root, name);
    script += fmt::format(
        "# One unit per array task: the line SLURM_ARRAY_TASK_ID (from 0) of ../{}.units. "
        "Resubmit\n"
        "# failed tasks alone with: sbatch --array=3,7 {}.sbatch\n"
        "set -euo pipefail\n"
        "unit=$(sed -n \"$((SLURM_ARRAY_TASK_ID + 1))p\" {})\n"
        "exec {} run-unit {} \"$unit\"\n",
        name, name, shell_quote(root + "/" + name + ".units"), program, shell_quote(root));
    write_file_atomically(slurm / (name + ".sbatch"), script);
    written.push_back(slurm / (name + ".sbatch"));
  }
  std::string merge = sbatch_header("radarpr-merge", options);
  merge += fmt::format(
      "#SBATCH --output={}/logs/merge-%j.log\nset -euo pipefail\nexec {} merge {} --out {}\n", root,
      program, shell_quote(root), shell_quote(root + "/results"));
  write_file_atomically(slurm / "merge.sbatch", merge);
  written.push_back(slurm / "merge.sbatch");

  std::string submit =
      "#!/bin/sh\n"
      "# Submits the plan's phases in order, each after the previous one succeeded, then the\n"
      "# merge. Prints the job ids.\n"
      "set -eu\n"
      "cd \"$(dirname \"$0\")\"\n"
      "dependency=\n";
  for (const auto& name : phases) {
    submit += fmt::format(
        "{0}=$(sbatch --parsable ${{dependency:+--dependency=afterok:$dependency}} {0}.sbatch)\n"
        "echo \"{0}: job ${0}\"\n"
        "dependency=${{{0}%%;*}}\n",
        name);
  }
  submit +=
      "merge=$(sbatch --parsable ${dependency:+--dependency=afterok:$dependency} merge.sbatch)\n"
      "echo \"merge: job $merge\"\n";
  write_file_atomically(slurm / "submit.sh", submit);
  written.push_back(slurm / "submit.sh");

  for (const auto& path : written) {
    if (path.extension() == ".sh" || path.extension() == ".sbatch") make_executable(path);
  }
  return written;
}

}  // namespace radarpr
