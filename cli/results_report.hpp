#pragma once

#include <filesystem>
#include <string>

namespace radarpr::cli {

// The report of a results folder whose summary files are written (run, merge): draws it, prints
// its warnings and where it is. A report failure is printed, not thrown, since the metrics are
// already safe. `style`: "screen", "paper", or empty for the run's config. Returns the verb's exit
// code: 0, or 1 when the report failed.
int write_report_after_results(const std::filesystem::path& out, bool include_missed,
                               const std::string& style = "");

}  // namespace radarpr::cli
