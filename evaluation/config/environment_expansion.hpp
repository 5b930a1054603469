#pragma once

#include <string>

namespace radarpr {

// Replaces every "${NAME}" in `text` by the environment variable NAME, so configs can say
// "root": "${RADARPR_MULRAN_ROOT}" and work on every machine. Throws ConfigError at `key_path`
// for an unset or empty variable, saying how to set it and the --set alternative, and for an
// unterminated "${". A '$' not followed by '{' is kept as it is.
std::string expand_environment_variables(const std::string& text, const std::string& key_path);

// The --set spelling of a key path: "datasets[0].query.root" -> "datasets.0.query.root".
std::string override_path(const std::string& key_path);

}  // namespace radarpr
