// Trainable descriptors in the runner: which scans they learn from, fresh instances per dataset,
// and the config keys that choose the training scans; also labels and declared shapes.
#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "descriptors/opencv_image.hpp"
#include "evaluation/config/config_error.hpp"
#include "evaluation/config/config_reader.hpp"
#include "evaluation/config/experiment_config.hpp"
#include "evaluation/descriptor_training.hpp"
#include "evaluation/experiment_runner.hpp"
#include "evaluation/results/results_writer.hpp"

namespace radarpr {
namespace {

// Learns the mean intensity of the first and last training scan and describes a scan by its
// mean minus that. Remembers where it learnt, so tests can see which sequence was used.
class MeanOffsetTrainable final : public Descriptor {
 public:
  DescriptorValue extract(const PolarImage& scan) const override {
    if (!trained_) throw std::logic_error("MeanOffsetTrainable is not trained");
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
    if (scans.size() < 2) throw std::invalid_argument("needs two scans");
    offset_ = (cv::mean(opencv_view(scans.load(0).power))[0] +
               cv::mean(opencv_view(scans.load(scans.size() - 1).power))[0]) /
              2.0;
    learnt_from = scans.description();
    trained_ = true;
  }
  std::string learnt_from;

 private:
  bool trained_ = false;
  double offset_ = 0.0;
};

// Declares 2x1 but returns 1x1: a plugin bug the runner must catch.
class WrongShape final : public Descriptor {
 public:
  DescriptorValue extract(const PolarImage&) const override { return {1, 1, {0.0f}}; }
  double distance(const DescriptorValue&, const DescriptorValue&) const override { return 0.0; }
  bool rotation_invariant() const override { return false; }
  DescriptorShape shape(const ScanGeometry&) const override { return {2, 1}; }
};

DescriptorInstance fake_instance(std::string id,
                                 std::function<std::unique_ptr<Descriptor>()> make) {
  DescriptorInstance instance;
  instance.id = id;
  instance.name = id;
  instance.descriptor = make();
  instance.create_fresh = make;
  return instance;
}

nlohmann::json config_json(const std::string& train_on) {
  auto json = nlohmann::json::parse(R"({
    "experiment": "training_test",
    "datasets": [
      {"name": "single", "query": {"type": "synthetic", "seed": 3, "scans": 70,
        "azimuths": 120, "range_bins": 210, "range_resolution_m": 0.476, "route_blocks_x": 1}},
      {"name": "multi",
       "query": {"type": "synthetic", "seed": 3, "session": 1, "scans": 20,
        "azimuths": 120, "range_bins": 210, "range_resolution_m": 0.476, "route_blocks_x": 1},
       "database": {"type": "synthetic", "seed": 3, "session": 2, "scans": 30,
        "azimuths": 120, "range_bins": 210, "range_resolution_m": 0.476, "route_blocks_x": 1}}
    ],
    "descriptors": ["referee"],
    "protocol": {"exclude_recent_frames": 10}
  })");
  json["protocol"]["train_on"] = train_on;
  if (train_on == "training_sequence") {
    for (auto& dataset : json["datasets"]) {
      dataset["training"] = {{"type", "synthetic"},
                             {"seed", 3},
                             {"session", 9},
                             {"scans", 5},
                             {"azimuths", 120},
                             {"range_bins", 210},
                             {"range_resolution_m", 0.476},
                             {"route_blocks_x", 1}};
    }
  }
  return json;
}

std::string learnt_from(const DescriptorRun& run) {
  return run.training ? run.training->sequence : std::string("(untrained)");
}

TEST(Training, DefaultTrainsOnTheDatabaseSessionOrTheSequenceItself) {
  ExperimentConfig config = parse_experiment_config(config_json("database"));
  config.descriptors.push_back(
      fake_instance("mean_offset", [] { return std::make_unique<MeanOffsetTrainable>(); }));
  const ExperimentRun run = run_experiment(config, false);
  ASSERT_EQ(run.datasets.size(), 2u);
  // referee is not trainable: no training record.
  EXPECT_FALSE(run.datasets[0].descriptors[0].training.has_value());
  EXPECT_EQ(learnt_from(run.datasets[0].descriptors[1]), run.datasets[0].query_sequence);
  EXPECT_EQ(run.datasets[0].descriptors[1].training->scans, 70u);
  EXPECT_EQ(run.datasets[0].descriptors[1].training->loaded, 2u);  // the first and the last
  EXPECT_EQ(learnt_from(run.datasets[1].descriptors[1]), run.datasets[1].database_sequence);
  EXPECT_EQ(run.datasets[1].descriptors[1].training->scans, 30u);
  // The configured instance itself stays untrained: each dataset trains a fresh one.
  EXPECT_FALSE(config.descriptors[1].descriptor->is_trained());
}

TEST(Training, ANamedTrainingSequenceWhenTheProtocolSaysSo) {
  ExperimentConfig config = parse_experiment_config(config_json("training_sequence"));
  config.descriptors.push_back(
      fake_instance("mean_offset", [] { return std::make_unique<MeanOffsetTrainable>(); }));
  const ExperimentRun run = run_experiment(config, false);
  for (const auto& dataset : run.datasets) {
    const auto& training = dataset.descriptors[1].training;
    ASSERT_TRUE(training.has_value());
    EXPECT_NE(training->sequence.find("session=9"), std::string::npos) << training->sequence;
    EXPECT_EQ(training->scans, 5u);
  }
}

TEST(Training, TrainDescriptorsSharesTheOthersAndNamesFailures) {
  ExperimentConfig config = parse_experiment_config(config_json("database"));
  auto sequence = open_sequence(config.datasets[0].query);
  config.descriptors.push_back(
      fake_instance("mean_offset", [] { return std::make_unique<MeanOffsetTrainable>(); }));
  const TrainedDescriptors trained = train_descriptors(config.descriptors, *sequence, false);
  EXPECT_EQ(trained.instances[0].descriptor, config.descriptors[0].descriptor);
  EXPECT_NE(trained.instances[1].descriptor, config.descriptors[1].descriptor);
  EXPECT_TRUE(trained.instances[1].descriptor->is_trained());
  EXPECT_EQ(dynamic_cast<const MeanOffsetTrainable&>(*trained.instances[1].descriptor).learnt_from,
            sequence->name());

  config.datasets[0].query =
      parse_sequence_config(ConfigReader(nlohmann::json{{"type", "synthetic"},
                                                        {"scans", 1},
                                                        {"azimuths", 120},
                                                        {"range_bins", 210},
                                                        {"range_resolution_m", 0.476},
                                                        {"route_blocks_x", 1}},
                                         "query"));
  const auto one_scan = open_sequence(config.datasets[0].query);
  try {
    train_descriptors(config.descriptors, *one_scan, false);
    FAIL() << "expected a training error";
  } catch (const std::runtime_error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("mean_offset"), std::string::npos) << message;
    EXPECT_NE(message.find(one_scan->name()), std::string::npos) << message;
    EXPECT_NE(message.find("needs two scans"), std::string::npos) << message;
  }
}

TEST(Training, ConfigKeysAreCheckedBothWays) {
  auto missing = config_json("training_sequence");
  missing["datasets"][1].erase("training");
  try {
    parse_experiment_config(missing);
    FAIL() << "expected a ConfigError";
  } catch (const ConfigError& error) {
    EXPECT_NE(std::string(error.what()).find("datasets.1"), std::string::npos) << error.what();
  }
  auto unused = config_json("training_sequence");
  unused["protocol"].erase("train_on");
  try {
    parse_experiment_config(unused);
    FAIL() << "expected a ConfigError";
  } catch (const ConfigError& error) {
    EXPECT_NE(std::string(error.what()).find("datasets.0.training"), std::string::npos)
        << error.what();
  }
  auto typo = config_json("database");
  typo["protocol"]["train_on"] = "databse";
  EXPECT_THROW(parse_experiment_config(typo), ConfigError);
  EXPECT_EQ(protocol_to_json(parse_experiment_config(config_json("database")).protocol)["train_on"],
            "database");
}

TEST(Labels, NameTableRowsAndMustBeUnique) {
  auto json = config_json("database");
  json["datasets"].erase(1);
  json["descriptors"] = nlohmann::json::parse(
      R"([{"name": "referee", "label": "ReFeree"}, {"name": "referee_r", "label": "R-ReFeree"}])");
  const ExperimentConfig config = parse_experiment_config(json);
  EXPECT_EQ(config.descriptors[0].display_name(), "ReFeree");
  const ExperimentRun run = run_experiment(config, false);
  // Table I and II as summary.md shows them.
  const std::string table = summary_markdown(config, run);
  EXPECT_NE(table.find("| ReFeree |"), std::string::npos) << table;
  EXPECT_NE(table.find("| single AUC | single F1-max |"), std::string::npos) << table;
  EXPECT_NE(table.find("| ReFeree | `referee` | 50x1 | float32 | 200 | 528 | no |"),
            std::string::npos)
      << table;

  json["descriptors"][1]["label"] = "ReFeree";
  EXPECT_THROW(parse_experiment_config(json), ConfigError);
}

TEST(DeclaredShape, AValueThatDisagreesStopsTheRun) {
  auto json = config_json("database");
  json["datasets"].erase(1);
  ExperimentConfig config = parse_experiment_config(json);
  config.descriptors = {
      fake_instance("wrong_shape", [] { return std::make_unique<WrongShape>(); })};
  try {
    run_experiment(config, false);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("declares shape 2x1"), std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace radarpr
