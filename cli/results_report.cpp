#include "cli/results_report.hpp"

#include <exception>

#include <fmt/format.h>

#include "cli/common_options.hpp"
#include "evaluation/report/report.hpp"

namespace radarpr::cli {

int write_report_after_results(const std::filesystem::path& out, bool include_missed,
                               const std::string& style) {
  try {
    ReportOptions report_options;
    report_options.include_missed = include_missed;
    report_options.style = parse_figure_style(style);
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
