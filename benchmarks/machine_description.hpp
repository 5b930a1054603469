#pragma once

#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace radarpr::bench {

// The machine and build a benchmark run was measured on: numbers only compare within one.
struct MachineDescription {
  std::string cpu_model;  // /proc/cpuinfo's "model name", or "unknown"
  int logical_cores = 0;
  double memory_gib = 0.0;  // MemTotal; 0 when unknown
  std::string operating_system;
  std::string compiler;
  std::string build_type;  // CMAKE_BUILD_TYPE of the benchmark code
  bool optimised = false;  // compiled with NDEBUG and optimisation (a Release-like build)
  std::string radarpr_version;
  std::string date_utc;              // ISO 8601, when the run started
  std::vector<double> load_average;  // 1, 5, 15 minutes at the start (shared machines)
};

// Whether the benchmark code (and so radarpr, built alike) was compiled with NDEBUG and
// optimisation: a Release-like build.
bool optimised_build();

// Describes this process's machine and build.
MachineDescription describe_this_machine();

nlohmann::json to_json(const MachineDescription& machine);

}  // namespace radarpr::bench
