#include <filesystem>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "datasets/cache_directory.hpp"
#include "evaluation/config/experiment_config.hpp"
#include "evaluation/experiment_runner.hpp"
#include "evaluation/report/report.hpp"
#include "evaluation/results/results_writer.hpp"
#include "evaluation/results/summary_table.hpp"

namespace radarpr::cli {

const char* const kRunHelp =
    R"(usage: radarpr run CONFIG [--out DIR] [--set key.path=value ...] [--quiet]
                   [--cache-dir DIR | --no-cache] [--missed]

Runs the experiment in CONFIG (a JSON file, see configs/): decodes every scan once, extracts
every descriptor, retrieves each query's nearest database frames, scores them against the
revisit ground truth and prints a table per dataset. Writes summary.{json,csv,md} and, per
dataset and descriptor, metrics.json, matches.csv, curve.csv and matching_graph.csv; then the
report (see radarpr report --help): figures/, table1/table2.{md,csv,tex} and index.html. The
summary files come first: a report problem never loses the metrics, and a missing gnuplot is a
warning (the figures' data and scripts are still written).

  --out DIR              where to write (default: results/<experiment>); replaced atomically
  --set key.path=value   change any config value before validation, e.g.
                         --set protocol.revisit_radius_m=5 --set datasets.0.query.scans=200
                         --set descriptors.1.params.z_q=3   (repeatable; value parsed as JSON
                         when it is JSON, else taken as a string)
  --quiet                no progress on stderr
  --cache-dir DIR        keep what can be recomputed here (default: $RADARPR_CACHE_DIR, else
                         $XDG_CACHE_HOME/radarpr, else ~/.cache/radarpr): extracted descriptor
                         values, so that a re-run after a protocol change decodes no scan
  --no-cache             neither read nor write a cache (RADARPR_CACHE_DIR=off does the same)
  --missed               also draw missed revisits on the matching graphs
  --plugin PATH          load a descriptor plugin (a shared library) first (repeatable); the
                         config's "plugins" and $RADARPR_PLUGINS are loaded too
)";

int run_command(const std::vector<std::string>& args) {
  std::string config_path;
  std::string out_dir;
  std::vector<std::string> overrides;
  bool quiet = false;
  ReportOptions report_options;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    auto value = [&](const char* flag) -> const std::string& {
      if (i + 1 >= args.size()) throw UsageError(fmt::format("{} needs a value", flag));
      return args[++i];
    };
    if (arg == "--help" || arg == "-h") {
      fmt::print("{}", kRunHelp);
      return 0;
    } else if (arg == "--out") {
      out_dir = value("--out");
    } else if (arg == "--set") {
      overrides.push_back(value("--set"));
    } else if (arg == "--missed") {
      report_options.include_missed = true;
    } else if (arg == "--quiet") {
      quiet = true;
    } else if (arg == "--cache-dir") {
      override_cache_directory(std::filesystem::path(value("--cache-dir")));
    } else if (arg == "--no-cache") {
      override_cache_directory(std::filesystem::path("off"));
    } else if (arg.starts_with("-")) {
      throw UsageError(fmt::format("unknown option '{}'", arg));
    } else if (config_path.empty()) {
      config_path = arg;
    } else {
      throw UsageError(fmt::format("one CONFIG expected, got '{}' and '{}'", config_path, arg));
    }
  }
  if (config_path.empty()) throw UsageError("run needs a CONFIG file");

  const ExperimentConfig config = load_experiment_config(config_path, overrides);
  const std::filesystem::path out = out_dir.empty() ? std::filesystem::path("results") / config.name
                                                    : std::filesystem::path(out_dir);
  resolve_results_folder(out);  // refuse a bad --out before the run, not after it
  const ExperimentRun run = run_experiment(config, !quiet);
  write_results(out, config, run);

  for (const auto& dataset : run.datasets) {
    fmt::print("\n{} ({})\n\n{}", dataset.name, describe_session(dataset, config.protocol),
               summary_table(dataset, config.protocol));
  }
  fmt::print("\nresults: {} ({:.1f} s)\n", out.string(), run.seconds);
  // After the summary files: the metrics are safe whatever happens here.
  try {
    const ReportOutcome outcome = write_report(out, report_options);
    print_report_warnings(outcome);
    fmt::print("report: {} ({} figures, {} drawn)\n", (out / "index.html").string(),
               outcome.figures, outcome.drawn);
  } catch (const std::exception& error) {
    fmt::print(stderr, "radarpr: error: the report failed, the results are written: {}\n",
               error.what());
    return 1;
  }
  return 0;
}

}  // namespace radarpr::cli
