#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "cli/common_options.hpp"
#include "cli/verb.hpp"
#include "evaluation/report/report.hpp"

namespace radarpr::cli {
namespace {

constexpr const char* kReportDescription =
    R"(redraw a results folder's figures, tables and index.html

Regenerates the figures, tables and page of a results folder that `radarpr run` wrote, from its
files alone (no recomputation). Writes into RESULTS_DIR:
  figures/     per figure NAME.csv (data), NAME.gp (gnuplot script), NAME.svg, NAME.png and
               NAME.pdf (with a gnuplot that has pdfcairo), in the --style:
               PR and ROC curves per dataset (F1-max marked), a matching graph per dataset and
               descriptor, mean ROC AUC per session kind against payload bytes. These are
               overwritten; to restyle, edit a copy of NAME.gp and run gnuplot on it in figures/
               (files of other names there are kept)
  table1.{md,csv,tex}   ROC AUC and F1-max per dataset (the ReFeree paper's Table I)
  table2.{md,csv,tex}   descriptor shape and size (Table II)
  table3.{md,csv,tex}   the AUC-against-size values: mean ROC AUC per descriptor and session
                        kind, and over how many datasets
  table4.{md,csv,tex}   PR-AUC, Recall@1 and R@100P per dataset
  index.html   one page: tables, figures (shown from figures/), protocol, descriptor ids;
               no script, nothing fetched from outside the folder
Every input file is checked first; a missing or corrupt one is an error naming it and nothing is
written. Without gnuplot ($RADARPR_GNUPLOT, else gnuplot on $PATH) the data and scripts are
still written, with a warning.)";

struct ReportArguments {
  std::string folder;
  bool missed = false;
  std::string style;
  std::optional<long long> threads;
};

int report(const ReportArguments& arguments) {
  const auto start = std::chrono::steady_clock::now();
  ReportOptions options;
  options.include_missed = arguments.missed;
  options.style = parse_figure_style(arguments.style);
  const ReportOutcome outcome = write_report(arguments.folder, options);
  print_report_warnings(outcome);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  fmt::print("report: {} ({} figures, {} drawn; {:.1f} s)\n",
             (std::filesystem::path(arguments.folder) / "index.html").string(), outcome.figures,
             outcome.drawn, seconds);
  return 0;
}

// The arguments and options of `radarpr report`, and what it does with them.
VerbAction define_report(CLI::App& verb) {
  auto arguments = std::make_shared<ReportArguments>();
  verb.add_option("RESULTS_DIR", arguments->folder,
                  "a folder `radarpr run` wrote (holds summary.json)")
      ->required();
  verb.add_flag("--missed", arguments->missed,
                "also draw the missed revisits (false negatives) on the matching "
                "graphs");
  add_style_option(verb, arguments->style);
  add_threads_option(verb, arguments->threads);
  return [arguments] { return report(*arguments); };
}

}  // namespace

Verb report_verb() {
  return {"report", kReportDescription, define_report};
}

}  // namespace radarpr::cli
