#include "evaluation/config/session_matrix_config.hpp"

#include <algorithm>
#include <cctype>
#include <set>

#include <fmt/format.h>

namespace radarpr {
namespace {

// Session names become part of folder names ("<matrix>.<query>.<database>"), so no '.'.
void check_session_name(ConfigReader& reader, const std::string& name) {
  const bool safe = !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
  });
  if (!safe) {
    reader.fail("name",
                fmt::format("'{}' must be a non-empty name of letters, digits, '_', '-'", name));
  }
}

std::size_t session_index(const SessionMatrixConfig& matrix, const std::string& name,
                          const std::string& path) {
  for (std::size_t s = 0; s < matrix.sessions.size(); ++s) {
    if (matrix.sessions[s].name == name) return s;
  }
  std::vector<std::string> names;
  for (const auto& session : matrix.sessions) names.push_back(session.name);
  throw ConfigError(path, fmt::format("'{}' is not a session of matrix '{}' (sessions: {})", name,
                                      matrix.name, fmt::join(names, ", ")));
}

}  // namespace

std::string matrix_pair_name(const std::string& matrix, const std::string& query,
                             const std::string& database) {
  return fmt::format("{}.{}.{}", matrix, query, database);
}

bool is_session_matrix_entry(const nlohmann::json& entry) {
  return entry.is_object() && entry.contains("kind");
}

SessionMatrixConfig parse_session_matrix(ConfigReader reader) {
  const std::string kind = reader.required_string("kind");
  if (kind != "session_matrix") {
    reader.fail("kind", fmt::format("'{}' is not a dataset kind; the one kind is session_matrix "
                                    "(a plain dataset has no \"kind\")",
                                    kind));
  }
  SessionMatrixConfig matrix;
  matrix.name = reader.required_string("name");
  std::set<std::string> names;
  for (const auto& [entry, path] : reader.array("sessions")) {
    ConfigReader session_reader(*entry, path);
    MatrixSession session;
    session.name = session_reader.required_string("name");
    check_session_name(session_reader, session.name);
    if (!names.insert(session.name).second) {
      session_reader.fail("name", fmt::format("session '{}' is listed twice", session.name));
    }
    session.sequence = parse_sequence_config(session_reader.object("sequence"));
    session_reader.finish();
    matrix.sessions.push_back(std::move(session));
  }
  if (matrix.sessions.size() < 2) reader.fail("sessions", "needs at least two sessions");

  const nlohmann::json& pairs = reader.value("pairs");
  if (pairs.is_null() || (pairs.is_string() && pairs.get<std::string>() == "all")) {
    for (std::size_t q = 0; q < matrix.sessions.size(); ++q) {
      for (std::size_t d = 0; d < matrix.sessions.size(); ++d) {
        if (q != d) matrix.pairs.emplace_back(q, d);
      }
    }
  } else if (pairs.is_array()) {
    std::set<std::pair<std::size_t, std::size_t>> seen;
    for (const auto& [entry, path] : reader.array("pairs")) {
      ConfigReader pair_reader(*entry, path);
      const std::string query = pair_reader.required_string("query");
      const std::string database = pair_reader.required_string("database");
      pair_reader.finish();
      const std::size_t q = session_index(matrix, query, pair_reader.path_of("query"));
      const std::size_t d = session_index(matrix, database, pair_reader.path_of("database"));
      if (q == d) {
        throw ConfigError(path, fmt::format("pairs a session with itself ('{}'): a session "
                                            "searched against itself is a single-session dataset",
                                            query));
      }
      if (!seen.emplace(q, d).second) {
        throw ConfigError(path, fmt::format("the pair {} -> {} is listed twice", query, database));
      }
      matrix.pairs.emplace_back(q, d);
    }
    if (matrix.pairs.empty()) reader.fail("pairs", "needs at least one pair");
  } else {
    reader.fail("pairs", fmt::format("expected \"all\" or a list of {{\"query\", \"database\"}} "
                                     "pairs, got {}",
                                     pairs.dump()));
  }
  if (reader.has("training")) matrix.training = parse_sequence_config(reader.object("training"));
  reader.finish();
  return matrix;
}

std::vector<DatasetConfig> expand_session_matrix(const SessionMatrixConfig& matrix,
                                                 std::size_t matrix_index) {
  std::vector<DatasetConfig> datasets;
  for (const auto& [q, d] : matrix.pairs) {
    DatasetConfig dataset;
    dataset.name = matrix_pair_name(matrix.name, matrix.sessions[q].name, matrix.sessions[d].name);
    dataset.query = matrix.sessions[q].sequence;
    dataset.database = matrix.sessions[d].sequence;
    dataset.training = matrix.training;
    dataset.matrix_pair = MatrixPair{matrix_index, q, d};
    datasets.push_back(std::move(dataset));
  }
  return datasets;
}

}  // namespace radarpr
