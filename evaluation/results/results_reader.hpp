#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace radarpr {

// One point of a descriptor's threshold sweep (curve.csv); precision is undefined when nothing
// is accepted.
struct SweepPoint {
  double threshold = 0.0;
  std::optional<double> precision;
  double recall = 0.0;  // = TPR
  double fpr = 0.0;
  std::optional<double> f1;
};

// One matching-graph edge at the F1-max threshold (matching_graph.csv).
struct GraphEdge {
  std::size_t query = 0;
  std::size_t match = 0;
  std::string label;  // "tp", "fp" or "fn"
  double query_x = 0.0, query_y = 0.0, match_x = 0.0, match_y = 0.0;
};

struct TrajectoryPoint {
  std::size_t frame = 0;
  double x = 0.0, y = 0.0;
};

// One dataset x descriptor row of summary.json with its per-descriptor files.
struct ResultRow {
  std::string dataset;
  bool multi_session = false;
  std::string descriptor;  // the id
  std::string label;       // the table name
  int rows = 0, cols = 0;
  std::string element_type;
  double payload_bytes = 0.0, paper_bytes = 0.0;
  bool rotation_invariant = false;
  std::optional<double> roc_auc, f1_max, f1_max_threshold;
  // Retrieval metrics the page shows beside Table I; empty when undefined, or absent from results
  // written before they were recorded.
  std::optional<double> pr_auc, recall_at_1, recall_at_100_precision;
  // From timing.json (or, in results written before it, summary.json); absent in reference
  // results, which keep only what a rerun reproduces.
  std::optional<double> extract_ms_per_scan;
  std::string query_values_from;  // "extracted" or "cache" (then the time is the earlier run's)
  std::vector<SweepPoint> curve;
  std::vector<GraphEdge> graph;
  // matches.csv per query: whether it is a revisit, and the rank of its first correct frame (0:
  // none within the ranked frames).
  std::vector<std::pair<bool, std::size_t>> ranks;
  // How many nearest frames each ranking covers (summary.json "ranked_frames"); unset in results
  // written before it was recorded.
  std::optional<std::size_t> ranked_frames;
};

// The path the matching graph is drawn on: trajectory.csv, or for results written before it
// existed, the frames matches.csv names.
struct DatasetTrajectory {
  std::vector<TrajectoryPoint> query, database;  // database empty in a single session
  bool from_file = false;  // read from trajectory.csv: it bounds the frame indices
};

// A whole results folder, read and checked: what `radarpr report` draws from, with no
// recomputation.
struct RunResults {
  std::filesystem::path folder;
  nlohmann::json summary;  // summary.json as written
  nlohmann::json timing;   // timing.json (run time, machine), or null when there is none
  std::string experiment;
  std::vector<std::string> datasets;            // in run order
  std::vector<std::string> descriptors;         // ids, in config order
  std::vector<ResultRow> rows;                  // dataset-major, as in summary.json
  std::vector<DatasetTrajectory> trajectories;  // one per dataset

  // The row of (dataset, descriptor id), or null.
  const ResultRow* find(const std::string& dataset, const std::string& descriptor) const;
  bool multi_session(const std::string& dataset) const;
};

// summary.json's content alone (no other file read): experiment, datasets, descriptors and rows
// without curves or graphs. `path` names the file in errors. What the writer builds summary.md's
// tables from, so that they are the report's.
RunResults run_summary(const nlohmann::json& summary, const std::filesystem::path& path);

// Reads summary.json, timing.json when present, and every file the report needs. Throws
// ResultsError
// ("<path>: <what was expected>") for a missing, unreadable or malformed file.
RunResults read_run_results(const std::filesystem::path& folder);

}  // namespace radarpr
