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
// (per figure csv, gp, svg, png), table1.{md,csv,tex}, table2.{md,csv,tex}, table3.{md,csv,tex}
// (the AUC-against-size means) and index.html. Everything is read and checked first (ResultsError
// "<path>: <what was expected>"), then written to a staging folder and moved into place, so a
// failure writes nothing half-done.
ReportOutcome write_report(const std::filesystem::path& results_folder,
                           const ReportOptions& options);

// Removes the staging folders `<folder>/<prefix><pid>` that a report or comparison killed
// midway left behind: those whose process no longer exists.
void remove_stale_staging(const std::filesystem::path& folder, const std::string& prefix);

// Moves every entry of `staging` into `target` (replacing entries of the same name; folders
// merged, so other files in them stay) and removes `staging`. Used by the report.
void publish_staged(const std::filesystem::path& staging, const std::filesystem::path& target);

}  // namespace radarpr
