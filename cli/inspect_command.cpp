#include <cctype>
#include <set>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "descriptors/descriptor_registry.hpp"
#include "evaluation/config/config_overrides.hpp"
#include "evaluation/config/experiment_config.hpp"
#include "evaluation/dataset_inspection.hpp"

namespace radarpr::cli {

const char* const kInspectHelp =
    R"(usage: radarpr inspect CONFIG [--set key.path=value ...]
       radarpr inspect --dataset TYPE ROOT [key=value ...] [--set key.path=value ...]

Opens every dataset of CONFIG (or the one dataset given on the command line) without extracting
anything, and prints per sequence what was found: layout, A x R, range resolution, time span and
scan rate, where the positions come from (global or local frame), pose coverage and the largest
pose gap, scans left without a pose, invalid azimuth rows in the first scan; then the number of
revisit queries at the protocol's radius and exclusion, and warnings (clocks that do not
overlap, duplicated timestamps, interpolated rows, no revisit). Errors are what would stop
`radarpr run` before any work (including a dataset where no query has an eligible database
frame). Exit code 0 when every dataset can be evaluated, 1 otherwise.

  --dataset TYPE ROOT [key=value ...]
        one sequence as a single session: TYPE is mulran, oxford, boreas, oord, radiate or
        folder; the key=value pairs are its config keys, e.g. sequence=KAIST03 every_nth=2
        (values parsed as JSON when they are JSON, else taken as strings; root, sequence,
        polar, poses, scans, layout and position_frame are always strings)
  --set key.path=value
        change a config value first, as for run: --set protocol.revisit_radius_m=5
        --set datasets.0.query.root=/data/mulran (with --dataset, the dataset is datasets.0)
  --plugin PATH
        load a descriptor plugin first (repeatable), for a CONFIG naming its descriptors; the
        config's "plugins" and $RADARPR_PLUGINS are loaded too
)";

namespace {

// Keys whose values are strings (evaluation/config/real_dataset_config.cpp): `sequence=10` or
// `root=2021` must stay text, not become numbers the config then rejects.
bool is_string_key(const std::string& key) {
  static const std::set<std::string> kStringKeys = {"root",  "sequence", "polar",         "poses",
                                                    "scans", "layout",   "position_frame"};
  return kStringKeys.count(key) > 0;
}

// A one-dataset experiment around the sequence given on the command line, so the config's
// validation, overrides and protocol defaults apply unchanged. The descriptor is a placeholder:
// inspection never extracts.
nlohmann::json dataset_config(const std::vector<std::string>& words) {
  nlohmann::json query{{"type", words.at(0)}, {"root", words.at(1)}};
  for (std::size_t i = 2; i < words.size(); ++i) {
    const auto equals = words[i].find('=');
    if (equals == std::string::npos || equals == 0) {
      throw UsageError(
          fmt::format("expected key=value after --dataset TYPE ROOT, got '{}'", words[i]));
    }
    const std::string key = words[i].substr(0, equals);
    const std::string text = words[i].substr(equals + 1);
    if (is_string_key(key)) {
      query[key] = text;
      continue;
    }
    nlohmann::json value = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
    query[key] = value.is_discarded() ? nlohmann::json(text) : value;
  }
  // Named after its type when that is a valid dataset name (the config rejects others anyway).
  std::string name;
  for (const char c : words[0]) {
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-') name += c;
  }
  return {{"experiment", "inspect"},
          {"datasets", {{{"name", name.empty() ? "dataset" : name}, {"query", query}}}},
          {"descriptors", {DescriptorRegistry::global().all().front()->name}},
          {"protocol", nlohmann::json::object()}};  // so --set protocol.x=... has a parent
}

}  // namespace

int inspect_command(const std::vector<std::string>& args) {
  std::string config_path;
  std::vector<std::string> dataset_words;
  std::vector<std::string> overrides;
  bool dataset_mode = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg == "--help" || arg == "-h") {
      fmt::print("{}", kInspectHelp);
      return 0;
    } else if (arg == "--set") {
      if (i + 1 >= args.size()) throw UsageError("--set needs a value");
      overrides.push_back(args[++i]);
    } else if (arg == "--dataset") {
      dataset_mode = true;
    } else if (arg.starts_with("-")) {
      throw UsageError(fmt::format("unknown option '{}'", arg));
    } else if (dataset_mode) {
      dataset_words.push_back(arg);
    } else if (config_path.empty()) {
      config_path = arg;
    } else {
      throw UsageError(fmt::format("one CONFIG expected, got '{}' and '{}'", config_path, arg));
    }
  }
  if (dataset_mode && !config_path.empty()) {
    throw UsageError("give either CONFIG or --dataset TYPE ROOT, not both");
  }
  if (dataset_mode && dataset_words.size() < 2) throw UsageError("--dataset needs TYPE and ROOT");
  if (!dataset_mode && config_path.empty()) {
    throw UsageError("inspect needs a CONFIG file or --dataset TYPE ROOT");
  }

  ExperimentConfig config;
  if (dataset_mode) {
    nlohmann::json raw = dataset_config(dataset_words);
    try {
      for (const auto& assignment : overrides) apply_config_override(raw, assignment);
      config = parse_experiment_config(raw);
    } catch (const ConfigError& error) {
      throw error.in_file("--dataset");
    }
  } else {
    config = load_experiment_config(config_path, overrides);
  }

  bool fatal = false;
  for (std::size_t d = 0; d < config.datasets.size(); ++d) {
    const DatasetInspection inspection =
        inspect_dataset(config.datasets[d], config.protocol, /*count_revisits=*/true);
    fmt::print("{}{}", d == 0 ? "" : "\n", format_inspection(inspection, config.protocol));
    fatal = fatal || inspection.fatal();
  }
  return fatal ? 1 : 0;
}

}  // namespace radarpr::cli
