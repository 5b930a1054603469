#pragma once

#include <filesystem>
#include <string>

#include "evaluation/config/experiment_config.hpp"
#include "evaluation/experiment_runner.hpp"
#include "evaluation/safe_name.hpp"  // descriptor_folder_name

namespace radarpr {

// Writes a run to `out_dir` (normally results/<experiment>/): summary.json, summary.csv and
// summary.md, per dataset trajectory.csv (every frame's pose), and per dataset x descriptor a
// folder with metrics.json, matches.csv, curve.csv and matching_graph.csv. Every file records the
// radarpr version, the protocol and the descriptor id(s). Everything is written to a sibling
// staging folder first (`<out>.partial.<pid>`; those of dead processes are removed) and moved in
// at the end, so a failed run never leaves a half-written result behind. Only the files radarpr
// writes are replaced (and those of the previous run's dropped datasets and descriptors
// removed): any other file in the folder is kept.
void write_results(const std::filesystem::path& out_dir, const ExperimentConfig& config,
                   const ExperimentRun& run);

// summary.md of a run: the protocol, a table per dataset, Table I and Table II (paper_tables,
// the report's tables without bold).
std::string summary_markdown(const ExperimentConfig& config, const ExperimentRun& run);

// A descriptor's metrics as metrics.json and summary.json record them (undefined ones null).
nlohmann::json metrics_to_json(const Metrics& metrics);

// The absolute, normalised folder a run will be written to ("out/" and "out" are the same).
// Throws std::runtime_error when it must not be written: "/", a regular file, or an existing
// folder that is neither empty nor a radarpr results folder. The
// CLI calls it before the run, so a bad --out costs nothing.
std::filesystem::path resolve_results_folder(const std::filesystem::path& out_dir);

}  // namespace radarpr
