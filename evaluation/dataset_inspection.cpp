#include "evaluation/dataset_inspection.hpp"

#include <cstdio>
#include <exception>
#include <memory>
#include <stdexcept>

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
  const RevisitGroundTruth truth(positions_of(db), protocol.revisit_radius_m);
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
  const auto open = [&](const std::string& role, const SequenceSpec& spec) {
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

  if (count_revisits && !inspection.fatal()) {
    const auto& query = opened[0]->records();
    const auto* database = dataset.database ? &opened[1]->records() : nullptr;
    inspection.revisits = count_revisit_queries(query, database, protocol);
    if (inspection.revisits->queries == 0) {
      add(inspection, Severity::warning,
          fmt::format("no query has an eligible database frame ({} scans, {}): nothing to "
                      "evaluate",
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
    const DatasetInspection inspection =
        inspect_dataset(dataset, config.protocol, /*count_revisits=*/false);
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
