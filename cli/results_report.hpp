#pragma once

#include <filesystem>

namespace radarpr::cli {

// The report of a results folder whose summary files are written (run, merge): draws it, prints
// its warnings and where it is. A report failure is printed, not thrown, since the metrics are
// already safe. Returns the verb's exit code: 0, or 1 when the report failed.
int write_report_after_results(const std::filesystem::path& out, bool include_missed);

}  // namespace radarpr::cli
