#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evaluation/config/report_config.hpp"
#include "evaluation/results/staging_folder.hpp"  // remove_stale_staging, publish_staged

namespace radarpr {

struct ReportOptions {
  bool include_missed = false;  // draw missed revisits (FN) on the matching graphs
  // The figures' style; unset: the run's config ("report": {"style": ...}), else screen.
  std::optional<FigureStyle> style;
};

struct ReportOutcome {
  std::vector<std::string> warnings;  // gnuplot missing, a script failed: the data is there
  std::size_t figures = 0;            // figures written (csv + gp)
  std::size_t drawn = 0;              // of which svg + png were drawn
};

// Writes the report of a results folder from its files alone (no recomputation): figures/
// (per figure csv, gp, svg, png, pdf), table1.{md,csv,tex}, table2.{md,csv,tex},
// table3.{md,csv,tex} (the AUC-against-size means) and index.html. Everything is read and checked
// first (ResultsError
// "<path>: <what was expected>"), then written to a staging folder and moved into place, so a
// failure writes nothing half-done.
ReportOutcome write_report(const std::filesystem::path& results_folder,
                           const ReportOptions& options);

// The run's "report" settings as its summary.json recorded its config (defaults when it names
// none). Throws ResultsError naming summary.json for a recorded value the config would refuse.
ReportConfig recorded_report_config(const std::filesystem::path& results_folder,
                                    const nlohmann::json& summary);

}  // namespace radarpr
