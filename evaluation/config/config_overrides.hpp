#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace radarpr {

// Applies one "key.path=value" override (the CLI's --set) to a raw config before validation.
// Path segments are object keys or array indices ("datasets.0.sequence.scans=100"); the value is
// parsed as JSON when it is valid JSON (3, true, "x", [1,2]) and taken as a string otherwise
// (kernel=box). The last key may be new, so optional keys can be set; validation then rejects
// typos. Throws ConfigError naming the path when it cannot be applied.
void apply_config_override(nlohmann::json& config, const std::string& assignment);

}  // namespace radarpr
