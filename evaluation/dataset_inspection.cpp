#include "evaluation/dataset_inspection.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <map>
#include <memory>
#include <stdexcept>
#include <system_error>

#include <fmt/format.h>

#include "evaluation/ground_truth.hpp"

namespace radarpr {
namespace {

std::string describe_exclusion(const Protocol& protocol) {
  return protocol.exclude_recent_seconds
             ? fmt::format("the last {} s excluded", *protocol.exclude_recent_seconds)
             : fmt::format("the {} most recent frames excluded", protocol.exclude_recent_frames);
}

void add(DatasetInspection& inspection, Severity severity, std::string message) {
  inspection.findings.push_back({severity, std::move(message)});
}

// Evaluation needs poses, and across sessions poses in one frame.
void check_positions(DatasetInspection& inspection, const SequenceInspection& sequence) {
  const DatasetReport& report = *sequence.report;
  if (report.position_frame == PositionFrame::none) {
    add(inspection, Severity::fatal,
        fmt::format("{} {} has no poses ({}): it can be used for extraction and benchmarks, "
                    "not evaluated",
                    sequence.role, report.name, report.pose_source));
    return;
  }
  if (report.posed_scans == 0) {
    add(inspection, Severity::fatal,
        fmt::format("{} {} has no scan with a pose ({} scans selected, {} pose samples)",
                    sequence.role, report.name, report.scans_selected, report.pose_samples));
  }
  if (inspection.multi_session && report.position_frame == PositionFrame::local) {
    add(inspection, Severity::fatal,
        fmt::format("multi session needs the query and database positions in one world frame, "
                    "but the {} {} has local positions ({}): each sequence's odometry starts at "
                    "its own origin, so distances between sessions mean nothing. Use global "
                    "positions for both (oxford: \"poses\": \"ins\" or \"gps\"), or evaluate each "
                    "sequence as a single session",
                    sequence.role, report.name, report.pose_source));
  }
}

// A record's source with its folder resolved (symlinks, "..", a trailing slash), so the same
// file reached through two spellings of a root compares equal. Sources that are not files
// (generated scans) compare as written. Folders are resolved once each.
class SourceKeys {
 public:
  std::string key(const std::string& source) {
    const std::filesystem::path path(source);
    const std::filesystem::path parent = path.parent_path();
    auto known = folders_.find(parent.string());
    if (known == folders_.end()) {
      std::error_code error;
      std::filesystem::path resolved;
      if (!parent.empty() && std::filesystem::is_directory(parent, error)) {
        resolved = std::filesystem::weakly_canonical(parent, error);
        if (error) resolved.clear();
      }
      known = folders_.emplace(parent.string(), resolved.string()).first;
    }
    return known->second.empty()
               ? source
               : (std::filesystem::path(known->second) / path.filename()).string();
  }

 private:
  std::map<std::string, std::string> folders_;
};

// A multi-session pair whose sides share scans matches each shared scan with itself at distance
// 0: recall 1.000 that says nothing about place recognition.
void check_shared_scans(DatasetInspection& inspection, const std::vector<ScanRecord>& query,
                        const std::vector<ScanRecord>& database) {
  SourceKeys keys;
  std::vector<std::string> database_keys;
  database_keys.reserve(database.size());
  for (const ScanRecord& record : database) database_keys.push_back(keys.key(record.source));
  std::sort(database_keys.begin(), database_keys.end());
  std::size_t shared = 0;
  const ScanRecord* example = nullptr;
  for (const ScanRecord& record : query) {
    if (std::binary_search(database_keys.begin(), database_keys.end(), keys.key(record.source))) {
      ++shared;
      if (example == nullptr) example = &record;
    }
  }
  if (shared == 0) return;
  add(inspection, Severity::fatal,
      fmt::format("the query and database share {} of the query's {} scans (e.g. {}): a multi-"
                  "session pair must be two different recordings, or every shared scan finds "
                  "itself at distance 0 and the scores mean nothing (1.000). Use two sequences, "
                  "or evaluate one sequence as a single session (no database)",
                  shared, query.size(), example->source));
}

// Sessions of different sensors or settings can be compared, but descriptors that depend on the
// range bins or the metres per bin then compare unlike images: worth a warning.
void check_pair_geometry(DatasetInspection& inspection, const DatasetReport& query,
                         const DatasetReport& database) {
  if (query.type != database.type) {
    add(inspection, Severity::warning,
        fmt::format("the query is a {} sequence and the database a {} one: different sensors or "
                    "processing make descriptors less comparable",
                    query.type, database.type));
  }
  const bool same_resolution =
      std::abs(query.range_resolution_m - database.range_resolution_m) <=
      1e-9 * std::max(query.range_resolution_m, database.range_resolution_m);
  if (query.range_bins != database.range_bins || !same_resolution) {
    add(inspection, Severity::warning,
        fmt::format("the query has {} range bins at {} m/bin and the database {} at {} m/bin: "
                    "descriptors computed per range bin compare different distances",
                    query.range_bins, query.range_resolution_m, database.range_bins,
                    database.range_resolution_m));
  }
}

}  // namespace

bool DatasetInspection::fatal() const {
  for (const Finding& finding : findings) {
    if (finding.severity == Severity::fatal) return true;
  }
  return false;
}

RevisitCount count_revisit_queries(const std::vector<ScanRecord>& query,
                                   const std::vector<ScanRecord>* database,
                                   const Protocol& protocol) {
  const std::vector<ScanRecord>& db = database ? *database : query;
  const std::vector<std::size_t> ends = database ? std::vector<std::size_t>(query.size(), db.size())
                                                 : single_session_eligible_ends(query, protocol);
  const RevisitGroundTruth truth(positions_of(db), protocol.revisit_radius_m,
                                 protocol.radius_comparison, protocol.revisit_max_yaw_deg);
  const std::vector<Position2D> positions = positions_of(query);
  RevisitCount count;
  for (std::size_t q = 0; q < query.size(); ++q) {
    if (ends[q] == 0) continue;
    ++count.queries;
    if (truth.has_revisit(positions[q], ends[q])) ++count.revisits;
  }
  return count;
}

DatasetInspection inspect_dataset(const DatasetConfig& dataset, const Protocol& protocol,
                                  bool count_revisits) {
  DatasetInspection inspection;
  inspection.name = dataset.name;
  inspection.multi_session = dataset.multi_session();

  std::vector<std::unique_ptr<ScanSequence>> opened;
  const auto open = [&](const std::string& role, const SequenceConfig& spec) {
    SequenceInspection sequence{role, std::nullopt};
    try {
      opened.push_back(open_sequence(spec));
      sequence.report = opened.back()->describe();
    } catch (const std::exception& error) {
      opened.push_back(nullptr);
      add(inspection, Severity::fatal, fmt::format("{}: {}", role, error.what()));
    }
    inspection.sequences.push_back(std::move(sequence));
  };
  open("query", dataset.query);
  if (dataset.database) open("database", *dataset.database);
  // Trainable descriptors learn from the training sequence's images only: it needs no poses.
  if (dataset.training) open("training", *dataset.training);

  for (const SequenceInspection& sequence : inspection.sequences) {
    if (!sequence.report) continue;
    for (const std::string& warning : sequence.report->warnings) {
      add(inspection, Severity::warning, fmt::format("{}: {}", sequence.role, warning));
    }
    if (sequence.role != "training") check_positions(inspection, sequence);
  }
  if (dataset.database && opened[0] && opened[1]) {
    check_pair_geometry(inspection, *inspection.sequences[0].report,
                        *inspection.sequences[1].report);
    check_shared_scans(inspection, opened[0]->records(), opened[1]->records());
  }

  if (count_revisits && !inspection.fatal()) {
    const auto& query = opened[0]->records();
    const auto* database = dataset.database ? &opened[1]->records() : nullptr;
    inspection.revisits = count_revisit_queries(query, database, protocol);
    if (inspection.revisits->queries == 0) {
      // The exclusion (or an empty database), not the radius: no query has anything to match.
      add(inspection, Severity::fatal,
          fmt::format("no query has an eligible database frame ({} scans, {}): nothing to "
                      "evaluate; exclude fewer recent frames or use a longer sequence",
                      query.size(), describe_exclusion(protocol)));
    } else if (inspection.revisits->revisits == 0) {
      add(inspection, Severity::warning,
          fmt::format("no revisit: no query has an eligible database frame within {} m; recall, "
                      "F1 and ROC AUC will be undefined",
                      protocol.revisit_radius_m));
    }
  }
  return inspection;
}

std::string format_inspection(const DatasetInspection& inspection, const Protocol& protocol) {
  std::string text = fmt::format(
      "dataset {} ({})\n", inspection.name,
      inspection.multi_session ? "multi session: query against database" : "single session");
  for (const SequenceInspection& sequence : inspection.sequences) {
    text += fmt::format("  {}\n", sequence.role);
    text += sequence.report ? format_report(*sequence.report, "    ")
                            : std::string("    (could not be opened)\n");
  }
  if (inspection.revisits) {
    text +=
        fmt::format("  revisits      {} of {} queries at {} m{}\n", inspection.revisits->revisits,
                    inspection.revisits->queries, protocol.revisit_radius_m,
                    inspection.multi_session ? "" : ", " + describe_exclusion(protocol));
  }
  for (const Finding& finding : inspection.findings) {
    text += fmt::format("  {}: {}\n", finding.severity == Severity::fatal ? "error" : "warning",
                        finding.message);
  }
  return text;
}

void check_datasets_before_run(const ExperimentConfig& config) {
  std::vector<std::string> fatal;
  for (const DatasetConfig& dataset : config.datasets) {
    // Counting revisits is cheap next to extraction, and a run with nothing to evaluate should
    // stop before it.
    const DatasetInspection inspection =
        inspect_dataset(dataset, config.protocol, /*count_revisits=*/true);
    for (const Finding& finding : inspection.findings) {
      if (finding.severity == Severity::fatal) {
        fatal.push_back(fmt::format("dataset '{}': {}", dataset.name, finding.message));
      } else {
        fmt::print(stderr, "warning: dataset '{}': {}\n", dataset.name, finding.message);
      }
    }
  }
  if (!fatal.empty()) {
    throw std::runtime_error(
        fmt::format("{} (radarpr inspect CONFIG shows what was found)", fmt::join(fatal, "; ")));
  }
}

}  // namespace radarpr
