#include <filesystem>
#include <memory>
#include <optional>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "cli/common_options.hpp"
#include "cli/verb.hpp"
#include "evaluation/report/compare.hpp"

namespace radarpr::cli {
namespace {

constexpr const char* kCompareDescription =
    R"(merge runs into one table and overlaid curves

Merges results folders written by `radarpr run` (e.g. two parameter choices, or two versions)
into one comparison, from their files alone:
  compare.{md,csv,tex}   one row per run x descriptor, per dataset ROC AUC and F1-max, the best
                         per column in bold; a run is named by its experiment, with the folder
                         name added when two runs share one
  figures/               PR and ROC curves of every dataset all runs have, overlaid
                         (csv + gnuplot script + svg + png per figure)
  compare.json, index.html
Datasets are matched by name; when runs' configs of a same-named dataset differ (summary.json
"config"), the comparison says so on stderr and on the page.)";

struct CompareArguments {
  std::vector<std::string> folders;
  std::string out = (std::filesystem::path("results") / "compare").string();
  std::optional<long long> threads;
};

int compare(const CompareArguments& arguments) {
  const std::vector<std::filesystem::path> folders(arguments.folders.begin(),
                                                   arguments.folders.end());
  const std::filesystem::path out(arguments.out);
  const ReportOutcome outcome = write_comparison(folders, out);
  print_report_warnings(outcome);
  fmt::print("comparison: {} ({} runs, {} figures, {} drawn)\n", (out / "index.html").string(),
             folders.size(), outcome.figures, outcome.drawn);
  return 0;
}

// The arguments and options of `radarpr compare`, and what it does with them.
VerbAction define_compare(CLI::App& verb) {
  auto arguments = std::make_shared<CompareArguments>();
  verb.add_option("RESULTS_DIR", arguments->folders,
                  "folders `radarpr run` wrote (each holds summary.json)")
      ->required();
  verb.add_option("--out", arguments->out,
                  "where to write; replaced whole, and only when it is empty or an "
                  "earlier comparison (holds compare.json)")
      ->type_name("DIR")
      ->capture_default_str();
  add_threads_option(verb, arguments->threads);
  return [arguments] { return compare(*arguments); };
}

}  // namespace

Verb compare_verb() {
  return {"compare", kCompareDescription, define_compare};
}

}  // namespace radarpr::cli
