#include "evaluation/results/results_writer.hpp"

#include <fstream>
#include <iterator>
#include <stdexcept>

#include <unistd.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "evaluation/machine_summary.hpp"
#include "evaluation/results/csv_file.hpp"
#include "evaluation/results/paper_tables.hpp"
#include "evaluation/results/published_comparison.hpp"
#include "evaluation/results/results_reader.hpp"
#include "evaluation/results/session_matrix_tables.hpp"
#include "evaluation/results/staging_folder.hpp"
#include "evaluation/results/summary_table.hpp"
#include "evaluation/text_escaping.hpp"
#include "evaluation/version.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

nlohmann::json optional_json(const std::optional<double>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

std::string optional_csv(const std::optional<double>& value) {
  return value ? fmt::format("{}", *value) : "";
}

void write_file(const fs::path& path, const std::string& content) {
  std::ofstream file(path, std::ios::binary);
  file << content;
  file.close();
  if (!file) throw std::runtime_error(fmt::format("{}: cannot write the file", path.string()));
}

double seconds_of(std::int64_t timestamp_ns) {
  return static_cast<double>(timestamp_ns) * 1e-9;
}

nlohmann::json metrics_json(const Metrics& m) {
  nlohmann::json recall_at_k = nlohmann::json::object();
  for (const auto& [k, value] : m.recall_at_k)
    recall_at_k[std::to_string(k)] = optional_json(value);
  nlohmann::json recall_all_queries = nlohmann::json::object();
  for (const auto& [k, value] : m.recall_at_k_all_queries)
    recall_all_queries[std::to_string(k)] = optional_json(value);
  nlohmann::json recall_with_positive = nlohmann::json::object();
  for (const auto& [k, value] : m.recall_at_k_with_positive)
    recall_with_positive[std::to_string(k)] = optional_json(value);
  return {
      {"queries", m.queries},
      {"revisits", m.revisits},
      {"correct_top1", m.correct_top1},
      {"roc_auc", optional_json(m.roc_auc)},
      {"f1_max", optional_json(m.f1_max)},
      {"f1_max_threshold", optional_json(m.f1_max_threshold)},
      {"pr_auc_trapezoid", optional_json(m.pr_auc)},
      {"average_precision", optional_json(m.average_precision)},
      {"pr_auc_mulran", optional_json(m.pr_auc_mulran)},
      {"pr_auc_vpr_bench", optional_json(m.pr_auc_vpr_bench)},
      {"recall_at_1", optional_json(m.recall_at_1)},
      {"recall_at_k", recall_at_k},
      {"recall_at_1_all_queries", optional_json(m.recall_at_1_all_queries)},
      {"recall_at_k_all_queries", recall_all_queries},
      {"recall_at_1_with_positive", optional_json(m.recall_at_1_with_positive)},
      {"recall_at_k_with_positive", recall_with_positive},
      {"recall_at_100_precision", optional_json(m.recall_at_100_precision)},
      {"extended_precision", optional_json(m.extended_precision)},
      {"extended_precision_vpr_bench", optional_json(m.extended_precision_vpr_bench)},
  };
}

// The run's deterministic facts only: a rerun writes the same row byte for byte, so that the
// committed reference results hold summary.json too. Times and cache state go to timing.json.
nlohmann::json summary_row(const DatasetRun& dataset, const DescriptorRun& run) {
  nlohmann::json row{
      {"dataset", dataset.name},
      {"session", dataset.multi_session ? "multi" : "single"},
      {"query_sequence", dataset.query_sequence},
      {"database_sequence", dataset.database_sequence},
      {"descriptor", run.id},
      {"label", run.label},
      {"shape", {run.rows, run.cols}},
      {"element_type", kDescriptorElementType},
      {"payload_bytes", run.payload_bytes},
      {"paper_bytes", run.paper_bytes},
      {"rotation_invariant", run.rotation_invariant},
  };
  row["training"] = run.training ? nlohmann::json{{"sequence", run.training->sequence},
                                                  {"scans_in_sequence", run.training->scans},
                                                  {"scans_loaded", run.training->loaded}}
                                 : nlohmann::json(nullptr);
  // Only descriptors with a learnt codebook carry the key.
  if (run.codebook) {
    const auto file_or_null = [](const std::string& file) {
      return file.empty() ? nlohmann::json(nullptr) : nlohmann::json(file);
    };
    row["codebook"] = {{"sha256", run.codebook->sha256},
                       {"loaded_from", file_or_null(run.codebook->loaded_from)},
                       {"saved_to", file_or_null(run.codebook->saved_to)}};
  }
  row.update(metrics_json(run.evaluation.metrics));
  return row;
}

// What varies from run to run: the extraction time and where the values came from. "cache":
// read from the descriptor cache, and extract_ms_per_scan (and the training time) are those of
// the run that computed them.
nlohmann::json timing_row(const DatasetRun& dataset, const DescriptorRun& run) {
  nlohmann::json row{{"dataset", dataset.name},
                     {"descriptor", run.id},
                     {"extract_ms_per_scan", run.mean_extract_ms}};
  row["values_from"] = {{"query", run.query_values_cached ? "cache" : "extracted"}};
  if (dataset.multi_session) {
    row["values_from"]["database"] = run.database_values_cached ? "cache" : "extracted";
  }
  row["training"] = run.training ? nlohmann::json{{"seconds", run.training->seconds},
                                                  {"from_cache", run.training->from_cache}}
                                 : nlohmann::json(nullptr);
  return row;
}

// The CSV files are plain: header first, no comment lines. What they describe is in metrics.json
// (per descriptor) and summary.json beside them.
std::string matches_csv(const DatasetRun& dataset, const DescriptorRun& run) {
  std::string csv = csv_line({"query", "match", "distance", "query_x", "query_y", "match_x",
                              "match_y", "correct", "revisit", "first_correct_rank"});
  const auto& database = dataset.database();
  for (const auto& r : run.evaluation.results) {
    const Pose2D& q = dataset.query_records[r.query].pose;
    const Pose2D& m = database[r.match].pose;
    csv += fmt::format("{},{},{},{},{},{},{},{},{},{}\n", r.query, r.match, r.distance, q.x, q.y,
                       m.x, m.y, int(r.correct), int(r.revisit), r.first_correct_rank);
  }
  return csv;
}

std::string curve_csv(const DescriptorRun& run) {
  std::string csv =
      csv_line({"threshold", "tp", "fp", "fn", "tn", "precision", "recall", "f1", "tpr", "fpr"});
  for (const auto& p : run.evaluation.curve) {
    csv += fmt::format("{},{},{},{},{},{},{},{},{},{}\n", p.threshold, p.counts.tp, p.counts.fp,
                       p.counts.fn, p.counts.tn, optional_csv(p.precision), optional_csv(p.recall),
                       optional_csv(p.f1), optional_csv(p.recall), optional_csv(p.fpr));
  }
  return csv;
}

std::string matching_graph_csv(const DatasetRun& dataset, const DescriptorRun& run) {
  // At the F1-max threshold, which metrics.json gives as f1_max_threshold.
  std::string csv = csv_line({"query", "match", "label", "distance", "query_x", "query_y",
                              "query_time_s", "match_x", "match_y", "match_time_s"});
  const auto& database = dataset.database();
  for (const auto& edge : run.evaluation.matching_graph) {
    const ScanRecord& q = dataset.query_records[edge.query];
    const ScanRecord& m = database[edge.match];
    csv += fmt::format("{},{},{},{},{},{},{:.6f},{},{},{:.6f}\n", edge.query, edge.match,
                       to_string(edge.label), edge.distance, q.pose.x, q.pose.y,
                       seconds_of(q.timestamp_ns), m.pose.x, m.pose.y, seconds_of(m.timestamp_ns));
  }
  return csv;
}

// Every frame's pose, query session first: the matching graph draws its edges on this path.
std::string trajectory_csv(const DatasetRun& dataset) {
  std::string csv = csv_line({"session", "frame", "x", "y", "time_s"});
  auto append = [&](const char* session, const std::vector<ScanRecord>& records) {
    for (std::size_t i = 0; i < records.size(); ++i) {
      csv += fmt::format("{},{},{},{},{:.6f}\n", session, i, records[i].pose.x, records[i].pose.y,
                         seconds_of(records[i].timestamp_ns));
    }
  };
  append("query", dataset.query_records);
  if (dataset.multi_session) append("database", dataset.database_records);
  return csv;
}

std::string summary_csv(const ExperimentConfig& config, const ExperimentRun& run) {
  std::vector<std::string> header = {"dataset",
                                     "session",
                                     "descriptor",
                                     "label",
                                     "rows",
                                     "cols",
                                     "element_type",
                                     "payload_bytes",
                                     "paper_bytes",
                                     "rotation_invariant",
                                     "queries",
                                     "revisits",
                                     "roc_auc",
                                     "f1_max",
                                     "f1_max_threshold",
                                     "pr_auc_trapezoid",
                                     "average_precision",
                                     "recall_at_1"};
  // Recall@1 has its own column above.
  for (int k : config.protocol.recall_at_k) {
    if (k != 1) header.push_back(fmt::format("recall_at_{}", k));
  }
  for (const char* name : {"recall_at_100_precision", "extended_precision"}) {
    header.push_back(name);
  }
  std::string csv = csv_line(header);
  for (const auto& dataset : run.datasets) {
    for (const auto& d : dataset.descriptors) {
      const Metrics& m = d.evaluation.metrics;
      std::vector<std::string> row = {dataset.name,
                                      dataset.multi_session ? "multi" : "single",
                                      d.id,
                                      d.label,
                                      fmt::format("{}", d.rows),
                                      fmt::format("{}", d.cols),
                                      std::string(kDescriptorElementType),
                                      fmt::format("{}", d.payload_bytes),
                                      fmt::format("{}", d.paper_bytes),
                                      fmt::format("{}", d.rotation_invariant),
                                      fmt::format("{}", m.queries),
                                      fmt::format("{}", m.revisits),
                                      optional_csv(m.roc_auc),
                                      optional_csv(m.f1_max),
                                      optional_csv(m.f1_max_threshold),
                                      optional_csv(m.pr_auc),
                                      optional_csv(m.average_precision),
                                      optional_csv(m.recall_at_1)};
      for (int k : config.protocol.recall_at_k) {
        if (k == 1) continue;
        const auto it = m.recall_at_k.find(k);
        row.push_back(optional_csv(it == m.recall_at_k.end() ? std::nullopt : it->second));
      }
      row.push_back(optional_csv(m.recall_at_100_precision));
      row.push_back(optional_csv(m.extended_precision));
      csv += csv_line(row);
    }
  }
  return csv;
}

std::string_view roc_auc_sentence(RocAucVariant variant) {
  switch (variant) {
    case RocAucVariant::pooled_pairs:
      return "`pooled_pairs`, every pair accepted at every threshold pooled (label: wrong, score: "
             "distance), as the ReFeree code computes it";
    case RocAucVariant::query_ranks:
      return "`query_ranks`, one sample per query (label: right, score: minus the distance), as "
             "VPR-Bench computes it";
    case RocAucVariant::trapezoid:
      break;
  }
  return "trapezoid over the sweep with (0,0) and (1,1) added";
}

// Which queries the summary's Recall@K columns are a share of (Protocol::recall_denominator).
std::string_view recall_sentence(RecallDenominator denominator) {
  switch (denominator) {
    case RecallDenominator::all_queries:
      return "share of all evaluated queries with a frame within the radius among the K nearest "
             "(denominator `all_queries`)";
    case RecallDenominator::queries_with_positive:
      return "share of the queries with a positive in their database with a frame within the "
             "radius among the K nearest (denominator `queries_with_positive`)";
    case RecallDenominator::revisit_queries:
      break;
  }
  return "share of revisit queries with a frame within the radius among the K nearest";
}

// `tables`: the summary as the report reads it, so that Table I and II are the report's tables.
std::string markdown_of(const ExperimentConfig& config, const ExperimentRun& run,
                        const RunResults& tables) {
  const Protocol& p = config.protocol;
  std::string md = fmt::format("# {} (radarpr {})\n\n", config.name, radarpr_version());
  if (!config.description.empty()) md += markdown_cell(config.description) + "\n\n";
  // A preset is named only when it is not radarpr's own protocol (the summaries of the default
  // stay as they were).
  if (p.preset != ProtocolPreset::radarpr) {
    md += fmt::format(
        "Protocol preset `{}` (protocols.md); the revisit radius is {}; over session pairs its "
        "aggregate is the {}.\n\n",
        to_string(p.preset),
        p.radius_comparison == RadiusComparison::strict ? "strict (distance < radius)"
                                                        : "inclusive",
        to_string(p.pair_aggregation));
  }
  md += fmt::format(
      "Protocol: revisit radius {} m{}; labels `{}`; threshold sweep `{}`; a query is accepted "
      "when "
      "its top-1 distance {} the threshold. ROC AUC: {}. F1-max: best F1 over the sweep. "
      "Recall@K: {}.\n\n",
      p.revisit_radius_m,
      p.revisit_max_yaw_deg
          ? fmt::format(" and headings at most {} degrees apart", *p.revisit_max_yaw_deg)
          : std::string(),
      to_string(p.labels), to_string(p.sweep),
      p.threshold_comparison == ThresholdComparison::strict ? "<" : "<=",
      roc_auc_sentence(p.roc_auc), recall_sentence(p.recall_denominator));
  for (const auto& dataset : run.datasets) {
    md += fmt::format("## {}\n\n{}\n\n", markdown_cell(dataset.name),
                      markdown_cell(describe_session(dataset, p)));
    md += summary_table(dataset, p) + "\n";
  }
  for (const auto& matrix : config.matrices) md += matrix_summary_markdown(config, matrix, run);
  // Plain: the report's copies mark the best of each column in bold.
  md += fmt::format("## {}\n\n{}\n", kMetricsTableTitle,
                    to_markdown(without_bold(metrics_table(tables))));
  md += fmt::format("## {}\n\n{}", kSizeTableTitle, to_markdown(size_table(tables))) +
        "\nPaper bytes: elements x 8 + 128, a float64 numpy file, the convention behind the "
        "ReFeree paper's size table (ReFeree 528 B, RadVLAD 262,272 B, Raplace 3,008 B). Its "
        "RadarSC 1,616 B and RadarSC-DS 346 B are two numpy files each, the context as uint8 and "
        "the ring key as float64 (docs/descriptors.md); the sizes here are measured from the "
        "values.\n\n";
  // A paper's published tables beside this run's, when the config names them.
  md += published_comparison_markdown(config, run);
  return md;
}

void write_descriptor_files(const fs::path& folder, const ExperimentConfig& config,
                            const DatasetRun& dataset, const DescriptorRun& run) {
  fs::create_directories(folder);
  nlohmann::json metrics{
      {"radarpr_version", radarpr_version()},
      {"experiment", config.name},
      {"protocol", protocol_to_json(config.protocol)},
  };
  metrics.update(summary_row(dataset, run));
  make_json_utf8(metrics);
  write_file(folder / "metrics.json", metrics.dump(2) + "\n");
  write_file(folder / "matches.csv", matches_csv(dataset, run));
  write_file(folder / "curve.csv", curve_csv(run));
  write_file(folder / "matching_graph.csv", matching_graph_csv(dataset, run));
}

// summary.json: what a rerun reproduces byte for byte.
nlohmann::json summary_json(const ExperimentConfig& config, const ExperimentRun& run) {
  nlohmann::json summary{
      {"radarpr_version", radarpr_version()},
      {"experiment", config.name},
      {"description", config.description},
      {"protocol", protocol_to_json(config.protocol)},
      {"config", config.resolved},
  };
  nlohmann::json ids = nlohmann::json::array();
  for (const auto& instance : config.descriptors) ids.push_back(instance.id);
  summary["descriptors"] = ids;
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& dataset : run.datasets) {
    for (const auto& descriptor : dataset.descriptors) {
      rows.push_back(summary_row(dataset, descriptor));
    }
  }
  summary["rows"] = rows;
  if (!config.matrices.empty()) {
    // Which datasets are the pairs of which session matrix, for the report's matrix figures.
    nlohmann::json matrices = nlohmann::json::array();
    for (const auto& matrix : config.matrices) {
      nlohmann::json sessions = nlohmann::json::array();
      for (const auto& session : matrix.sessions) sessions.push_back(session.name);
      nlohmann::json pairs = nlohmann::json::array();
      for (std::size_t p = 0; p < matrix.pairs.size(); ++p) {
        pairs.push_back({{"query", matrix.pairs[p].first},
                         {"database", matrix.pairs[p].second},
                         {"dataset", config.datasets[matrix.first_dataset + p].name}});
      }
      matrices.push_back({{"name", matrix.name}, {"sessions", sessions}, {"pairs", pairs}});
    }
    summary["matrices"] = matrices;
  }
  make_json_utf8(summary);  // sequence names come from folder names: bytes, not always UTF-8
  return summary;
}

void write_all(const fs::path& folder, const ExperimentConfig& config, const ExperimentRun& run) {
  fs::create_directories(folder);
  const nlohmann::json summary = summary_json(config, run);
  nlohmann::json timing{
      {"radarpr_version", radarpr_version()},
      {"experiment", config.name},
      {"seconds", run.seconds},
      {"machine", describe_run_machine()},
  };
  nlohmann::json timing_rows = nlohmann::json::array();
  for (const auto& dataset : run.datasets) {
    fs::create_directories(folder / dataset.name);
    write_file(folder / dataset.name / "trajectory.csv", trajectory_csv(dataset));
    for (const auto& descriptor : dataset.descriptors) {
      timing_rows.push_back(timing_row(dataset, descriptor));
      write_descriptor_files(folder / dataset.name / descriptor_folder_name(descriptor.id), config,
                             dataset, descriptor);
    }
  }
  timing["rows"] = timing_rows;
  for (const auto& matrix : config.matrices) {
    fs::create_directories(folder / matrix.name);
    write_file(folder / matrix.name / "pairs.csv", matrix_pairs_csv(config, matrix, run));
    write_file(folder / matrix.name / "aggregate.csv", matrix_aggregate_csv(config, matrix, run));
  }
  make_json_utf8(timing);  // sequence names come from folder names: bytes, not always UTF-8
  write_file(folder / "summary.json", summary.dump(2) + "\n");
  write_file(folder / "timing.json", timing.dump(2) + "\n");
  write_file(folder / "summary.csv", summary_csv(config, run));
  if (config.published) {
    write_file(folder / "published_comparison.csv", published_comparison_csv(config, run));
  }
  write_file(folder / "summary.md",
             markdown_of(config, run, run_summary(summary, folder / "summary.json")));
}

}  // namespace

std::string summary_markdown(const ExperimentConfig& config, const ExperimentRun& run) {
  return markdown_of(config, run, run_summary(summary_json(config, run), "summary.json"));
}

namespace {

// A folder the writer may replace wholesale: empty, or written by a radarpr run before. Anything
// else (a source tree, a home folder, the working directory) is never deleted.
// A fresh clone holds a committed reference run as its summary.md alone (results/README.md): that
// folder, and nothing else beside that file, counts as results too.
bool replaceable(const fs::path& folder) {
  if (fs::is_empty(folder)) return true;
  std::ifstream summary(folder / "summary.json");
  const auto json = nlohmann::json::parse(summary, nullptr, /*allow_exceptions=*/false);
  if (json.is_object() && json.contains("radarpr_version")) return true;
  const auto entries = std::distance(fs::directory_iterator(folder), fs::directory_iterator());
  std::ifstream markdown(folder / "summary.md");
  std::string first_line;
  std::getline(markdown, first_line);
  return entries == 1 && first_line.starts_with("# ") &&
         first_line.find(" (radarpr ") != std::string::npos;
}

}  // namespace

fs::path resolve_results_folder(const fs::path& out_dir) {
  fs::path target = fs::absolute(out_dir).lexically_normal();
  if (!target.has_filename()) target = target.parent_path();  // "out/" -> "out"
  if (target == target.root_path()) {
    throw std::runtime_error(
        fmt::format("{}: results need a folder of their own", out_dir.string()));
  }
  if (fs::exists(target)) {
    if (!fs::is_directory(target)) {
      throw std::runtime_error(
          fmt::format("{}: exists and is not a folder; choose another --out", out_dir.string()));
    }
    if (!replaceable(target)) {
      throw std::runtime_error(fmt::format(
          "{}: exists and does not hold radarpr results; refusing to replace it (choose another "
          "--out, or remove it first)",
          out_dir.string()));
    }
  }
  return target;
}

namespace {

void remove_if_not_rewritten(const fs::path& file, const fs::path& rewritten) {
  std::error_code ignored;
  if (!fs::exists(rewritten, ignored)) fs::remove(file, ignored);
}

void remove_if_empty(const fs::path& folder) {
  std::error_code ignored;
  if (fs::is_directory(folder, ignored) && fs::is_empty(folder, ignored))
    fs::remove(folder, ignored);
}

// The files the previous run in `target` wrote (named by its summary.json) that this run, staged
// in `staging`, does not write again: a descriptor or dataset since dropped from the config. Only
// those go; a user's own files in the folder (an edited figure script) are never deleted.
void remove_previous_results(const fs::path& target, const fs::path& staging) {
  std::ifstream file(target / "summary.json");
  const auto summary = nlohmann::json::parse(file, nullptr, /*allow_exceptions=*/false);
  if (!summary.is_object() || !summary.contains("rows") || !summary["rows"].is_array()) return;
  for (const auto& row : summary["rows"]) {
    if (!row.is_object() || !row.contains("dataset") || !row["dataset"].is_string() ||
        !row.contains("descriptor") || !row["descriptor"].is_string()) {
      continue;
    }
    const std::string dataset = row["dataset"].get<std::string>();
    const std::string descriptor = descriptor_folder_name(row["descriptor"].get<std::string>());
    if (!is_safe_name(dataset) || !is_safe_name(descriptor)) continue;  // never outside target
    for (const char* name : {"metrics.json", "matches.csv", "curve.csv", "matching_graph.csv"}) {
      remove_if_not_rewritten(target / dataset / descriptor / name,
                              staging / dataset / descriptor / name);
    }
    remove_if_empty(target / dataset / descriptor);
    remove_if_not_rewritten(target / dataset / "trajectory.csv",
                            staging / dataset / "trajectory.csv");
    remove_if_empty(target / dataset);
  }
}

}  // namespace

void write_results(const fs::path& out_dir, const ExperimentConfig& config,
                   const ExperimentRun& run) {
  const fs::path target = resolve_results_folder(out_dir);
  const fs::path parent = target.parent_path();
  const std::string prefix = target.filename().string() + ".partial.";
  const fs::path staging = parent / fmt::format("{}{}", prefix, ::getpid());
  try {
    fs::create_directories(parent);
    remove_stale_staging(parent, prefix);  // left by a run killed while writing
    fs::remove_all(staging);
    write_all(staging, config, run);
    fs::create_directories(target);
    remove_previous_results(target, staging);
    publish_staged(staging, target);
  } catch (const fs::filesystem_error& error) {
    std::error_code ignored;
    fs::remove_all(staging, ignored);
    throw std::runtime_error(
        fmt::format("{}: cannot write the results ({})", target.string(), error.what()));
  } catch (...) {
    std::error_code ignored;
    fs::remove_all(staging, ignored);
    throw;
  }
}

nlohmann::json metrics_to_json(const Metrics& metrics) {
  return metrics_json(metrics);
}

}  // namespace radarpr
