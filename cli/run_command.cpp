#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <system_error>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "cli/common_options.hpp"
#include "cli/results_report.hpp"
#include "cli/verb.hpp"
#include "datasets/cache_directory.hpp"
#include "evaluation/config/experiment_config.hpp"
#include "evaluation/experiment_runner.hpp"
#include "evaluation/path_inside.hpp"
#include "evaluation/results/results_writer.hpp"
#include "evaluation/results/summary_table.hpp"

namespace radarpr::cli {
namespace {

constexpr const char* kRunDescription =
    R"(run an experiment: extract, evaluate, write results/<experiment>/ with its report

Runs the experiment in CONFIG: decodes every scan once, extracts every descriptor, retrieves each
query's nearest database frames, scores them against the revisit ground truth and prints a table
per dataset. Writes summary.{json,csv,md} and, per dataset and descriptor, metrics.json,
matches.csv, curve.csv and matching_graph.csv; then the report (see radarpr report --help):
figures/, table1/table2/table3/table4.{md,csv,tex} and index.html. The summary files come first: a
report problem never loses the metrics, and a missing gnuplot is a warning (the figures' data and
scripts are still written).)";

struct RunOptions {
  std::string config;
  std::string out;
  std::vector<std::string> overrides;
  bool quiet = false;
  std::string cache_dir;
  bool no_cache = false;
  bool missed = false;
  std::string style;
  std::optional<long long> threads;
};

int run(const RunOptions& options) {
  if (!options.cache_dir.empty()) override_cache_directory(options.cache_dir);
  if (options.no_cache) override_cache_directory("off");
  ExperimentConfig config = load_experiment_config(options.config, options.overrides);
  if (options.threads) config.threads = static_cast<int>(*options.threads);
  const std::filesystem::path out = options.out.empty()
                                        ? std::filesystem::path("results") / config.name
                                        : std::filesystem::path(options.out);
  // A bad --out is refused before the run, not after it: a folder that is not results, or one
  // holding the descriptor cache (the run would fill it, then refuse to write its results there).
  const std::filesystem::path target = resolve_results_folder(out);
  if (const auto cache = cache_directory(); cache && is_inside(*cache, target)) {
    throw std::runtime_error(fmt::format(
        "the descriptor cache {} is inside the results folder {}: choose a --cache-dir (or "
        "RADARPR_CACHE_DIR) outside --out",
        cache->string(), out.string()));
  }
  const ExperimentRun run = run_experiment(config, !options.quiet);
  write_results(out, config, run);

  for (const auto& dataset : run.datasets) {
    fmt::print("\n{} ({})\n\n{}", dataset.name, describe_session(dataset, config.protocol),
               summary_table(dataset, config.protocol));
  }
  fmt::print("\nresults: {} ({:.1f} s)\n", out.string(), run.seconds);
  // After the summary files: the metrics are safe whatever happens here.
  return write_report_after_results(out, options.missed, options.style);
}

// The arguments and options of `radarpr run`, and what it does with them.
VerbAction define_run(CLI::App& verb) {
  auto options = std::make_shared<RunOptions>();
  add_config_argument(verb, options->config)->required();
  verb.add_option("--out", options->out,
                  "where to write: a results folder or an empty one; only the files the run "
                  "writes are replaced, other files there are kept")
      ->type_name("DIR")
      ->default_str("results/<experiment>");
  add_set_option(verb, options->overrides);
  verb.add_flag("--quiet", options->quiet, "no progress on stderr");
  auto* cache_dir = verb.add_option("--cache-dir", options->cache_dir,
                                    "keep what can be recomputed here: the extracted descriptor "
                                    "values, so that a re-run after a protocol change decodes no "
                                    "scan")
                        ->type_name("DIR")
                        ->default_str(
                            "$RADARPR_CACHE_DIR, else $XDG_CACHE_HOME/radarpr, else "
                            "~/.cache/radarpr");
  verb.add_flag("--no-cache", options->no_cache,
                "neither read nor write a cache (RADARPR_CACHE_DIR=off does the same)")
      ->excludes(cache_dir);
  verb.add_flag("--missed", options->missed,
                "also draw the missed revisits on the matching graphs");
  add_style_option(verb, options->style);
  add_threads_option(verb, options->threads);
  return [options] { return run(*options); };
}

}  // namespace

Verb run_verb() {
  return {"run", kRunDescription, define_run};
}

}  // namespace radarpr::cli
