#include <filesystem>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "evaluation/report/compare.hpp"

namespace radarpr::cli {

const char* const kCompareHelp =
    R"(usage: radarpr compare RESULTS_DIR... [--out DIR]

Merges results folders written by `radarpr run` (e.g. two parameter choices, or two versions)
into one comparison, from their files alone:
  compare.{md,csv,tex}   one row per run x descriptor, per dataset ROC AUC and F1-max, the best
                         per column in bold; a run is named by its experiment, with the folder
                         name added when two runs share one
  figures/               PR and ROC curves of every dataset all runs have, overlaid
                         (csv + gnuplot script + svg + png per figure)
  compare.json, index.html
Datasets are matched by name; when runs' configs of a same-named dataset differ (summary.json
"config"), the comparison says so on stderr and on the page.

  --out DIR    where to write (default: results/compare). Replaced whole, and only when it is
               empty or an earlier comparison (holds compare.json).
)";

int compare_command(const std::vector<std::string>& args) {
  std::vector<std::filesystem::path> folders;
  std::filesystem::path out = std::filesystem::path("results") / "compare";
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg == "--help" || arg == "-h") {
      fmt::print("{}", kCompareHelp);
      return 0;
    } else if (arg == "--out") {
      if (i + 1 >= args.size()) throw UsageError("--out needs a value");
      out = args[++i];
    } else if (arg.starts_with("-")) {
      throw UsageError(fmt::format("unknown option '{}'", arg));
    } else {
      folders.emplace_back(arg);
    }
  }
  if (folders.empty()) throw UsageError("compare needs at least one RESULTS_DIR");
  const ReportOutcome outcome = write_comparison(folders, out);
  print_report_warnings(outcome);
  fmt::print("comparison: {} ({} runs, {} figures, {} drawn)\n", (out / "index.html").string(),
             folders.size(), outcome.figures, outcome.drawn);
  return 0;
}

}  // namespace radarpr::cli
