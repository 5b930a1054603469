#include <filesystem>
#include <memory>
#include <optional>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "cli/common_options.hpp"
#include "cli/results_report.hpp"
#include "cli/verb.hpp"
#include "evaluation/results/results_writer.hpp"
#include "evaluation/results/summary_table.hpp"
#include "evaluation/study/unit_runner.hpp"

namespace radarpr::cli {
namespace {

constexpr const char* kMergeDescription =
    R"(write the results of a finished plan, as radarpr run would

Reads the outputs of every unit of the plan folder DIR and writes the results folder `radarpr
run CONFIG` writes in one process, with its report: every file is byte-identical to that run's
but timing.json (the measured times) and the figures' images. Refuses, listing them, while units
are not done.)";

struct MergeOptions {
  std::string folder;
  std::string out;
  bool missed = false;
  std::optional<long long> threads;
};

int merge(const MergeOptions& options) {
  const PlanFolder folder{options.folder};
  const ExperimentConfig config = load_plan_config(folder);
  const std::filesystem::path out = options.out.empty()
                                        ? std::filesystem::path("results") / config.name
                                        : std::filesystem::path(options.out);
  resolve_results_folder(out);
  const auto units = plan_units(config, UnitCosts::skip);
  const ExperimentRun run = merge_units(config, folder, units);
  write_results(out, config, run);
  fmt::print("results: {} ({} units, {:.1f} s of unit time)\n", out.string(), units.size(),
             run.seconds);
  return write_report_after_results(out, options.missed);
}

VerbAction define_merge(CLI::App& verb) {
  auto options = std::make_shared<MergeOptions>();
  verb.add_option("DIR", options->folder, "a plan folder whose units are all done")->required();
  verb.add_option("--out", options->out, "where to write, as radarpr run --out")
      ->type_name("DIR")
      ->default_str("results/<experiment>");
  verb.add_flag("--missed", options->missed,
                "also draw the missed revisits on the matching graphs");
  // Merging reads the units' outputs and writes the tables in one pass; the parallel work is
  // the report's figures, one gnuplot process each.
  add_threads_option(verb, options->threads,
                     "how many of the report's figures are drawn at once (one gnuplot process "
                     "each)");
  return [options] { return merge(*options); };
}

}  // namespace

Verb merge_verb() {
  return {"merge", kMergeDescription, define_merge};
}

}  // namespace radarpr::cli
