#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evaluation/config/config_error.hpp"

namespace radarpr {

// A config problem caused by one of the command line's overrides: the message leads with that
// `--set` instead of the config file, "--set protocol.revisit_radius_m=-5:
// protocol.revisit_radius_m: must be > 0, got -5", because the command line is what to fix.
class OverrideError : public ConfigError {
 public:
  OverrideError(const std::string& assignment, const std::string& key_path,
                const std::string& message)
      : ConfigError(key_path, message, "--set " + assignment) {}
  // A malformed assignment (no '='): nothing to point at inside it.
  OverrideError(const std::string& assignment, const std::string& message)
      : ConfigError(Unkeyed{}, "--set " + assignment, message) {}
};

// Applies one "key.path=value" override (the CLI's --set) to a raw config before validation.
// Path segments are object keys or array indices ("datasets.0.sequence.scans=100"); the value is
// parsed as JSON when it is valid JSON (3, true, "x", [1,2]) and taken as a string otherwise
// (kernel=box); a number must be finite (1e999 is refused). The last key may be new, so optional
// keys can be set; validation then rejects typos. Throws OverrideError naming the assignment and
// the path when it cannot be applied.
void apply_config_override(nlohmann::json& config, const std::string& assignment);

// The override among `overrides` that wrote the value at `key_path` (a ConfigError's path,
// "datasets[0].query.scans"), at a key inside it or at one of its parents: the last one, as it
// won. Empty when none did, so the config file is to blame.
std::string override_behind(const std::string& key_path, const std::vector<std::string>& overrides);

}  // namespace radarpr
