#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "datasets/dataset_report.hpp"
#include "datasets/scan_sequence.hpp"
#include "evaluation/config/experiment_config.hpp"
#include "evaluation/protocol.hpp"

namespace radarpr {

// Queries with an eligible database frame, and those among them that are revisits, at the
// protocol's radius and exclusion: the same ground truth the evaluation uses.
struct RevisitCount {
  std::size_t queries = 0;
  std::size_t revisits = 0;
};

// `database` = nullptr: single session (the query sequence against its own past).
RevisitCount count_revisit_queries(const std::vector<ScanRecord>& query,
                                   const std::vector<ScanRecord>* database,
                                   const Protocol& protocol);

enum class Severity {
  warning,  // results may mislead; the run goes on
  fatal,    // the dataset cannot be evaluated; a run stops before any extraction
};

struct Finding {
  Severity severity = Severity::warning;
  std::string message;
};

struct SequenceInspection {
  std::string role;                     // "query", "database" or "training"
  std::optional<DatasetReport> report;  // nullopt when the sequence could not be opened
};

// What `radarpr inspect` prints for one dataset of a config.
struct DatasetInspection {
  std::string name;
  bool multi_session = false;
  std::vector<SequenceInspection> sequences;
  std::optional<RevisitCount> revisits;  // counted when asked and nothing is fatal
  std::vector<Finding> findings;

  bool fatal() const;
};

// Opens the dataset's sequences (query, database, training) and checks them for evaluation:
// clocks, pose coverage, duplicated stamps and invalid rows (from each loader's report),
// evaluated sequences without poses (a training sequence needs none), multi-session positions
// in a local frame, a multi-session pair sharing scan files (fatal) or differing in dataset
// type, range bins or resolution (warnings), and (when `count_revisits`) the number of revisit
// queries: none with an eligible database frame is fatal, none a revisit a warning. Data problems
// become findings, never exceptions: a sequence that cannot be opened is a fatal finding
// carrying the loader's message, which names the file.
DatasetInspection inspect_dataset(const DatasetConfig& dataset, const Protocol& protocol,
                                  bool count_revisits);

// The inspection as text: each sequence's report, the revisit count, warnings and errors.
std::string format_inspection(const DatasetInspection& inspection, const Protocol& protocol);

// The checks `radarpr run` makes before any work: inspects every dataset, revisits included,
// prints the warnings to stderr and throws std::runtime_error with every fatal finding, so a
// broken dataset (or one with nothing to evaluate) never yields results.
void check_datasets_before_run(const ExperimentConfig& config);

}  // namespace radarpr
