#include <filesystem>
#include <memory>
#include <optional>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "cli/common_options.hpp"
#include "cli/verb.hpp"
#include "datasets/cache_directory.hpp"
#include "evaluation/config/experiment_config.hpp"
#include "evaluation/results/value_export.hpp"

namespace radarpr::cli {
namespace {

constexpr const char* kExportDescription =
    R"(write an experiment's descriptor values, scan times and positions as numpy .npy files

For every dataset in CONFIG and each of its sessions (query, and database in a multi session),
writes DIR/<dataset>/<session>/<descriptor>.npy (N x D float32, one row per scan),
timestamps.npy (N int64, ns) and positions.npy (N x 3 float64: x, y in m, yaw in rad). The values
are those `radarpr run` evaluates: read from the descriptor cache, or extracted and cached. The
`precomputed` descriptor reads them back, e.g. values=DIR/{dataset}/{role}/referee.npy and
timestamps=DIR/{dataset}/{role}/timestamps.npy.)";

struct ExportOptions {
  std::string config;
  std::string out;
  std::vector<std::string> overrides;
  bool quiet = false;
  std::optional<long long> threads;
};

int export_values(const ExportOptions& options) {
  ExperimentConfig config = load_experiment_config(options.config, options.overrides);
  if (options.threads) config.threads = static_cast<int>(*options.threads);
  const auto written = export_descriptor_values(config, options.out, !options.quiet);
  fmt::print("exported {} files to {}\n", written.size(), options.out);
  return 0;
}

VerbAction define_export(CLI::App& verb) {
  auto options = std::make_shared<ExportOptions>();
  add_config_argument(verb, options->config)->required();
  verb.add_option("--out", options->out, "where to write the .npy files (created if needed)")
      ->type_name("DIR")
      ->required();
  add_set_option(verb, options->overrides);
  verb.add_flag("--quiet", options->quiet, "no progress on stderr");
  add_threads_option(verb, options->threads);
  return [options] { return export_values(*options); };
}

}  // namespace

Verb export_verb() {
  return {"export", kExportDescription, define_export};
}

}  // namespace radarpr::cli
