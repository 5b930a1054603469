#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "descriptors/descriptor_registry.hpp"
#include "evaluation/config/config_error.hpp"
#include "evaluation/config/published_tables.hpp"
#include "evaluation/config/report_config.hpp"
#include "evaluation/config/sequence_config.hpp"
#include "evaluation/protocol.hpp"

namespace radarpr {

// Where a dataset comes from when it is one ordered pair of a session matrix.
struct MatrixPair {
  std::size_t matrix = 0;  // index into ExperimentConfig::matrices
  std::size_t query = 0;   // session indices into SessionMatrixConfig::sessions
  std::size_t database = 0;
};

// One dataset of an experiment: a single session (`query` only: the sequence is searched against
// its own past) or a multi session (`query` searched against all of `database`).
struct DatasetConfig {
  std::string name;
  SequenceConfig query;
  std::optional<SequenceConfig> database;
  // Trainable descriptors learn from these scans when protocol.train_on is training_sequence.
  std::optional<SequenceConfig> training;
  // Set when the dataset is one pair of a session matrix (named "<matrix>.<query>.<database>").
  std::optional<MatrixPair> matrix_pair;

  bool multi_session() const { return database.has_value(); }
};

struct MatrixSession {
  std::string name;
  SequenceConfig sequence;
};

// A dataset of kind "session_matrix": sessions of one place and the ordered pairs (query session
// searched against database session) evaluated among them. The config expands it into one
// multi-session dataset per pair, in `pairs` order; this keeps what they share, so that each
// session's values are computed once and a trainable descriptor trained once per database
// session.
struct SessionMatrixConfig {
  std::string name;
  std::vector<MatrixSession> sessions;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;  // (query, database) session indices
  std::optional<SequenceConfig> training;
  std::size_t first_dataset = 0;  // index of its first pair in ExperimentConfig::datasets
};

// The dataset name of a matrix pair (a folder name under results/).
std::string matrix_pair_name(const std::string& matrix, const std::string& query,
                             const std::string& database);

// A validated experiment config (configs/*.json).
struct ExperimentConfig {
  std::string name;
  std::string description;
  std::vector<std::filesystem::path> plugins;  // descriptor plugins, loaded before descriptors
  std::vector<DatasetConfig> datasets;         // a session matrix contributes one per pair
  std::vector<SessionMatrixConfig> matrices;
  std::vector<DescriptorInstance> descriptors;
  Protocol protocol;
  // A paper's published tables to show beside this run's values ("published"; paper-table.md).
  std::optional<PublishedComparisonConfig> published;
  int threads = 0;          // extraction threads; 0 = default_thread_count()
  ReportConfig report;      // how the report draws its figures
  nlohmann::json resolved;  // the config as run (after --set overrides), for result files
};

// Parses and validates a config; errors are ConfigError naming the key path. Loads the plugins
// the config names (into the global registry) before resolving its descriptors; relative plugin
// paths are taken from `config_folder` (empty: the working directory).
ExperimentConfig parse_experiment_config(const nlohmann::json& config,
                                         const std::filesystem::path& config_folder = {});
// Applies the command line's --set overrides to `config` in order, then parses it. A problem an
// override caused (it cannot be applied, or the config refuses the key or value it wrote, or a
// key inside it) is an OverrideError naming that --set; any other ConfigError names `source`
// (the config file, or what stands for it).
ExperimentConfig parse_with_overrides(nlohmann::json config,
                                      const std::vector<std::string>& overrides,
                                      const std::string& source,
                                      const std::filesystem::path& config_folder = {});
// Reads `path` (a JSON file: a folder or an unreadable file is an error naming it), then
// parse_with_overrides.
ExperimentConfig load_experiment_config(const std::filesystem::path& path,
                                        const std::vector<std::string>& overrides = {});

// Parses and validates a config's "protocol" object alone (a preset and the keys that override
// it); errors are ConfigError naming `path`.key.
Protocol parse_protocol_object(const nlohmann::json& protocol,
                               const std::string& path = "protocol");

// The protocol as recorded in every result file.
nlohmann::json protocol_to_json(const Protocol& protocol);

}  // namespace radarpr
