#include "evaluation/results/results_reader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <map>

#include <fmt/format.h>

#include "evaluation/results/csv_file.hpp"
#include "evaluation/results/results_error.hpp"
#include "evaluation/results/results_writer.hpp"
#include "evaluation/safe_name.hpp"
#include "evaluation/text_escaping.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

nlohmann::json read_json(const fs::path& path) {
  std::ifstream file(path);
  if (!file)
    throw ResultsError(fmt::format("{}: missing or unreadable (a JSON file)", path.string()));
  nlohmann::json json = nlohmann::json::parse(file, nullptr, /*allow_exceptions=*/false);
  if (json.is_discarded()) {
    throw ResultsError(fmt::format("{}: not valid JSON (truncated or edited?)", path.string()));
  }
  return json;
}

// summary.json's field `key` of `row`, checked for type; names the file and the row on error.
const nlohmann::json& field(const fs::path& path, const nlohmann::json& row, std::size_t index,
                            const char* key, bool (nlohmann::json::*is_type)() const noexcept,
                            const char* expected) {
  if (!row.contains(key) || !(row[key].*is_type)()) {
    throw ResultsError(
        fmt::format("{}: rows[{}].{} missing or not {}", path.string(), index, key, expected));
  }
  return row[key];
}

std::optional<double> optional_metric(const fs::path& path, const nlohmann::json& row,
                                      std::size_t index, const char* key) {
  if (row.contains(key) && row[key].is_null()) return std::nullopt;
  return field(path, row, index, key, &nlohmann::json::is_number, "a number or null").get<double>();
}

// As optional_metric, and also empty when the key is absent (results older than the metric).
std::optional<double> metric_if_recorded(const fs::path& path, const nlohmann::json& row,
                                         std::size_t index, const char* key) {
  if (!row.contains(key)) return std::nullopt;
  return optional_metric(path, row, index, key);
}

void require_folder_name(const fs::path& path, std::size_t index, const char* key,
                         const std::string& name) {
  if (const auto reason = unsafe_name_reason(name)) {
    throw ResultsError(
        fmt::format("{}: rows[{}].{} gives the folder name '{}', which {}; {} expected",
                    path.string(), index, key, printable(name), *reason, safe_name_rule()));
  }
}

// A row's time and value source: in timing.json, or in summary.json's rows for results written
// before timing.json existed. Optional either way.
void read_timing(const fs::path& path, const nlohmann::json& row, std::size_t i, ResultRow& r) {
  if (row.contains("extract_ms_per_scan")) {
    r.extract_ms_per_scan =
        field(path, row, i, "extract_ms_per_scan", &nlohmann::json::is_number, "a number")
            .get<double>();
  }
  // Optional: results written before the descriptor cache have no "values_from".
  if (row.contains("values_from") && row["values_from"].is_object() &&
      row["values_from"].contains("query") && row["values_from"]["query"].is_string()) {
    r.query_values_from = row["values_from"]["query"].get<std::string>();
  }
}

// A size in bytes: a whole number in [0, 2^53] (exact as a double, printed as written).
double byte_count(const fs::path& path, const nlohmann::json& row, std::size_t index,
                  const char* key) {
  const double value =
      field(path, row, index, key, &nlohmann::json::is_number, "a number").get<double>();
  if (!(value >= 0.0) || value > 9007199254740992.0 || value != std::floor(value)) {
    throw ResultsError(fmt::format("{}: rows[{}].{} is {}; a whole number of bytes >= 0 expected",
                                   path.string(), index, key, row[key].dump()));
  }
  return value;
}

ResultRow parse_row(const fs::path& path, const nlohmann::json& row, std::size_t i) {
  using J = nlohmann::json;
  ResultRow r;
  r.dataset = field(path, row, i, "dataset", &J::is_string, "a string").get<std::string>();
  const auto session = field(path, row, i, "session", &J::is_string, "a string").get<std::string>();
  if (session != "single" && session != "multi") {
    throw ResultsError(fmt::format("{}: rows[{}].session is '{}'; \"single\" or \"multi\" expected",
                                   path.string(), i, session));
  }
  r.multi_session = session == "multi";
  r.descriptor = field(path, row, i, "descriptor", &J::is_string, "a string").get<std::string>();
  // Both name folders the report reads: a summary must not point it outside the results.
  require_folder_name(path, i, "dataset", r.dataset);
  require_folder_name(path, i, "descriptor", descriptor_folder_name(r.descriptor));
  r.label = field(path, row, i, "label", &J::is_string, "a string").get<std::string>();
  const J& shape = field(path, row, i, "shape", &J::is_array, "an array");
  // Each dimension in [1, 2^31 - 1]: read as int, a larger one (2^40) wrapped to a shape of 0x1.
  constexpr std::int64_t kLargestDimension = std::numeric_limits<int>::max();
  const auto dimension = [&](const J& value) {
    return value.is_number_integer() && value.get<std::int64_t>() >= 1 &&
           (value.is_number_unsigned() ? value.get<std::uint64_t>() <= kLargestDimension
                                       : value.get<std::int64_t>() <= kLargestDimension);
  };
  if (shape.size() != 2 || !dimension(shape[0]) || !dimension(shape[1])) {
    throw ResultsError(fmt::format(
        "{}: rows[{}].shape is {}; [rows, cols] expected, each a whole number in [1, {}]",
        path.string(), i, shape.dump(), kLargestDimension));
  }
  r.rows = shape[0].get<int>();
  r.cols = shape[1].get<int>();
  r.element_type =
      field(path, row, i, "element_type", &J::is_string, "a string").get<std::string>();
  r.payload_bytes = byte_count(path, row, i, "payload_bytes");
  r.paper_bytes = byte_count(path, row, i, "paper_bytes");
  r.rotation_invariant =
      field(path, row, i, "rotation_invariant", &J::is_boolean, "a boolean").get<bool>();
  r.roc_auc = optional_metric(path, row, i, "roc_auc");
  r.f1_max = optional_metric(path, row, i, "f1_max");
  r.f1_max_threshold = optional_metric(path, row, i, "f1_max_threshold");
  r.pr_auc = metric_if_recorded(path, row, i, "pr_auc_trapezoid");
  r.recall_at_1 = metric_if_recorded(path, row, i, "recall_at_1");
  r.recall_at_100_precision = metric_if_recorded(path, row, i, "recall_at_100_precision");
  if (row.contains("ranked_frames")) {
    const nlohmann::json& ranked = row["ranked_frames"];
    if (!ranked.is_number_unsigned()) {
      throw ResultsError(fmt::format("{}: rows[{}].ranked_frames is {}; a whole number expected",
                                     path.string(), i, ranked.dump()));
    }
    r.ranked_frames = ranked.get<std::size_t>();
  }
  read_timing(path, row, i, r);
  return r;
}

std::vector<SweepPoint> read_curve(const fs::path& path) {
  const CsvFile csv(path);
  const std::size_t threshold = csv.column("threshold"), precision = csv.column("precision"),
                    recall = csv.column("recall"), fpr = csv.column("fpr"), f1 = csv.column("f1");
  if (csv.row_count() == 0) {
    throw ResultsError(
        fmt::format("{}: no sweep points; at least one row expected", path.string()));
  }
  std::vector<SweepPoint> points(csv.row_count());
  for (std::size_t i = 0; i < csv.row_count(); ++i) {
    SweepPoint& p = points[i];
    p.threshold = csv.number(i, threshold);
    double value = 0.0;
    if (csv.optional_number(i, precision, value)) p.precision = value;
    if (csv.optional_number(i, f1, value)) p.f1 = value;
    // Recall and FPR are undefined only without revisits / non-revisits: drawn as 0.
    p.recall = csv.optional_number(i, recall, value) ? value : 0.0;
    p.fpr = csv.optional_number(i, fpr, value) ? value : 0.0;
  }
  return points;
}

// How many frames each session has, when trajectory.csv says (results without it: unknown).
struct FrameLimits {
  std::optional<std::size_t> query, database;
};

std::size_t frame_index(const CsvFile& csv, std::size_t row, std::size_t column,
                        const std::optional<std::size_t>& limit, const char* session) {
  if (!limit) return csv.index(row, column);
  return csv.index(row, column, *limit,
                   fmt::format("the {} {} frames of trajectory.csv", *limit, session));
}

std::vector<GraphEdge> read_graph(const fs::path& path, const FrameLimits& limits,
                                  bool multi_session) {
  const CsvFile csv(path);
  const std::size_t query = csv.column("query"), match = csv.column("match"),
                    label = csv.column("label"), qx = csv.column("query_x"),
                    qy = csv.column("query_y"), mx = csv.column("match_x"),
                    my = csv.column("match_y");
  std::vector<GraphEdge> edges(csv.row_count());
  for (std::size_t i = 0; i < csv.row_count(); ++i) {
    GraphEdge& e = edges[i];
    e.query = frame_index(csv, i, query, limits.query, "query");
    e.match = multi_session ? frame_index(csv, i, match, limits.database, "database")
                            : frame_index(csv, i, match, limits.query, "query");
    // Written "TP"/"FP"/"FN" (to_string(GraphLabel)); kept lower-case here.
    e.label = csv.text(i, label);
    for (char& c : e.label) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (e.label != "tp" && e.label != "fp" && e.label != "fn") {
      csv.fail(i, fmt::format("label '{}'; TP, FP or FN expected", e.label));
    }
    e.query_x = csv.number(i, qx);
    e.query_y = csv.number(i, qy);
    e.match_x = csv.number(i, mx);
    e.match_y = csv.number(i, my);
  }
  return edges;
}

// matches.csv's revisit flag and first correct rank per query, for the Recall@N curve.
std::vector<std::pair<bool, std::size_t>> read_ranks(const fs::path& path) {
  const CsvFile csv(path);
  const std::size_t revisit = csv.column("revisit"), rank = csv.column("first_correct_rank");
  std::vector<std::pair<bool, std::size_t>> ranks;
  ranks.reserve(csv.row_count());
  for (std::size_t i = 0; i < csv.row_count(); ++i) {
    const std::size_t flag = csv.index(i, revisit);
    if (flag > 1) csv.fail(i, fmt::format("revisit is {}; 0 or 1 expected", flag));
    ranks.emplace_back(flag == 1, csv.index(i, rank));
  }
  return ranks;
}

// Results written before trajectory.csv existed: the path is pieced together from the frames
// matches.csv names (each query's pose and its match's), so the matching graph still has one.
DatasetTrajectory trajectory_from_matches(const fs::path& trajectory_path,
                                          const fs::path& matches_path, bool multi_session) {
  if (!fs::exists(matches_path)) {
    throw ResultsError(fmt::format("{}: missing (nor is there {} to draw the path from)",
                                   trajectory_path.string(), matches_path.string()));
  }
  const CsvFile csv(matches_path);
  const std::size_t query = csv.column("query"), match = csv.column("match"),
                    qx = csv.column("query_x"), qy = csv.column("query_y"),
                    mx = csv.column("match_x"), my = csv.column("match_y");
  std::map<std::size_t, TrajectoryPoint> queries, database;
  for (std::size_t i = 0; i < csv.row_count(); ++i) {
    const std::size_t q = csv.index(i, query);
    const std::size_t m = csv.index(i, match);
    queries[q] = {q, csv.number(i, qx), csv.number(i, qy)};
    (multi_session ? database : queries)[m] = {m, csv.number(i, mx), csv.number(i, my)};
  }
  DatasetTrajectory trajectory;
  for (const auto& [frame, point] : queries) trajectory.query.push_back(point);
  for (const auto& [frame, point] : database) trajectory.database.push_back(point);
  return trajectory;
}

DatasetTrajectory read_trajectory(const fs::path& path, const fs::path& matches_path,
                                  bool multi_session) {
  if (!fs::exists(path)) return trajectory_from_matches(path, matches_path, multi_session);
  DatasetTrajectory trajectory;
  const CsvFile csv(path);
  const std::size_t session = csv.column("session"), frame = csv.column("frame"),
                    x = csv.column("x"), y = csv.column("y");
  for (std::size_t i = 0; i < csv.row_count(); ++i) {
    const std::string& kind = csv.text(i, session);
    if (kind != "query" && kind != "database") {
      csv.fail(i, fmt::format("session '{}'; query or database expected", kind));
    }
    const TrajectoryPoint point{csv.index(i, frame), csv.number(i, x), csv.number(i, y)};
    (kind == "database" ? trajectory.database : trajectory.query).push_back(point);
  }
  trajectory.from_file = true;
  return trajectory;
}

FrameLimits frame_limits(const DatasetTrajectory& trajectory) {
  if (!trajectory.from_file) return {};
  auto count = [](const std::vector<TrajectoryPoint>& points) {
    std::size_t frames = 0;
    for (const auto& p : points) frames = std::max(frames, p.frame + 1);
    return frames;
  };
  return {count(trajectory.query), count(trajectory.database)};
}

}  // namespace

const ResultRow* RunResults::find(const std::string& dataset, const std::string& descriptor) const {
  for (const auto& row : rows) {
    if (row.dataset == dataset && row.descriptor == descriptor) return &row;
  }
  return nullptr;
}

bool RunResults::multi_session(const std::string& dataset) const {
  return std::any_of(rows.begin(), rows.end(), [&](const ResultRow& row) {
    return row.dataset == dataset && row.multi_session;
  });
}

RunResults run_summary(const nlohmann::json& s, const fs::path& summary_path) {
  RunResults run;
  run.summary = s;
  if (!s.is_object() || !s.contains("radarpr_version") || !s.contains("experiment") ||
      !s["experiment"].is_string() || !s.contains("rows") || !s["rows"].is_array() ||
      !s.contains("descriptors") || !s["descriptors"].is_array()) {
    throw ResultsError(fmt::format(
        "{}: not a radarpr summary (radarpr_version, experiment, descriptors and rows expected)",
        summary_path.string()));
  }
  run.experiment = s["experiment"].get<std::string>();
  for (const auto& id : s["descriptors"]) {
    if (!id.is_string()) {
      throw ResultsError(fmt::format("{}: descriptors holds a non-string", summary_path.string()));
    }
    run.descriptors.push_back(id.get<std::string>());
  }
  for (std::size_t i = 0; i < s["rows"].size(); ++i) {
    ResultRow row = parse_row(summary_path, s["rows"][i], i);
    if (std::find(run.datasets.begin(), run.datasets.end(), row.dataset) == run.datasets.end()) {
      run.datasets.push_back(row.dataset);
    }
    run.rows.push_back(std::move(row));
  }
  if (run.rows.empty()) {
    throw ResultsError(
        fmt::format("{}: rows is empty; a run with results expected", summary_path.string()));
  }
  return run;
}

RunResults read_run_results(const fs::path& folder) {
  if (!fs::is_directory(folder)) {
    throw ResultsError(
        fmt::format("{}: not a folder; a radarpr results folder expected", folder.string()));
  }
  RunResults run = run_summary(read_json(folder / "summary.json"), folder / "summary.json");
  run.folder = folder;
  // timing.json is optional: committed reference results leave it out (it differs every run).
  const fs::path timing_path = folder / "timing.json";
  if (fs::exists(timing_path)) {
    run.timing = read_json(timing_path);
    if (!run.timing.is_object() || !run.timing.contains("rows") || !run.timing["rows"].is_array()) {
      throw ResultsError(
          fmt::format("{}: not a radarpr timing record (rows expected)", timing_path.string()));
    }
    const nlohmann::json& rows = run.timing["rows"];
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const nlohmann::json& row = rows[i];
      if (!row.is_object() || !row.contains("dataset") || !row["dataset"].is_string() ||
          !row.contains("descriptor") || !row["descriptor"].is_string()) {
        throw ResultsError(
            fmt::format("{}: rows[{}] names no dataset and descriptor", timing_path.string(), i));
      }
      for (auto& r : run.rows) {
        if (r.dataset == row["dataset"] && r.descriptor == row["descriptor"]) {
          read_timing(timing_path, row, i, r);
        }
      }
    }
  }
  // The path first: the matching graphs' frame indices are checked against its length.
  for (const auto& dataset : run.datasets) {
    // Any descriptor's matches.csv holds the same query and database poses: the first one's.
    const ResultRow* first = nullptr;
    for (const auto& row : run.rows) {
      if (row.dataset == dataset && first == nullptr) first = &row;
    }
    run.trajectories.push_back(read_trajectory(
        folder / dataset / "trajectory.csv",
        folder / dataset / descriptor_folder_name(first->descriptor) / "matches.csv",
        run.multi_session(dataset)));
  }
  for (auto& row : run.rows) {
    const auto d = static_cast<std::size_t>(
        std::find(run.datasets.begin(), run.datasets.end(), row.dataset) - run.datasets.begin());
    const fs::path descriptor_folder =
        folder / row.dataset / descriptor_folder_name(row.descriptor);
    row.curve = read_curve(descriptor_folder / "curve.csv");
    row.ranks = read_ranks(descriptor_folder / "matches.csv");
    row.graph = read_graph(descriptor_folder / "matching_graph.csv",
                           frame_limits(run.trajectories[d]), row.multi_session);
  }
  return run;
}

}  // namespace radarpr
