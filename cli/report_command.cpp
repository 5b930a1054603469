#include <chrono>
#include <filesystem>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "evaluation/report/report.hpp"

namespace radarpr::cli {

const char* const kReportHelp =
    R"(usage: radarpr report RESULTS_DIR [--missed]

Regenerates the figures, tables and page of a results folder that `radarpr run` wrote, from
its files alone (no recomputation). Writes into RESULTS_DIR:
  figures/     per figure NAME.csv (data), NAME.gp (gnuplot script), NAME.svg and NAME.png:
               PR and ROC curves per dataset (F1-max marked), a matching graph per dataset and
               descriptor, mean ROC AUC per session kind against payload bytes. These are
               overwritten; to restyle, edit a copy of NAME.gp and run gnuplot on it in figures/
               (files of other names there are kept)
  table1.{md,csv,tex}   ROC AUC and F1-max per dataset (the seed paper's Table I)
  table2.{md,csv,tex}   descriptor shape and size (Table II)
  table3.{md,csv,tex}   the AUC-against-size values: mean ROC AUC per descriptor and session
                        kind, and over how many datasets
  index.html   one self-contained page: tables, figures, protocol, descriptor ids, machine
Every input file is checked first; a missing or corrupt one is an error naming it and nothing
is written. Without gnuplot ($RADARPR_GNUPLOT, else gnuplot on $PATH) the data and scripts are
still written, with a warning.

  --missed     also draw the missed revisits (false negatives) on the matching graphs
)";

void print_report_warnings(const ReportOutcome& outcome) {
  for (const auto& warning : outcome.warnings)
    fmt::print(stderr, "radarpr: warning: {}\n", warning);
}

int report_command(const std::vector<std::string>& args) {
  std::string folder;
  ReportOptions options;
  for (const auto& arg : args) {
    if (arg == "--help" || arg == "-h") {
      fmt::print("{}", kReportHelp);
      return 0;
    } else if (arg == "--missed") {
      options.include_missed = true;
    } else if (arg.starts_with("-")) {
      throw UsageError(fmt::format("unknown option '{}'", arg));
    } else if (folder.empty()) {
      folder = arg;
    } else {
      throw UsageError(fmt::format("one RESULTS_DIR expected, got '{}' and '{}'", folder, arg));
    }
  }
  if (folder.empty()) throw UsageError("report needs a RESULTS_DIR");
  const auto start = std::chrono::steady_clock::now();
  const ReportOutcome outcome = write_report(folder, options);
  print_report_warnings(outcome);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  fmt::print("report: {} ({} figures, {} drawn; {:.1f} s)\n",
             (std::filesystem::path(folder) / "index.html").string(), outcome.figures,
             outcome.drawn, seconds);
  return 0;
}

}  // namespace radarpr::cli
