// Session matrices: the config expands into one multi-session dataset per ordered pair; each
// session is decoded once whatever the number of pairs, a trainable descriptor is trained once per
// database session; every pair gives what the same pair as an ordinary dataset gives; the
// aggregate over pairs and the per-pair table carry the pairs' values.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "datasets/cache_directory.hpp"
#include "descriptors/opencv_image.hpp"
#include "evaluation/config/config_error.hpp"
#include "evaluation/config/experiment_config.hpp"
#include "evaluation/experiment_runner.hpp"
#include "evaluation/results/session_matrix_tables.hpp"
#include "tests/evaluation/counting_sequence.hpp"

namespace radarpr {
namespace {

// Learns the mean intensity of the first and last training scan; counts its trainings.
class CountingTrainable final : public Descriptor {
 public:
  explicit CountingTrainable(std::atomic<int>& trainings) : trainings_(trainings) {}
  DescriptorValue extract(const PolarImage& scan) const override {
    if (!trained_) throw std::logic_error("CountingTrainable is not trained");
    return {1, 1, {static_cast<float>(cv::mean(opencv_view(scan.power))[0] - offset_)}};
  }
  double distance(const DescriptorValue& a, const DescriptorValue& b) const override {
    return std::abs(double(a.values[0]) - b.values[0]);
  }
  bool rotation_invariant() const override { return true; }
  DescriptorShape shape(const ScanGeometry&) const override { return {1, 1}; }
  bool trainable() const override { return true; }
  bool is_trained() const override { return trained_; }
  void train(const TrainingScans& scans) override {
    ++trainings_;
    offset_ = (cv::mean(opencv_view(scans.load(0).power))[0] +
               cv::mean(opencv_view(scans.load(scans.size() - 1).power))[0]) /
              2.0;
    trained_ = true;
  }

 private:
  std::atomic<int>& trainings_;
  bool trained_ = false;
  double offset_ = 0.0;
};

// Four sessions of one small town (coarse scans so the test is quick), differing in weather,
// traffic and parked cars.
nlohmann::json matrix_experiment(const nlohmann::json& pairs = "all") {
  nlohmann::json json = nlohmann::json::parse(R"({
    "experiment": "session_matrix_test",
    "datasets": [{"kind": "session_matrix", "name": "town", "sessions": []}],
    "descriptors": ["referee", "referee_r"],
    "protocol": {"revisit_radius_m": 10, "recall_at_k": [1, 3]}
  })");
  const nlohmann::json base = nlohmann::json::parse(R"({"type": "synthetic", "seed": 5,
      "scans": 20, "azimuths": 120, "range_bins": 210, "range_resolution_m": 0.476,
      "route_blocks_x": 1, "speed_mps": 40})");
  const std::vector<std::pair<std::string, nlohmann::json>> sessions = {
      {"clear", {{"session", 0}}},
      {"rain", {{"session", 1}, {"weather", "rain"}}},
      {"busy", {{"session", 2}, {"traffic", 0.9}}},
      {"parked", {{"session", 3}, {"parked_car_churn", 0.8}}}};
  for (const auto& [name, changes] : sessions) {
    nlohmann::json sequence = base;
    sequence.update(changes);
    json["datasets"][0]["sessions"].push_back({{"name", name}, {"sequence", sequence}});
  }
  json["datasets"][0]["pairs"] = pairs;
  return json;
}

class NoCache {
 public:
  NoCache() { override_cache_directory("off"); }
  ~NoCache() { override_cache_directory(std::nullopt); }
};

TEST(SessionMatrixConfig, AllPairsExpandIntoOrderedMultiSessionDatasets) {
  const ExperimentConfig config = parse_experiment_config(matrix_experiment());
  ASSERT_EQ(config.matrices.size(), 1u);
  EXPECT_EQ(config.matrices[0].sessions.size(), 4u);
  ASSERT_EQ(config.datasets.size(), 12u);
  EXPECT_EQ(config.datasets[0].name, "town.clear.rain");
  EXPECT_EQ(config.datasets[1].name, "town.clear.busy");
  EXPECT_EQ(config.datasets[3].name, "town.rain.clear");
  for (const auto& dataset : config.datasets) {
    EXPECT_TRUE(dataset.multi_session());
    ASSERT_TRUE(dataset.matrix_pair.has_value());
    EXPECT_NE(dataset.matrix_pair->query, dataset.matrix_pair->database);
  }
}

TEST(SessionMatrixConfig, ListedPairsAndTheirErrors) {
  const ExperimentConfig config = parse_experiment_config(
      matrix_experiment(nlohmann::json::parse(R"([{"query": "rain", "database": "clear"}])")));
  ASSERT_EQ(config.datasets.size(), 1u);
  EXPECT_EQ(config.datasets[0].name, "town.rain.clear");

  auto error_of = [](const nlohmann::json& json) {
    try {
      parse_experiment_config(json);
    } catch (const ConfigError& error) {
      return std::string(error.what());
    }
    return std::string("(no error)");
  };
  EXPECT_NE(error_of(matrix_experiment(
                         nlohmann::json::parse(R"([{"query": "snow", "database": "clear"}])")))
                .find("'snow' is not a session of matrix 'town'"),
            std::string::npos);
  EXPECT_NE(error_of(matrix_experiment(
                         nlohmann::json::parse(R"([{"query": "rain", "database": "rain"}])")))
                .find("with itself"),
            std::string::npos);
  EXPECT_NE(
      error_of(
          matrix_experiment(nlohmann::json::parse(
              R"([{"query": "rain", "database": "clear"}, {"query": "rain", "database": "clear"}])")))
          .find("listed twice"),
      std::string::npos);
  EXPECT_NE(error_of(matrix_experiment("some")).find("expected \"all\""), std::string::npos);
  nlohmann::json bad_kind = matrix_experiment();
  bad_kind["datasets"][0]["kind"] = "session_grid";
  EXPECT_NE(error_of(bad_kind).find("not a dataset kind"), std::string::npos);
  nlohmann::json one_session = matrix_experiment();
  auto& sessions = one_session["datasets"][0]["sessions"];
  sessions.erase(sessions.begin() + 1, sessions.end());
  EXPECT_NE(error_of(one_session).find("at least two sessions"), std::string::npos);
}

TEST(SessionMatrix, EachSessionIsDecodedOnceAndTrainedOncePerDatabaseSession) {
  const NoCache no_cache;  // nothing may come from an earlier run
  ExperimentConfig config = parse_experiment_config(matrix_experiment());
  std::atomic<std::size_t> loads{0};
  std::size_t scans = 0;
  for (auto& session : config.matrices[0].sessions) {
    scans += open_sequence(session.sequence)->size();
    testing::count_loads(session.sequence, loads);
  }
  std::atomic<int> trainings{0};
  DescriptorInstance trainable;
  trainable.id = trainable.name = "counting_trainable";
  trainable.create_fresh = [&trainings] { return std::make_unique<CountingTrainable>(trainings); };
  trainable.descriptor = trainable.create_fresh();
  config.descriptors.push_back(trainable);

  const ExperimentRun run = run_experiment(config, false);
  ASSERT_EQ(run.datasets.size(), 12u);  // N(N-1) pairs of N = 4 sessions
  // Every session decoded once for all three descriptors and all the codebooks it is encoded
  // with, plus the two scans each of the four trainings loads: N extractions, N trainings.
  EXPECT_EQ(trainings.load(), 4);
  EXPECT_EQ(loads.load(), scans + 4 * 2);
  for (const auto& pair : run.datasets) {
    ASSERT_EQ(pair.descriptors.size(), 3u);
    ASSERT_TRUE(pair.descriptors[2].training.has_value());
    EXPECT_EQ(pair.descriptors[2].training->sequence, pair.database_sequence);
  }
}

TEST(SessionMatrix, APairGivesWhatTheSamePairAsAnOrdinaryDatasetGives) {
  const NoCache no_cache;
  const nlohmann::json json = matrix_experiment();
  const ExperimentConfig matrix_config = parse_experiment_config(json);
  const ExperimentRun matrix_run = run_experiment(matrix_config, false);

  nlohmann::json plain = json;
  const auto& sessions = json["datasets"][0]["sessions"];
  plain["datasets"] = {{{"name", "busy_on_parked"},
                        {"query", sessions[2]["sequence"]},
                        {"database", sessions[3]["sequence"]}}};
  const ExperimentRun plain_run = run_experiment(parse_experiment_config(plain), false);
  const auto it =
      std::find_if(matrix_run.datasets.begin(), matrix_run.datasets.end(),
                   [](const DatasetRun& run) { return run.name == "town.busy.parked"; });
  ASSERT_NE(it, matrix_run.datasets.end());
  ASSERT_EQ(it->descriptors.size(), plain_run.datasets[0].descriptors.size());
  for (std::size_t d = 0; d < it->descriptors.size(); ++d) {
    const auto& a = it->descriptors[d].evaluation;
    const auto& b = plain_run.datasets[0].descriptors[d].evaluation;
    ASSERT_EQ(a.results.size(), b.results.size());
    for (std::size_t q = 0; q < a.results.size(); ++q) {
      EXPECT_EQ(a.results[q].match, b.results[q].match);
      EXPECT_EQ(a.results[q].distance, b.results[q].distance);
    }
    EXPECT_EQ(a.metrics.roc_auc, b.metrics.roc_auc);
    EXPECT_EQ(a.metrics.recall_at_1, b.metrics.recall_at_1);
  }
}

TEST(SessionMatrix, TheAggregateAndThePairTableCarryThePairsValues) {
  const NoCache no_cache;
  const ExperimentConfig config = parse_experiment_config(matrix_experiment());
  const ExperimentRun run = run_experiment(config, false);
  const auto aggregates = aggregate_matrix(config, config.matrices[0], run);
  ASSERT_EQ(aggregates.size(), 2u);
  for (std::size_t d = 0; d < aggregates.size(); ++d) {
    std::vector<double> recalls;
    std::size_t without_revisit = 0;
    for (const auto& pair : run.datasets) {
      const Metrics& metrics = pair.descriptors[d].evaluation.metrics;
      if (metrics.recall_at_1) recalls.push_back(*metrics.recall_at_1);
      if (metrics.revisits == 0) ++without_revisit;
    }
    ASSERT_FALSE(recalls.empty());
    std::sort(recalls.begin(), recalls.end());
    const auto& recall = *std::find_if(aggregates[d].metrics.begin(), aggregates[d].metrics.end(),
                                       [](const auto& m) { return m.metric == "recall_at_1"; });
    EXPECT_EQ(recall.pairs, recalls.size());
    EXPECT_EQ(recall.pairs + recall.undefined, 12u);
    EXPECT_EQ(aggregates[d].pairs_without_revisit, without_revisit);
    EXPECT_EQ(*recall.min, recalls.front());
    EXPECT_EQ(*recall.max, recalls.back());
    double sum = 0.0;
    for (double value : recalls) sum += value;
    EXPECT_NEAR(*recall.mean, sum / static_cast<double>(recalls.size()), 1e-12);
    const std::size_t n = recalls.size();
    EXPECT_NEAR(*recall.median,
                n % 2 ? recalls[n / 2] : (recalls[n / 2 - 1] + recalls[n / 2]) / 2.0, 1e-12);
    EXPECT_EQ(aggregates[d].metrics.size(), matrix_metric_names(config.protocol).size());
  }
  const std::string pairs = matrix_pairs_csv(config, config.matrices[0], run);
  EXPECT_EQ(std::count(pairs.begin(), pairs.end(), '\n'),
            1 + 12 * 2);  // header, 12 pairs x 2 descriptors
  EXPECT_NE(pairs.find("rain,clear,town.rain.clear,referee,"), std::string::npos);
  const std::string markdown = matrix_summary_markdown(config, config.matrices[0], run);
  EXPECT_NE(markdown.find("## Session matrix town"), std::string::npos);
  EXPECT_NE(markdown.find("| parked | busy |"), std::string::npos);
}

}  // namespace
}  // namespace radarpr
