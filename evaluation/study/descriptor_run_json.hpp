#pragma once

#include <nlohmann/json.hpp>

#include "evaluation/experiment_runner.hpp"

namespace radarpr {

// A DescriptorRun as a unit of a plan hands it to the merge: every field, every double exactly
// (non-finite ones as the strings "inf", "-inf", "nan"), so that the merged results are the
// ones a single process writes.
nlohmann::json descriptor_run_to_json(const DescriptorRun& run);
// Throws std::runtime_error naming the missing or mistyped field.
DescriptorRun descriptor_run_from_json(const nlohmann::json& json);

}  // namespace radarpr
