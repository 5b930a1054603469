#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace radarpr {

// The machine and build a run was timed on, for summary.json and the report page: timings only
// compare within one. {cpu_model, logical_cores, operating_system, compiler, optimised,
// date_utc}; no host name (results get committed and shared).
nlohmann::json describe_run_machine();

// Its parts, shared with the benchmarks' fuller description.
std::string cpu_model();         // /proc/cpuinfo's first "model name", or "unknown"
std::string operating_system();  // os-release's PRETTY_NAME, kernel and architecture
std::string compiler();          // the compiler that built radarpr, with its version
std::string utc_now();           // ISO 8601, e.g. 2026-11-21T14:05:00Z

}  // namespace radarpr
