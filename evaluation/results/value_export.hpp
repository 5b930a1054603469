#pragma once

#include <filesystem>
#include <vector>

#include "evaluation/config/experiment_config.hpp"

namespace radarpr {

// Writes, for every dataset of `config` and each of its sessions (role "query", and "database" in
// a multi session), the descriptor values radarpr evaluates, as numpy files a Python user opens
// with np.load:
//   <out>/<dataset>/<role>/<descriptor folder>.npy  N x D float32, one row per scan (values of
//                                                   rows x cols descriptors flattened row-major)
//   <out>/<dataset>/<role>/timestamps.npy           N int64, the scans' times in ns
//   <out>/<dataset>/<role>/positions.npy            N x 3 float64: x, y (m), yaw (rad)
// The descriptor folder is the one results use (descriptor_folder_name: "referee_r__z_q=3").
// Values come from the descriptor cache where present, else are extracted (and cached), exactly
// as `radarpr run` obtains them; so the files evaluated with the `precomputed` descriptor, with
// values "<out>/{dataset}/{role}/<descriptor folder>.npy" and timestamps
// "<out>/{dataset}/{role}/timestamps.npy", reproduce the run's metrics. Every file is written
// atomically. Returns the files written.
std::vector<std::filesystem::path> export_descriptor_values(const ExperimentConfig& config,
                                                            const std::filesystem::path& out,
                                                            bool show_progress);

}  // namespace radarpr
