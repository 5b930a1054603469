#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "evaluation/report/report.hpp"
#include "evaluation/results/results_reader.hpp"

namespace radarpr {

// Each run's name in a comparison: its experiment, with the folder name added when two runs
// share an experiment ("quickstart (qs-a)"), and a number when even that is shared.
std::vector<std::string> comparison_labels(const std::vector<RunResults>& runs);

// Datasets that share a name but not their config entry (summary.json "config"."datasets")
// across runs: one sentence each, for a warning on stderr and on the page.
std::vector<std::string> dataset_mismatches(const std::vector<RunResults>& runs,
                                            const std::vector<std::string>& labels);

// Merges results folders (like evo_res): compare.{md,csv,tex} with one row per run x
// descriptor and per dataset ROC AUC and F1-max (best per column bold), PR and ROC curves of
// every dataset all runs share overlaid in figures/, compare.json and index.html. All runs are
// read and checked first; `out` is replaced whole, and only when it is empty or an earlier
// comparison (it holds compare.json).
ReportOutcome write_comparison(const std::vector<std::filesystem::path>& folders,
                               const std::filesystem::path& out);

}  // namespace radarpr
