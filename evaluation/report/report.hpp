#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace radarpr {

struct ReportOptions {
  bool include_missed = false;  // draw missed revisits (FN) on the matching graphs
};

struct ReportOutcome {
  std::vector<std::string> warnings;  // gnuplot missing, a script failed: the data is there
  std::size_t figures = 0;            // figures written (csv + gp)
  std::size_t drawn = 0;              // of which svg + png were drawn
};

// Writes the report of a results folder from its files alone (no recomputation): figures/
// (per figure csv, gp, svg, png), table1.{md,csv,tex}, table2.{md,csv,tex} and index.html.
// Everything is read and checked first (ReportError "<path>: <what was expected>"), then
// written to a staging folder and moved into place, so a failure writes nothing half-done.
ReportOutcome write_report(const std::filesystem::path& results_folder,
                           const ReportOptions& options);

// Moves every entry of `staging` into `target` (replacing entries of the same name) and removes
// `staging`. Used by the report and the comparison.
void publish_staged(const std::filesystem::path& staging, const std::filesystem::path& target);

}  // namespace radarpr
