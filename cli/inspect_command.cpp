#include <cctype>
#include <memory>
#include <set>
#include <string>

#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli/common_options.hpp"
#include "cli/verb.hpp"
#include "evaluation/config/experiment_config.hpp"
#include "evaluation/dataset_inspection.hpp"

namespace radarpr::cli {
namespace {

constexpr const char* kInspectDescription =
    R"(what the datasets hold, revisit counts and problems, before a run

Opens every dataset of CONFIG (or the one dataset given with --dataset) without extracting
anything, and prints per sequence what was found: layout, A x R, range resolution, time span and
scan rate, where the positions come from (global or local frame), pose coverage and the largest
pose gap, scans left without a pose, invalid azimuth rows in the first scan; then the number of
revisit queries at the protocol's radius and exclusion, and warnings (clocks that do not overlap,
duplicated timestamps, interpolated rows, no revisit). Errors are what would stop `radarpr run`
before any work (including a dataset where no query has an eligible database frame). Exit code 0
when every dataset can be evaluated, 1 otherwise.)";

struct InspectArguments {
  std::string config;
  std::vector<std::string> dataset;  // TYPE ROOT [KEY=VALUE ...]
  std::vector<std::string> overrides;
};

// Keys whose values are strings (the dataset types' parsers, datasets/real/): `sequence=10` or
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
          fmt::format("expected KEY=VALUE after --dataset TYPE ROOT, got '{}'", words[i]));
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
          // A config names a descriptor; inspect extracts nothing. ReFeree is built into the
          // program, so naming it loads no descriptor module (docs/architecture.md).
          {"descriptors", {"referee"}},
          {"protocol", nlohmann::json::object()}};  // so --set protocol.x=... has a parent
}

int inspect(const InspectArguments& arguments) {
  if (arguments.config.empty() && arguments.dataset.empty()) {
    throw UsageError("inspect needs a CONFIG file or --dataset TYPE ROOT");
  }
  const ExperimentConfig config =
      arguments.dataset.empty() ? load_experiment_config(arguments.config, arguments.overrides)
                                : parse_with_overrides(dataset_config(arguments.dataset),
                                                       arguments.overrides, "--dataset");
  bool fatal = false;
  for (std::size_t d = 0; d < config.datasets.size(); ++d) {
    const DatasetInspection inspection =
        inspect_dataset(config.datasets[d], config.protocol, /*count_revisits=*/true);
    fmt::print("{}{}", d == 0 ? "" : "\n", format_inspection(inspection, config.protocol));
    fatal = fatal || inspection.fatal();
  }
  return fatal ? 1 : 0;
}

// The arguments and options of `radarpr inspect`, and what it does with them.
VerbAction define_inspect(CLI::App& verb) {
  auto arguments = std::make_shared<InspectArguments>();
  auto* config = add_config_argument(verb, arguments->config);
  verb.add_option("--dataset", arguments->dataset,
                  "one sequence as a single session instead of CONFIG: TYPE is mulran, "
                  "oxford, boreas, oord, radiate or folder, KEY=VALUE its config keys, "
                  "e.g. sequence=KAIST03 every_nth=2 (values read as JSON when they are "
                  "JSON, else as strings; root, sequence, polar, poses, scans, layout "
                  "and position_frame are always strings)")
      ->type_name("TYPE ROOT [KEY=VALUE...]")
      ->expected(2, CLI::detail::expected_max_vector_size)
      ->excludes(config);
  add_set_option(verb, arguments->overrides);
  return [arguments] { return inspect(*arguments); };
}

}  // namespace

Verb inspect_verb() {
  return {"inspect", kInspectDescription, define_inspect};
}

}  // namespace radarpr::cli
