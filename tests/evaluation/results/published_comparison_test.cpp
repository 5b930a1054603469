// A paper's published tables beside a run (docs/paper-table.md): the file is read and checked,
// the config names which dataset stands for which published column, and the differences are
// worked by hand on a constructed run.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "evaluation/config/config_error.hpp"
#include "evaluation/config/experiment_config.hpp"
#include "evaluation/config/published_tables.hpp"
#include "evaluation/results/published_comparison.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

// Two descriptors x two published datasets; B's AUC on "far" is unknown.
nlohmann::json two_by_two() {
  return nlohmann::json::parse(R"({
    "source": "A paper, Table 1 and 2.",
    "table_1": {
      "datasets": ["near", "far"],
      "descriptors": ["A", "B"],
      "values": {
        "A": {"near": {"auc": 0.9, "f1_max": 0.8}, "far": {"auc": 0.75, "f1_max": 0.6}},
        "B": {"near": {"auc": 0.5, "f1_max": 0.4}, "far": {"auc": null, "f1_max": 0.2}}
      }
    },
    "table_2": {"rows": [{"descriptor": "A", "shape": [2, 3], "bytes": 100,
                          "convention": "a float64 file"},
                         {"descriptor": "B", "shape": [4, 1], "bytes": null}]}
  })");
}

class PublishedComparison : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() / ("radarpr_published_" + std::to_string(::getpid()));
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }

  fs::path write(const std::string& name, const std::string& text) {
    const fs::path file = folder_ / name;
    std::ofstream(file) << text;
    return file;
  }

  // The error message reading `json` gives.
  std::string error_of(const nlohmann::json& json) {
    const fs::path file = write("bad.json", json.dump());
    try {
      read_published_tables(file);
    } catch (const std::runtime_error& error) {
      return error.what();
    }
    return "";
  }

  fs::path folder_;
};

TEST_F(PublishedComparison, ReadsTheFileAndKeepsUnknownValuesUnknown) {
  const PublishedTables tables = read_published_tables(write("t.json", two_by_two().dump()));
  EXPECT_EQ(tables.source, "A paper, Table 1 and 2.");
  EXPECT_EQ(tables.datasets, (std::vector<std::string>{"near", "far"}));
  EXPECT_EQ(tables.table_1.at("A").at("far").auc, 0.75);
  EXPECT_FALSE(tables.table_1.at("B").at("far").auc.has_value());
  ASSERT_EQ(tables.table_2.size(), 2u);
  EXPECT_EQ(tables.table_2[0].shape, (std::vector<int>{2, 3}));
  EXPECT_EQ(tables.table_2[0].bytes, 100);
  EXPECT_FALSE(tables.table_2[1].bytes.has_value());
}

TEST_F(PublishedComparison, BadFilesAreNamedWithWhatWasExpected) {
  auto json = two_by_two();
  json["table_1"]["values"]["A"]["near"]["auc"] = 1.5;
  EXPECT_NE(error_of(json).find("'table_1.values.A.near.auc' must be null (unknown) or a number "
                                "in [0, 1]"),
            std::string::npos)
      << error_of(json);
  json = two_by_two();
  json["table_1"]["values"]["B"].erase("far");
  EXPECT_NE(error_of(json).find("expected the key 'table_1.values.B.far'"), std::string::npos);
  json = two_by_two();
  json.erase("source");
  EXPECT_NE(error_of(json).find("bad.json: expected the key 'source'"), std::string::npos);
  EXPECT_THROW(read_published_tables(write("broken.json", "{")), std::runtime_error);
  EXPECT_THROW(read_published_tables(folder_ / "missing.json"), std::runtime_error);
}

nlohmann::json config_with(const nlohmann::json& published) {
  auto config = nlohmann::json::parse(R"({
    "experiment": "unit",
    "datasets": [{"name": "one", "query": {"type": "synthetic", "seed": 3, "scans": 40}},
                 {"name": "two", "query": {"type": "synthetic", "seed": 4, "scans": 40}},
                 {"name": "three", "query": {"type": "synthetic", "seed": 5, "scans": 40}}],
    "descriptors": [{"name": "referee", "label": "A"}, {"name": "referee_r", "label": "C"}]
  })");
  config["published"] = published;
  return config;
}

std::string blamed_path(const nlohmann::json& config, const fs::path& folder) {
  try {
    parse_experiment_config(config, folder);
  } catch (const ConfigError& error) {
    return error.key_path();
  }
  return "";
}

TEST_F(PublishedComparison, TheConfigNamesKnownDatasetsAndPublishedColumns) {
  write("t.json", two_by_two().dump());
  const nlohmann::json good = {{"tables", "t.json"},
                               {"datasets", {{"one", "near"}, {"two", "far"}, {"three", "far"}}}};
  const ExperimentConfig config = parse_experiment_config(config_with(good), folder_);
  ASSERT_TRUE(config.published.has_value());
  EXPECT_EQ(config.published->datasets.size(), 3u);

  auto bad = good;
  bad["datasets"]["four"] = "near";
  EXPECT_EQ(blamed_path(config_with(bad), folder_), "published.datasets.four");
  bad = good;
  bad["datasets"]["one"] = "nearby";
  EXPECT_EQ(blamed_path(config_with(bad), folder_), "published.datasets.one");
  bad = good;
  bad["tables"] = "missing.json";
  EXPECT_EQ(blamed_path(config_with(bad), folder_), "published.tables");
  bad = good;
  bad["colour"] = "red";
  EXPECT_EQ(blamed_path(config_with(bad), folder_), "published.colour");
}

DescriptorRun descriptor_run(double auc, std::optional<double> f1_max, int rows) {
  DescriptorRun run;
  run.rows = rows;
  run.cols = 1;
  run.paper_bytes = static_cast<std::size_t>(rows) * 8 + 128;
  run.evaluation.metrics.roc_auc = auc;
  run.evaluation.metrics.f1_max = f1_max;
  return run;
}

// Run: A has AUC 0.95 on "one" (near), 0.5 and 1 on "two" and "three" (far: mean 0.75);
// F1-max 0.85 near, 0.5 and undefined far (mean of the defined: 0.5). Differences to the paper:
// AUC +0.05 near, 0 far; F1-max +0.05 near, -0.1 far. C is no row of the paper: left out.
TEST_F(PublishedComparison, DifferencesByHand) {
  write("t.json", two_by_two().dump());
  const ExperimentConfig config = parse_experiment_config(
      config_with({{"tables", "t.json"},
                   {"datasets", {{"one", "near"}, {"two", "far"}, {"three", "far"}}}}),
      folder_);
  ExperimentRun run;
  for (const auto& [name, auc, f1] :
       std::vector<std::tuple<std::string, double, std::optional<double>>>{
           {"one", 0.95, 0.85}, {"two", 0.5, 0.5}, {"three", 1.0, std::nullopt}}) {
    DatasetRun dataset;
    dataset.name = name;
    dataset.descriptors = {descriptor_run(auc, f1, 50), descriptor_run(0.5, 0.5, 21)};
    run.datasets.push_back(dataset);
  }
  const auto rows = published_comparison(config, run);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].descriptor, "A");
  EXPECT_EQ(rows[0].published_dataset, "near");
  EXPECT_NEAR(*rows[0].auc_difference(), 0.05, 1e-12);
  EXPECT_NEAR(*rows[0].f1_max_difference(), 0.05, 1e-12);
  EXPECT_EQ(rows[1].run_datasets, (std::vector<std::string>{"two", "three"}));
  EXPECT_EQ(*rows[1].run_auc, 0.75);
  EXPECT_EQ(*rows[1].auc_difference(), 0.0);
  EXPECT_NEAR(*rows[1].run_f1_max, 0.5, 1e-12);
  EXPECT_NEAR(*rows[1].f1_max_difference(), -0.1, 1e-12);

  const std::string md = published_comparison_markdown(config, run);
  EXPECT_NE(md.find("| A | near | one | 0.900 | 0.950 | +0.050 | 0.800 | 0.850 | +0.050 |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| A | far | two, three | 0.750 | 0.750 | +0.000 | 0.600 | 0.500 | -0.100 |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| A | 2x3 | 50x1 | 100 | 528 | +428 | a float64 file |"), std::string::npos)
      << md;
  EXPECT_EQ(md.find("| C |"), std::string::npos) << md;
  const std::string csv = published_comparison_csv(config, run);
  EXPECT_NE(csv.find("A,far,two;three,0.75,0.75,0,0.6,0.5,"), std::string::npos) << csv;

  // A paper value that is unknown gives n/a, never a made-up difference.
  auto unknown = config;
  unknown.descriptors[0].label = "B";
  const auto b_rows = published_comparison(unknown, run);
  ASSERT_EQ(b_rows.size(), 2u);
  EXPECT_FALSE(b_rows[1].auc_difference().has_value());
  EXPECT_NE(published_comparison_markdown(unknown, run)
                .find("| B | far | two, three | n/a | "
                      "0.750 | n/a |"),
            std::string::npos);
  // No published tables: nothing is written.
  EXPECT_EQ(published_comparison_markdown(ExperimentConfig{}, run), "");
}

}  // namespace
}  // namespace radarpr
