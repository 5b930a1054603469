#pragma once

#include <filesystem>
#include <string>

#include "evaluation/experiment_config.hpp"
#include "evaluation/experiment_runner.hpp"

namespace radarpr {

// Writes a run to `out_dir` (normally results/<experiment>/): summary.json, summary.csv and
// summary.md, and per dataset x descriptor a folder with metrics.json, matches.csv, curve.csv and
// matching_graph.csv. Every file records the radarpr version, the protocol and the descriptor
// id(s). Everything is written to a sibling temporary folder first and swapped in at the end,
// so a failed run never leaves a half-written result folder behind.
void write_results(const std::filesystem::path& out_dir, const ExperimentConfig& config,
                   const ExperimentRun& run);

// The folder name of a descriptor id: ':' -> "__", ',' -> '_' (ids hold [a-z0-9_=.:,-]).
std::string descriptor_folder_name(const std::string& id);

}  // namespace radarpr
