#include "evaluation/config/experiment_config.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "evaluation/config/config_overrides.hpp"
#include "evaluation/config/config_plugins.hpp"
#include "evaluation/config/config_reader.hpp"
#include "evaluation/config/session_matrix_config.hpp"
#include "evaluation/parallel.hpp"
#include "evaluation/safe_name.hpp"
#include "evaluation/text_escaping.hpp"

namespace radarpr {
namespace {

// Names become folder names under --out (safe_name.hpp): nothing outside it can be named.
void check_file_name(ConfigReader& reader, const std::string& key, const std::string& name) {
  if (const auto reason = unsafe_name_reason(name)) {
    reader.fail(key,
                fmt::format("'{}' {}; {} expected", printable(name), *reason, safe_name_rule()));
  }
}

// The largest exclusion window (s) and revisit radius (m): 31 years and the Earth many times
// over, far beyond any recording, while their squares and nanoseconds stay finite doubles.
constexpr double kMaxProtocolSpan = 1e9;

void check_positive_span(ConfigReader& reader, const std::string& key, double value) {
  if (!(value > 0.0)) reader.fail(key, fmt::format("must be > 0, got {}", value));
  if (!(value <= kMaxProtocolSpan)) {
    reader.fail(key, fmt::format("must be at most {}, got {}", kMaxProtocolSpan, value));
  }
}

DescriptorInstance parse_descriptor(const nlohmann::json& entry, const std::string& path) {
  const auto& registry = DescriptorRegistry::global();
  if (entry.is_string()) {
    try {
      return registry.create_from_id(entry.get<std::string>());
    } catch (const std::invalid_argument& error) {
      throw ConfigError(path, error.what());
    }
  }
  ConfigReader reader(entry, path);
  const std::string name = reader.required_string("name");
  if (!registry.contains(name)) reader.fail("name", registry.unknown_descriptor_message(name));
  const nlohmann::json& parameters = reader.value("params");
  const std::string label = reader.string_or("label", "");
  if (reader.has("label") && label.empty()) reader.fail("label", "must not be empty");
  reader.finish();
  try {
    DescriptorInstance instance = registry.create(name, parameters);
    instance.label = label;
    return instance;
  } catch (const ParameterError& error) {
    throw ConfigError(reader.path_of("params." + error.parameter()), error.what());
  } catch (const std::invalid_argument& error) {
    throw ConfigError(reader.path_of("params"), error.what());
  }
}

Protocol parse_protocol(ConfigReader reader) {
  // The preset first: it sets the defaults every key below may override.
  const std::string preset_name = reader.string_or("preset", "radarpr");
  const auto preset = parse_protocol_preset(preset_name);
  if (!preset) {
    reader.fail("preset", fmt::format("'{}' is not one of: radarpr, mulran_sc_evaluator, "
                                      "referee_code, open_radvlad, vpr_bench",
                                      preset_name));
  }
  Protocol protocol = protocol_preset(*preset);
  const auto exclude = reader.integer_or("exclude_recent_frames", protocol.exclude_recent_frames);
  if (exclude < 1 || exclude > 1'000'000'000) {
    // 0 would let a query match itself.
    reader.fail("exclude_recent_frames",
                fmt::format("must be in [1, 1000000000], got {}", exclude));
  }
  protocol.exclude_recent_frames = static_cast<int>(exclude);
  if (!reader.value("exclude_recent_seconds").is_null()) {
    const double seconds = reader.number_or("exclude_recent_seconds", 0.0);
    check_positive_span(reader, "exclude_recent_seconds", seconds);
    protocol.exclude_recent_seconds = seconds;
  }
  protocol.revisit_radius_m = reader.number_or("revisit_radius_m", protocol.revisit_radius_m);
  check_positive_span(reader, "revisit_radius_m", protocol.revisit_radius_m);
  if (!reader.value("revisit_max_yaw_deg").is_null()) {
    const double degrees = reader.number_or("revisit_max_yaw_deg", 180.0);
    if (!(degrees > 0.0 && degrees <= 180.0)) {
      reader.fail("revisit_max_yaw_deg",
                  fmt::format("must be a number of degrees in (0, 180], got {}", degrees));
    }
    protocol.revisit_max_yaw_deg = degrees;
  }
  const std::string comparison =
      reader.string_or("radius_comparison", std::string(to_string(protocol.radius_comparison)));
  const auto parsed_comparison = parse_radius_comparison(comparison);
  if (!parsed_comparison) {
    reader.fail("radius_comparison",
                fmt::format("'{}' is not one of: inclusive, strict", comparison));
  }
  protocol.radius_comparison = *parsed_comparison;
  const std::string labels = reader.string_or("labels", std::string(to_string(protocol.labels)));
  const auto rule = parse_label_rule(labels);
  if (!rule)
    reader.fail("labels", fmt::format("'{}' is not one of: standard, retrieved_pair", labels));
  protocol.labels = *rule;
  const std::string sweep = reader.string_or("sweep", std::string(to_string(protocol.sweep)));
  const auto parsed_sweep = parse_threshold_sweep(sweep);
  if (!parsed_sweep) {
    reader.fail(
        "sweep",
        fmt::format("'{}' is not one of: exact, linear100, mulran_grid, referee_grid", sweep));
  }
  protocol.sweep = *parsed_sweep;
  const std::string threshold_comparison = reader.string_or(
      "threshold_comparison", std::string(to_string(protocol.threshold_comparison)));
  const auto parsed_threshold_comparison = parse_threshold_comparison(threshold_comparison);
  if (!parsed_threshold_comparison) {
    reader.fail("threshold_comparison",
                fmt::format("'{}' is not one of: inclusive, strict", threshold_comparison));
  }
  protocol.threshold_comparison = *parsed_threshold_comparison;
  const std::string roc_auc = reader.string_or("roc_auc", std::string(to_string(protocol.roc_auc)));
  const auto parsed_roc_auc = parse_roc_auc_variant(roc_auc);
  if (!parsed_roc_auc) {
    reader.fail("roc_auc",
                fmt::format("'{}' is not one of: trapezoid, pooled_pairs, query_ranks", roc_auc));
  }
  protocol.roc_auc = *parsed_roc_auc;
  const std::string denominator =
      reader.string_or("recall_denominator", std::string(to_string(protocol.recall_denominator)));
  const auto parsed_denominator = parse_recall_denominator(denominator);
  if (!parsed_denominator) {
    reader.fail("recall_denominator",
                fmt::format("'{}' is not one of: revisit_queries, all_queries, "
                            "queries_with_positive",
                            denominator));
  }
  protocol.recall_denominator = *parsed_denominator;
  const std::string aggregation =
      reader.string_or("pair_aggregation", std::string(to_string(protocol.pair_aggregation)));
  const auto parsed_aggregation = parse_pair_aggregation(aggregation);
  if (!parsed_aggregation) {
    reader.fail("pair_aggregation", fmt::format("'{}' is not one of: mean, median", aggregation));
  }
  protocol.pair_aggregation = *parsed_aggregation;
  if (reader.has("recall_at_k")) {
    protocol.recall_at_k.clear();
    for (const auto& [element, path] : reader.array("recall_at_k")) {
      if (!element->is_number_integer() || element->get<std::int64_t>() < 1 ||
          element->get<std::int64_t>() > 1000) {
        throw ConfigError(
            path, fmt::format("expected an integer K in [1, 1000], got {}", element->dump()));
      }
      protocol.recall_at_k.push_back(element->get<int>());
    }
    std::sort(protocol.recall_at_k.begin(), protocol.recall_at_k.end());
    protocol.recall_at_k.erase(
        std::unique(protocol.recall_at_k.begin(), protocol.recall_at_k.end()),
        protocol.recall_at_k.end());
  }
  const std::string train_on =
      reader.string_or("train_on", std::string(to_string(protocol.train_on)));
  const auto parsed_train_on = parse_training_source(train_on);
  if (!parsed_train_on) {
    reader.fail("train_on",
                fmt::format("'{}' is not one of: database, training_sequence", train_on));
  }
  protocol.train_on = *parsed_train_on;
  reader.finish();
  return protocol;
}

DatasetConfig parse_dataset(const nlohmann::json& entry, const std::string& path) {
  ConfigReader reader(entry, path);
  DatasetConfig dataset;
  dataset.name = reader.required_string("name");
  check_file_name(reader, "name", dataset.name);
  dataset.query = parse_sequence_config(reader.object("query"));
  if (reader.has("database")) dataset.database = parse_sequence_config(reader.object("database"));
  if (reader.has("training")) dataset.training = parse_sequence_config(reader.object("training"));
  reader.finish();
  return dataset;
}

// A training sequence is used exactly when the protocol says so, so that a config never names
// scans that silently play no part.
void check_training_sequences(const ExperimentConfig& experiment, ConfigReader& reader) {
  const bool named = experiment.protocol.train_on == TrainingSource::training_sequence;
  for (std::size_t i = 0; i < experiment.datasets.size(); ++i) {
    const DatasetConfig& dataset = experiment.datasets[i];
    if (named && !dataset.training) {
      reader.fail(fmt::format("datasets.{}", i),
                  fmt::format("dataset '{}' needs a \"training\" sequence: protocol.train_on is "
                              "training_sequence",
                              dataset.name));
    }
    if (!named && dataset.training) {
      reader.fail(fmt::format("datasets.{}.training", i),
                  "is only used with protocol.train_on = training_sequence (the default trains on "
                  "the database session)");
    }
  }
}

// {"tables": FILE (relative to the config's folder), "datasets": {RUN DATASET: PUBLISHED
// DATASET, ...}}: every run dataset named must exist, every published one be a column of the
// file's Table I.
PublishedComparisonConfig parse_published(ConfigReader reader, const ExperimentConfig& experiment,
                                          const std::filesystem::path& config_folder) {
  PublishedComparisonConfig published;
  const std::filesystem::path file = reader.required_path("tables");
  try {
    published.tables = read_published_tables(file.is_relative() ? config_folder / file : file);
  } catch (const std::runtime_error& error) {
    reader.fail("tables", error.what());
  }
  const nlohmann::json& datasets = reader.value("datasets");
  if (!datasets.is_object() || datasets.empty()) {
    reader.fail("datasets", "expected an object {\"run dataset\": \"published dataset\", ...}");
  }
  for (const auto& item : datasets.items()) {
    // Named variables, not a structured binding: the lambda below captures the name, which
    // clang before 16 refuses for a binding (the sanitizer build compiles with clang 14).
    const std::string& run_name = item.key();
    const nlohmann::json& published_name = item.value();
    const std::string key = "datasets." + run_name;
    const bool known =
        std::any_of(experiment.datasets.begin(), experiment.datasets.end(),
                    [&](const DatasetConfig& dataset) { return dataset.name == run_name; });
    if (!known) reader.fail(key, fmt::format("'{}' is not a dataset of this config", run_name));
    const auto& columns = published.tables.datasets;
    if (!published_name.is_string() ||
        std::find(columns.begin(), columns.end(), published_name.get<std::string>()) ==
            columns.end()) {
      reader.fail(key, fmt::format("expected one of the published datasets ({}), got {}",
                                   fmt::join(columns, ", "), published_name.dump()));
    }
    published.datasets.emplace_back(run_name, published_name.get<std::string>());
  }
  // In the config's dataset order (a JSON object's keys come back sorted).
  const auto position = [&](const std::string& name) {
    return std::find_if(experiment.datasets.begin(), experiment.datasets.end(),
                        [&](const DatasetConfig& dataset) { return dataset.name == name; }) -
           experiment.datasets.begin();
  };
  std::sort(published.datasets.begin(), published.datasets.end(),
            [&](const auto& a, const auto& b) { return position(a.first) < position(b.first); });
  reader.finish();
  return published;
}

}  // namespace

Protocol parse_protocol_object(const nlohmann::json& protocol, const std::string& path) {
  return parse_protocol(ConfigReader(protocol, path));
}

nlohmann::json protocol_to_json(const Protocol& protocol) {
  nlohmann::json json{
      {"exclude_recent_frames", protocol.exclude_recent_frames},
      {"revisit_radius_m", protocol.revisit_radius_m},
      {"labels", to_string(protocol.labels)},
      {"sweep", to_string(protocol.sweep)},
      {"recall_at_k", protocol.recall_at_k},
      {"train_on", to_string(protocol.train_on)},
      {"score", "top-1 descriptor distance; accepted when distance <= threshold"},
  };
  json["exclude_recent_seconds"] = protocol.exclude_recent_seconds
                                       ? nlohmann::json(*protocol.exclude_recent_seconds)
                                       : nlohmann::json(nullptr);
  // Named only when they differ from radarpr's own protocol, so that results of the default
  // protocol stay as they were; under a preset every key is named, so that the record read back
  // is the protocol that ran whatever the preset's defaults.
  const bool preset = protocol.preset != ProtocolPreset::radarpr;
  if (preset) json["preset"] = to_string(protocol.preset);
  if (preset || protocol.radius_comparison != RadiusComparison::inclusive) {
    json["radius_comparison"] = to_string(protocol.radius_comparison);
  }
  if (preset || protocol.threshold_comparison != ThresholdComparison::inclusive) {
    json["threshold_comparison"] = to_string(protocol.threshold_comparison);
  }
  if (protocol.threshold_comparison == ThresholdComparison::strict) {
    json["score"] = "top-1 descriptor distance; accepted when distance < threshold";
  }
  if (protocol.revisit_max_yaw_deg) json["revisit_max_yaw_deg"] = *protocol.revisit_max_yaw_deg;
  if (preset || protocol.roc_auc != RocAucVariant::trapezoid) {
    json["roc_auc"] = to_string(protocol.roc_auc);
  }
  if (preset || protocol.recall_denominator != RecallDenominator::revisit_queries) {
    json["recall_denominator"] = to_string(protocol.recall_denominator);
  }
  if (preset || protocol.pair_aggregation != PairAggregation::mean) {
    json["pair_aggregation"] = to_string(protocol.pair_aggregation);
  }
  return json;
}

ExperimentConfig parse_experiment_config(const nlohmann::json& config,
                                         const std::filesystem::path& config_folder) {
  ConfigReader reader(config, "");
  ExperimentConfig experiment;
  experiment.plugins = load_config_plugins(reader, config_folder);
  experiment.name = reader.required_string("experiment");
  check_file_name(reader, "experiment", experiment.name);
  experiment.description = reader.string_or("description", "");
  const auto threads = reader.integer_or("threads", 0);
  if (threads < 0 || threads > kMaxThreads) {
    reader.fail("threads",
                fmt::format("must be in [0, {}] (0 = the processors available)", kMaxThreads));
  }
  experiment.threads = static_cast<int>(threads);

  std::set<std::string> dataset_names;
  for (const auto& [entry, path] : reader.array("datasets")) {
    std::vector<DatasetConfig> parsed;
    if (is_session_matrix_entry(*entry)) {
      ConfigReader matrix_reader(*entry, path);
      SessionMatrixConfig matrix = parse_session_matrix(matrix_reader);
      check_file_name(matrix_reader, "name", matrix.name);
      if (!dataset_names.insert(matrix.name).second) {
        throw ConfigError(path + ".name",
                          fmt::format("dataset name '{}' is used twice", matrix.name));
      }
      matrix.first_dataset = experiment.datasets.size();
      parsed = expand_session_matrix(matrix, experiment.matrices.size());
      experiment.matrices.push_back(std::move(matrix));
    } else {
      parsed.push_back(parse_dataset(*entry, path));
    }
    for (auto& dataset : parsed) {
      if (!dataset_names.insert(dataset.name).second) {
        throw ConfigError(path + ".name",
                          fmt::format("dataset name '{}' is used twice", dataset.name));
      }
      experiment.datasets.push_back(std::move(dataset));
    }
  }
  if (experiment.datasets.empty()) reader.fail("datasets", "needs at least one dataset");

  std::set<std::string> descriptor_ids;
  std::set<std::string> descriptor_names;
  for (const auto& [entry, path] : reader.array("descriptors")) {
    experiment.descriptors.push_back(parse_descriptor(*entry, path));
    const DescriptorInstance& instance = experiment.descriptors.back();
    // The id names the descriptor's results folder (a plugin's parameters are free text).
    if (const auto reason = unsafe_name_reason(descriptor_folder_name(instance.id))) {
      throw ConfigError(
          path, fmt::format("descriptor '{}' gives the folder name '{}', which {}; "
                            "{} expected",
                            printable(instance.id), printable(descriptor_folder_name(instance.id)),
                            *reason, safe_name_rule()));
    }
    if (!descriptor_ids.insert(instance.id).second) {
      throw ConfigError(path, fmt::format("descriptor '{}' is listed twice", instance.id));
    }
    if (!descriptor_names.insert(instance.display_name()).second) {
      throw ConfigError(path, fmt::format("two descriptors are named '{}' in the tables",
                                          instance.display_name()));
    }
  }
  if (experiment.descriptors.empty()) reader.fail("descriptors", "needs at least one descriptor");

  experiment.protocol =
      reader.has("protocol") ? parse_protocol(reader.object("protocol")) : Protocol{};
  if (reader.has("report")) experiment.report = parse_report_config(reader.object("report"));
  check_training_sequences(experiment, reader);
  // Asked for even when absent, so that an unknown key's error lists it.
  if (!reader.value("published").is_null()) {
    experiment.published = parse_published(reader.object("published"), experiment, config_folder);
  }
  reader.finish();
  experiment.resolved = config;
  return experiment;
}

ExperimentConfig parse_with_overrides(nlohmann::json config,
                                      const std::vector<std::string>& overrides,
                                      const std::string& source,
                                      const std::filesystem::path& config_folder) {
  for (const auto& assignment : overrides) apply_config_override(config, assignment);
  try {
    return parse_experiment_config(config, config_folder);
  } catch (const ConfigError& error) {
    const std::string blamed = override_behind(error.key_path(), overrides);
    if (!blamed.empty()) throw OverrideError(blamed, error.key_path(), error.message());
    throw error.in_file(source);
  }
}

ExperimentConfig load_experiment_config(const std::filesystem::path& path,
                                        const std::vector<std::string>& overrides) {
  std::error_code status_error;  // unreadable: left to the open below
  if (std::filesystem::is_directory(path, status_error)) {
    throw std::runtime_error(
        fmt::format("{}: is a folder, expected a JSON config file (see configs/)", path.string()));
  }
  std::ifstream file(path);
  if (!file)
    throw std::runtime_error(fmt::format("{}: cannot open the config file", path.string()));
  nlohmann::json config;
  try {
    config = nlohmann::json::parse(file, nullptr, /*allow_exceptions=*/true,
                                   /*ignore_comments=*/true);
  } catch (const nlohmann::json::parse_error& error) {
    throw std::runtime_error(fmt::format("{}: not valid JSON ({})", path.string(), error.what()));
  } catch (const nlohmann::json::out_of_range& error) {
    // 1e999: nlohmann reports the overflow as out_of_range.406, not as a parse error.
    throw std::runtime_error(
        fmt::format("{}: a number is beyond the range of a double (±1.8e308) ({})", path.string(),
                    error.what()));
  }
  return parse_with_overrides(std::move(config), overrides, path.string(), path.parent_path());
}

}  // namespace radarpr
