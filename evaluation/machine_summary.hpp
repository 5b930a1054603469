#pragma once

#include <nlohmann/json.hpp>

namespace radarpr {

// The machine and build a run was timed on, for summary.json and the report page: timings only
// compare within one. {cpu_model, logical_cores, operating_system, compiler, optimised,
// date_utc}; no host name (results get committed and shared).
nlohmann::json describe_run_machine();

}  // namespace radarpr
