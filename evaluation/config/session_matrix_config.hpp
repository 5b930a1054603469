#pragma once

#include <nlohmann/json.hpp>

#include "evaluation/config/config_reader.hpp"
#include "evaluation/config/experiment_config.hpp"

namespace radarpr {

// Whether a "datasets" entry is a session matrix ({"kind": "session_matrix", ...}).
bool is_session_matrix_entry(const nlohmann::json& entry);

// Reads {"kind": "session_matrix", "name", "sessions": [{"name", "sequence": {...}}, ...],
// "pairs": "all" | [{"query": NAME, "database": NAME}, ...], "training": {...}}. "all" is every
// ordered pair of distinct sessions, query-major in session order. Throws ConfigError naming the
// key path (an unknown session, a pair of a session with itself, a pair listed twice, ...).
SessionMatrixConfig parse_session_matrix(ConfigReader reader);

// The matrix's pairs as ordinary multi-session datasets, in pair order.
std::vector<DatasetConfig> expand_session_matrix(const SessionMatrixConfig& matrix,
                                                 std::size_t matrix_index);

}  // namespace radarpr
