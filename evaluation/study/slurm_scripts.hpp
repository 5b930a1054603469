#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "evaluation/study/study_plan.hpp"

namespace radarpr {

// What `plan --slurm` passes to sbatch. Empty strings are left out (the cluster's defaults).
struct SlurmOptions {
  std::string partition;
  std::string time;  // --time, e.g. "02:00:00"
  std::string mem;   // --mem, e.g. "8G": the memory of one unit
  std::string account;
  int cpus_per_task = 1;
  int max_parallel = 0;           // the %P of --array=0-K%P; 0 = as many as the cluster gives
  std::filesystem::path radarpr;  // the program the tasks run (absolute)
};

// Throws std::invalid_argument when an option cannot go into an #SBATCH line as it is (a line
// break, a quote, a space), naming the option.
void check_slurm_options(const SlurmOptions& options);

// Writes, per phase with units, <plan>/<phase>.units (one unit id per line, in plan order) and
// <plan>/run_local.sh: the units on this machine with xargs -P, phase after phase, then the
// merge into <plan>/results. Returns the files written.
std::vector<std::filesystem::path> write_local_runner(const PlanFolder& folder,
                                                      const std::vector<StudyUnit>& units,
                                                      const std::filesystem::path& radarpr);

// Writes <plan>/slurm/: per phase with units <phase>.sbatch (a job array over <plan>/<phase>.units:
// a task runs the line of its SLURM_ARRAY_TASK_ID; logs per task in <plan>/logs/),
// merge.sbatch, and submit.sh, which submits the phases in order, each after the previous one
// succeeded (--dependency=afterok), then the merge. Returns the files written.
std::vector<std::filesystem::path> write_slurm_scripts(const PlanFolder& folder,
                                                       const std::vector<StudyUnit>& units,
                                                       const SlurmOptions& options);

// Quotes `text` for a POSIX shell ('...', with ' written as '\'').
std::string shell_quote(const std::string& text);

}  // namespace radarpr
