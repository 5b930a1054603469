// A descriptor's values exported to .npy (radarpr export) and evaluated again as `precomputed`
// give the descriptor's own metrics exactly: the route a Python model's values take into radarpr.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <tuple>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "datasets/npy_file.hpp"
#include "evaluation/config/sequence_config.hpp"
#include "evaluation/experiment_runner.hpp"
#include "evaluation/results/value_export.hpp"
#include "evaluation/study/study_plan.hpp"
#include "tests/datasets/dataset_tree.hpp"

namespace radarpr {
namespace {

using test::TempTree;

nlohmann::json experiment(const nlohmann::json& descriptors) {
  nlohmann::json json = nlohmann::json::parse(R"({
    "experiment": "precomputed_run_test",
    "datasets": [
      {"name": "single", "query": {"type": "synthetic", "seed": 5, "scans": 60,
        "azimuths": 120, "range_bins": 210, "range_resolution_m": 0.476, "route_blocks_x": 1, "speed_mps": 40}},
      {"name": "multi",
       "query": {"type": "synthetic", "seed": 5, "session": 1, "scans": 30,
        "azimuths": 120, "range_bins": 210, "range_resolution_m": 0.476, "route_blocks_x": 1, "speed_mps": 40},
       "database": {"type": "synthetic", "seed": 5, "session": 2, "scans": 40,
        "azimuths": 120, "range_bins": 210, "range_resolution_m": 0.476, "route_blocks_x": 1, "speed_mps": 40}}
    ],
    "protocol": {"exclude_recent_frames": 10, "revisit_radius_m": 10, "recall_at_k": [1, 3]}
  })");
  json["descriptors"] = descriptors;
  return json;
}

void write_session(const std::filesystem::path& folder, const std::vector<ScanRecord>& records,
                   const std::vector<DescriptorValue>& values) {
  std::filesystem::create_directories(folder);
  std::vector<float> flat;
  for (const auto& value : values)
    flat.insert(flat.end(), value.values.begin(), value.values.end());
  write_npy(folder / "values.npy", {values.size(), values.front().values.size()},
            std::span<const float>(flat));
  std::vector<std::int64_t> times;
  for (const auto& record : records) times.push_back(record.timestamp_ns);
  write_npy(folder / "timestamps.npy", {times.size()}, std::span<const std::int64_t>(times));
}

TEST(PrecomputedRun, ExportedValuesReproduceTheDescriptorsMetricsExactly) {
  const TempTree tree;
  const ExperimentConfig config =
      parse_experiment_config(experiment(nlohmann::json::array({"referee_r"})));
  const ExperimentRun referee = run_experiment(config, false);
  const auto written = export_descriptor_values(config, tree.root(), false);
  // Per session: timestamps, positions and the one descriptor's values.
  EXPECT_EQ(written.size(), 3u * 3u);
  const NpyFile positions = NpyFile::open(tree.path("multi/database/positions.npy"));
  EXPECT_EQ(positions.shape(), (std::vector<std::size_t>{40, 3}));
  EXPECT_EQ(positions.as_doubles()[3], referee.datasets[1].database_records[1].pose.x);
  EXPECT_EQ(NpyFile::open(tree.path("single/query/referee_r.npy")).shape(),
            (std::vector<std::size_t>{
                60, static_cast<std::size_t>(referee.datasets[0].descriptors[0].rows)}));
  const nlohmann::json precomputed = {
      {"name", "precomputed"},
      {"label", "referee_r from .npy"},
      {"params",
       {{"values", (tree.root() / "{dataset}/{role}/referee_r.npy").string()},
        {"timestamps", (tree.root() / "{dataset}/{role}/timestamps.npy").string()},
        {"rotation_invariant", true}}}};
  const ExperimentRun replayed = run_experiment(
      parse_experiment_config(experiment(nlohmann::json::array({precomputed}))), false);
  ASSERT_EQ(replayed.datasets.size(), referee.datasets.size());
  for (std::size_t d = 0; d < referee.datasets.size(); ++d) {
    const DescriptorRun& a = referee.datasets[d].descriptors.front();
    const DescriptorRun& b = replayed.datasets[d].descriptors.front();
    EXPECT_EQ(b.label, "referee_r from .npy");
    EXPECT_EQ(a.rows, b.rows);
    EXPECT_EQ(a.cols, b.cols);
    EXPECT_EQ(a.rotation_invariant, b.rotation_invariant);
    const Metrics& m = a.evaluation.metrics;
    const Metrics& n = b.evaluation.metrics;
    EXPECT_EQ(m.queries, n.queries);
    EXPECT_EQ(m.revisits, n.revisits);
    EXPECT_EQ(m.correct_top1, n.correct_top1);
    EXPECT_EQ(m.roc_auc, n.roc_auc);
    EXPECT_EQ(m.f1_max, n.f1_max);
    EXPECT_EQ(m.recall_at_1, n.recall_at_1);
    EXPECT_EQ(m.recall_at_k, n.recall_at_k);
    EXPECT_EQ(m.average_precision, n.average_precision);
    ASSERT_EQ(a.evaluation.results.size(), b.evaluation.results.size());
    ASSERT_TRUE(m.recall_at_1.has_value());
  }
}

TEST(PrecomputedRun, AMisalignedFileStopsTheRunNamingDatasetAndFile) {
  const TempTree tree;
  const ExperimentConfig config =
      parse_experiment_config(experiment(nlohmann::json::array({"referee"})));
  const auto query = open_sequence(config.datasets.front().query);
  std::vector<ScanRecord> shifted(query->records().begin() + 1, query->records().end());
  std::vector<DescriptorValue> values(shifted.size(), DescriptorValue{2, 1, {1.0f, 2.0f}});
  write_session(tree.path("single/query"), shifted, values);
  const nlohmann::json precomputed = {
      {"name", "precomputed"},
      {"params",
       {{"values", (tree.root() / "{dataset}/{role}/values.npy").string()},
        {"timestamps", (tree.root() / "{dataset}/{role}/timestamps.npy").string()}}}};
  nlohmann::json json = experiment(nlohmann::json::array({precomputed}));
  json["datasets"].erase(1);
  try {
    run_experiment(parse_experiment_config(json), false);
    FAIL() << "expected the missing row to stop the run";
  } catch (const std::exception& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("dataset 'single' (query)"), std::string::npos) << message;
    EXPECT_NE(message.find("1 of 60 scans have no row"), std::string::npos) << message;
    EXPECT_NE(message.find("values.npy"), std::string::npos) << message;
  }
}

// The values file rewritten in place (same size, same modification time): the next run evaluates
// the new values, as a run on a fresh copy of them does, never the old ones (precomputed values
// are read on every run; nothing is kept of them between runs). For a .npy and for a CSV.
TEST(PrecomputedRun, AValuesFileChangedInPlaceIsNeverAnsweredWithItsOldValues) {
  const TempTree tree;
  nlohmann::json json = experiment(nlohmann::json::array({"referee"}));
  json["datasets"].erase(1);
  const ExperimentConfig config = parse_experiment_config(json);
  const ExperimentRun referee = run_experiment(config, false);
  export_descriptor_values(config, tree.path("export"), false);
  const NpyFile exported = NpyFile::open(tree.path("export/single/query/referee.npy"));
  const std::vector<float> values = exported.as_floats();
  const std::size_t rows = exported.shape()[0];
  const std::size_t width = exported.shape()[1];
  const std::vector<std::int64_t> times =
      NpyFile::open(tree.path("export/single/query/timestamps.npy")).as_int64s();
  // The same rows in reverse scan order: another, equally sized set of values.
  std::vector<float> reversed;
  for (std::size_t row = rows; row-- > 0;) {
    reversed.insert(reversed.end(), values.begin() + static_cast<std::ptrdiff_t>(row * width),
                    values.begin() + static_cast<std::ptrdiff_t>((row + 1) * width));
  }
  auto write_values = [&](const std::filesystem::path& path, const std::vector<float>& flat) {
    if (path.extension() == ".npy") {
      write_npy(path, {rows, width}, std::span<const float>(flat));
      return;
    }
    std::ofstream csv(path, std::ios::trunc);
    csv << "timestamp";
    for (std::size_t c = 0; c < width; ++c) csv << ",v" << c;
    csv << "\n";
    for (std::size_t row = 0; row < rows; ++row) {
      csv << times[row];
      for (std::size_t c = 0; c < width; ++c)
        csv << "," << fmt::format("{}", flat[row * width + c]);
      csv << "\n";
    }
  };
  auto run_on = [&](const std::filesystem::path& path) {
    nlohmann::json params = {{"values", path.string()}};
    if (path.extension() == ".npy") {
      params["timestamps"] = tree.path("export/single/query/timestamps.npy").string();
    }
    nlohmann::json with_values = json;
    with_values["descriptors"] = {{{"name", "precomputed"}, {"params", params}}};
    return run_experiment(parse_experiment_config(with_values), false)
        .datasets.front()
        .descriptors.front()
        .evaluation.metrics;
  };
  for (const std::string name : {"values.npy", "values.csv"}) {
    const std::filesystem::path path = tree.path(name);
    write_values(path, values);
    const Metrics first = run_on(path);
    EXPECT_EQ(first.roc_auc,
              referee.datasets.front().descriptors.front().evaluation.metrics.roc_auc)
        << name;
    const auto size = std::filesystem::file_size(path);
    const auto modified = std::filesystem::last_write_time(path);
    write_values(path, reversed);
    ASSERT_EQ(std::filesystem::file_size(path), size) << name;
    std::filesystem::last_write_time(path, modified);
    const Metrics changed = run_on(path);
    write_values(tree.path("fresh_" + name), reversed);
    const Metrics fresh = run_on(tree.path("fresh_" + name));
    EXPECT_EQ(changed.roc_auc, fresh.roc_auc) << name;
    EXPECT_EQ(changed.correct_top1, fresh.correct_top1) << name;
    EXPECT_EQ(changed.f1_max, fresh.f1_max) << name;
    EXPECT_NE(changed.correct_top1, first.correct_top1) << name;
  }
}

// In a session matrix, `precomputed` reads each session's values from its files ({dataset} is the
// matrix's name, {role} the session's): referee's values exported and read back this way give
// referee's metrics for every pair exactly. A study cannot split such a descriptor into units.
TEST(PrecomputedRun, ASessionMatrixReadsEachSessionsValuesAndReproducesTheDescriptor) {
  const TempTree tree;
  nlohmann::json json = nlohmann::json::parse(R"({
    "experiment": "precomputed_matrix_test",
    "datasets": [{"kind": "session_matrix", "name": "town", "sessions": [
      {"name": "clear", "sequence": {"type": "synthetic", "seed": 5, "session": 1, "scans": 30,
        "azimuths": 120, "range_bins": 210, "range_resolution_m": 0.476, "route_blocks_x": 1, "speed_mps": 40}},
      {"name": "rain", "sequence": {"type": "synthetic", "seed": 5, "session": 2, "scans": 40,
        "weather": "rain", "azimuths": 120, "range_bins": 210, "range_resolution_m": 0.476, "route_blocks_x": 1, "speed_mps": 40}}]}],
    "descriptors": ["referee"],
    "protocol": {"exclude_recent_frames": 10, "revisit_radius_m": 10, "recall_at_k": [1, 3]}
  })");
  const ExperimentConfig config = parse_experiment_config(json);
  const ExperimentRun referee = run_experiment(config, false);
  export_descriptor_values(config, tree.path("export"), false);
  // The export is per pair; each session's files, once.
  for (const auto& [session, pair, role] :
       {std::tuple{"clear", "town.clear.rain", "query"}, {"rain", "town.clear.rain", "database"}}) {
    std::filesystem::create_directories(tree.path(std::string("town/") + session));
    for (const char* file : {"referee.npy", "timestamps.npy"}) {
      std::filesystem::copy_file(tree.path(fmt::format("export/{}/{}/{}", pair, role, file)),
                                 tree.path(fmt::format("town/{}/{}", session, file)));
    }
  }
  json["descriptors"] = {
      {{"name", "precomputed"},
       {"params",
        {{"values", (tree.root() / "{dataset}/{role}/referee.npy").string()},
         {"timestamps", (tree.root() / "{dataset}/{role}/timestamps.npy").string()}}}}};
  const ExperimentConfig replay_config = parse_experiment_config(json);
  const ExperimentRun replayed = run_experiment(replay_config, false);
  ASSERT_EQ(replayed.datasets.size(), referee.datasets.size());
  ASSERT_EQ(referee.datasets.size(), 2u);
  for (std::size_t d = 0; d < referee.datasets.size(); ++d) {
    const Metrics& m = referee.datasets[d].descriptors.front().evaluation.metrics;
    const Metrics& n = replayed.datasets[d].descriptors.front().evaluation.metrics;
    EXPECT_EQ(m.queries, n.queries) << d;
    EXPECT_EQ(m.correct_top1, n.correct_top1) << d;
    EXPECT_EQ(m.roc_auc, n.roc_auc) << d;
    EXPECT_EQ(m.f1_max, n.f1_max) << d;
    EXPECT_EQ(m.recall_at_k, n.recall_at_k) << d;
  }
  try {
    plan_units(replay_config, UnitCosts::skip);
    FAIL() << "a study planned units for precomputed values";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("radarpr run"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace radarpr
