// The descriptor cache in the runner: a re-run after a protocol change decodes no scan and trains
// nothing and gives the same numbers; a changed sequence is re-extracted (only it); descriptors
// outside the registry are never cached; a damaged entry is recomputed; real PNG folders are
// invalidated by their files' stamps.
#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <unistd.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "datasets/cache_directory.hpp"
#include "datasets/dataset_types.hpp"
#include "datasets/real/polar_png_sequence.hpp"
#include "datasets/synthetic/synthetic_sequence.hpp"
#include "descriptors/opencv_image.hpp"
#include "evaluation/config/experiment_config.hpp"
#include "evaluation/descriptor_values.hpp"
#include "evaluation/experiment_runner.hpp"
#include "tests/evaluation/counting_sequence.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

using testing::count_loads;

// Points the process's cache at a fresh folder for one test (or turns it off).
class ScopedCache {
 public:
  ScopedCache() {
    static std::atomic<int> counter{0};
    root_ =
        fs::temp_directory_path() / ("radarpr_pipeline_cache_test_" + std::to_string(::getpid()) +
                                     "_" + std::to_string(counter++));
    fs::remove_all(root_);
    override_cache_directory(root_);
  }
  ~ScopedCache() {
    override_cache_directory(std::nullopt);
    std::error_code ignored;
    fs::remove_all(root_, ignored);
  }
  const fs::path& root() const { return root_; }

 private:
  fs::path root_;
};

// A single session of 40 scans and a multi session of 20 against 30, coarse scans (120 x 210; the
// Oxford layout needs more range bins than azimuths - 11) so the test is quick, driven fast (10 m
// between scans) so that the 320 m loop is revisited; referee and a small Open-RadVLAD
// (trainable: learns from the database session).
nlohmann::json experiment() {
  return nlohmann::json::parse(R"({
    "experiment": "pipeline_cache_test",
    "datasets": [
      {"name": "single", "query": {"type": "synthetic", "seed": 5, "scans": 40,
        "azimuths": 120, "range_bins": 210, "range_resolution_m": 0.476, "route_blocks_x": 1, "speed_mps": 40}},
      {"name": "multi",
       "query": {"type": "synthetic", "seed": 5, "session": 1, "scans": 20,
        "azimuths": 120, "range_bins": 210, "range_resolution_m": 0.476, "route_blocks_x": 1, "speed_mps": 40},
       "database": {"type": "synthetic", "seed": 5, "session": 2, "scans": 30,
        "azimuths": 120, "range_bins": 210, "range_resolution_m": 0.476, "route_blocks_x": 1, "speed_mps": 40}}
    ],
    "descriptors": ["referee",
      {"name": "open_radvlad", "params": {"min_bin": 10, "bin_dim": 8, "clusters": 4,
        "max_iterations": 5}}],
    "protocol": {"exclude_recent_frames": 10, "revisit_radius_m": 10, "recall_at_k": [1, 3]}
  })");
}

struct Counters {
  std::atomic<std::size_t> single{0};
  std::atomic<std::size_t> query{0};
  std::atomic<std::size_t> database{0};
  void reset() {
    single = 0;
    query = 0;
    database = 0;
  }
};

ExperimentConfig counted_config(const nlohmann::json& json, Counters& counters) {
  ExperimentConfig config = parse_experiment_config(json);
  count_loads(config.datasets[0].query, counters.single);
  count_loads(config.datasets[1].query, counters.query);
  count_loads(*config.datasets[1].database, counters.database);
  return config;
}

// Same matches at the same distances, query by query.
void expect_same_results(const ExperimentRun& actual, const ExperimentRun& expected) {
  ASSERT_EQ(actual.datasets.size(), expected.datasets.size());
  for (std::size_t s = 0; s < expected.datasets.size(); ++s) {
    const auto& a = actual.datasets[s].descriptors;
    const auto& e = expected.datasets[s].descriptors;
    ASSERT_EQ(a.size(), e.size());
    for (std::size_t d = 0; d < e.size(); ++d) {
      const auto& ar = a[d].evaluation.results;
      const auto& er = e[d].evaluation.results;
      ASSERT_EQ(ar.size(), er.size()) << e[d].id;
      for (std::size_t q = 0; q < er.size(); ++q) {
        EXPECT_EQ(ar[q].match, er[q].match) << e[d].id << " query " << q;
        EXPECT_EQ(ar[q].distance, er[q].distance) << e[d].id << " query " << q;
      }
      EXPECT_EQ(a[d].evaluation.metrics.roc_auc, e[d].evaluation.metrics.roc_auc) << e[d].id;
    }
  }
}

TEST(PipelineCache, ARunAfterAProtocolChangeDecodesNoScanAndTrainsNothing) {
  ScopedCache cache;
  Counters counters;
  const ExperimentRun first = run_experiment(counted_config(experiment(), counters), false);
  // Extraction decodes each scan once; Open-RadVLAD's training loads every training scan again
  // (the single session trains on itself, the multi session on its database).
  EXPECT_EQ(counters.single, 40u + 40u);
  EXPECT_EQ(counters.query, 20u);
  EXPECT_EQ(counters.database, 30u + 30u);
  for (const auto& dataset : first.datasets) {
    EXPECT_FALSE(dataset.descriptors[0].query_values_cached);
    ASSERT_TRUE(dataset.descriptors[1].training.has_value());
    EXPECT_FALSE(dataset.descriptors[1].training->from_cache);
  }

  nlohmann::json changed = experiment();
  changed["protocol"]["revisit_radius_m"] = 15;
  changed["protocol"]["recall_at_k"] = {1, 2, 5};
  counters.reset();
  const ExperimentRun second = run_experiment(counted_config(changed, counters), false);
  EXPECT_EQ(counters.single, 0u);
  EXPECT_EQ(counters.query, 0u);
  EXPECT_EQ(counters.database, 0u);
  for (const auto& dataset : second.datasets) {
    for (const auto& descriptor : dataset.descriptors) {
      EXPECT_TRUE(descriptor.query_values_cached) << descriptor.id;
      EXPECT_EQ(descriptor.database_values_cached, dataset.multi_session) << descriptor.id;
    }
    // Open-RadVLAD was not trained; the record is the first run's.
    const auto& training = dataset.descriptors[1].training;
    ASSERT_TRUE(training.has_value());
    EXPECT_TRUE(training->from_cache);
    EXPECT_EQ(training->scans, dataset.multi_session ? 30u : 40u);
    // The extraction time is the one measured when the values were extracted.
    EXPECT_GT(dataset.descriptors[0].mean_extract_ms, 0.0);
  }
  EXPECT_EQ(second.datasets[0].descriptors[0].mean_extract_ms,
            first.datasets[0].descriptors[0].mean_extract_ms);

  // The cached values give exactly what freshly extracted ones give.
  override_cache_directory(fs::path("off"));
  const ExperimentRun uncached = run_experiment(counted_config(changed, counters), false);
  override_cache_directory(cache.root());
  expect_same_results(second, uncached);
}

// In a single session the runner memory-maps the cached values of exhaustive_l2 descriptors
// (Open-RadVLAD) instead of reading them, so that their search holds a block at a time: the
// re-run in the test above went that way and equals the uncached run. Other descriptors, other
// sessions and other callers read the values.
TEST(PipelineCache, CachedSingleSessionL2ValuesAreMappedNotRead) {
  ScopedCache cache;
  Counters counters;
  const ExperimentConfig config = counted_config(experiment(), counters);
  run_experiment(config, false);
  const DatasetConfig& dataset = config.datasets[0];
  const auto query = open_sequence(dataset.query);
  const DescriptorCache entries = DescriptorCache::from_environment();
  const DatasetValues mapped =
      obtain_dataset_values(config, dataset, *query, nullptr, entries, false, {}, true);
  EXPECT_EQ(mapped.query[0].mapped, nullptr);  // referee: a KD-tree over keys read in memory
  EXPECT_EQ(mapped.query[0].values.size(), 40u);
  ASSERT_NE(mapped.query[1].mapped, nullptr);
  EXPECT_TRUE(mapped.query[1].values.empty());
  EXPECT_TRUE(mapped.query[1].from_cache);
  EXPECT_EQ(mapped.query[1].mapped->size(), 40u);
  EXPECT_TRUE(mapped.training[1].has_value());

  const DatasetValues read =
      obtain_dataset_values(config, dataset, *query, nullptr, entries, false, {}, false);
  EXPECT_EQ(read.query[1].mapped, nullptr);
  ASSERT_EQ(read.query[1].values.size(), 40u);
  const std::vector<DescriptorValue> in_map = mapped.query[1].mapped->read(0, 40);
  for (std::size_t i = 0; i < 40; ++i) EXPECT_EQ(in_map[i].values, read.query[1].values[i].values);
}

TEST(PipelineCache, AChangedSessionIsReExtractedAndOnlyWhatDependsOnItRetrained) {
  ScopedCache cache;
  Counters counters;
  run_experiment(counted_config(experiment(), counters), false);

  nlohmann::json changed = experiment();
  changed["datasets"][1]["database"]["scans"] = 32;
  counters.reset();
  const ExperimentRun run = run_experiment(counted_config(changed, counters), false);
  EXPECT_EQ(counters.single, 0u);
  // The new database is extracted and Open-RadVLAD retrained on it (32 + 32 loads); the query
  // session's referee values are still valid, its Open-RadVLAD values (from the old codebook)
  // are not: 20 loads.
  EXPECT_EQ(counters.database, 32u + 32u);
  EXPECT_EQ(counters.query, 20u);
  const DatasetRun& multi = run.datasets[1];
  EXPECT_TRUE(multi.descriptors[0].query_values_cached);
  EXPECT_FALSE(multi.descriptors[0].database_values_cached);
  EXPECT_FALSE(multi.descriptors[1].query_values_cached);
  EXPECT_FALSE(multi.descriptors[1].database_values_cached);
  ASSERT_TRUE(multi.descriptors[1].training.has_value());
  EXPECT_FALSE(multi.descriptors[1].training->from_cache);
  EXPECT_EQ(multi.descriptors[1].training->scans, 32u);
}

// Reports the image mean; not in the registry, so its id says nothing about what it computes.
class MeanOfScan final : public Descriptor {
 public:
  DescriptorValue extract(const PolarImage& scan) const override {
    return {1, 1, {static_cast<float>(cv::mean(opencv_view(scan.power))[0])}};
  }
  double distance(const DescriptorValue& a, const DescriptorValue& b) const override {
    return std::abs(double(a.values[0]) - b.values[0]);
  }
  bool rotation_invariant() const override { return true; }
  DescriptorShape shape(const ScanGeometry&) const override { return {1, 1}; }
};

TEST(PipelineCache, DescriptorsOutsideTheRegistryAreNeverCached) {
  ScopedCache cache;
  Counters counters;
  nlohmann::json json = experiment();
  json["descriptors"] = {"referee"};
  for (int run = 0; run < 2; ++run) {
    ExperimentConfig config = counted_config(json, counters);
    // An id that a registered descriptor could have: still not trusted.
    DescriptorInstance fake;
    fake.id = "referee:alpha=7";
    fake.name = "mean_of_scan";
    fake.descriptor = std::make_shared<MeanOfScan>();
    config.descriptors = {fake};
    counters.reset();
    const ExperimentRun result = run_experiment(config, false);
    EXPECT_EQ(counters.single, 40u) << "run " << run;
    EXPECT_FALSE(result.datasets[0].descriptors[0].query_values_cached);
  }
  EXPECT_FALSE(fs::exists(cache.root() / "descriptors" / "mean_of_scan"));
  EXPECT_FALSE(fs::exists(cache.root() / "descriptors" / "referee"));
}

TEST(PipelineCache, ADamagedEntryIsWarnedAndRecomputedWithTheSameResults) {
  ScopedCache cache;
  Counters counters;
  nlohmann::json json = experiment();
  json["descriptors"] = {"referee"};
  const ExperimentRun first = run_experiment(counted_config(json, counters), false);
  std::size_t damaged = 0;
  for (const auto& entry : fs::recursive_directory_iterator(cache.root() / "descriptors")) {
    if (!entry.is_regular_file() || entry.path().extension() != ".npy") continue;
    std::fstream file(entry.path(), std::ios::in | std::ios::out | std::ios::binary);
    file.seekp(-12, std::ios::end);  // inside the last value
    file.put('\x7f');
    ++damaged;
  }
  EXPECT_EQ(damaged, 3u);  // single, multi query, multi database
  counters.reset();
  ::testing::internal::CaptureStderr();
  const ExperimentRun second = run_experiment(counted_config(json, counters), false);
  const std::string errors = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(errors.find("checksum mismatch; recomputing"), std::string::npos) << errors;
  EXPECT_EQ(counters.single, 40u);
  EXPECT_EQ(counters.query, 20u);
  EXPECT_EQ(counters.database, 30u);
  expect_same_results(second, first);
  // Repaired: the next run reads them.
  counters.reset();
  run_experiment(counted_config(json, counters), false);
  EXPECT_EQ(counters.single + counters.query + counters.database, 0u);
}

// A folder dataset of PNGs rendered from a synthetic drive, in the native layout (one row per
// range bin: more range bins than azimuths, so that the layout is told from the shape), with
// its poses.
class PngFolder {
 public:
  explicit PngFolder(int scans) {
    static std::atomic<int> counter{0};
    root_ = fs::temp_directory_path() / ("radarpr_pipeline_png_" + std::to_string(::getpid()) +
                                         "_" + std::to_string(counter++));
    fs::remove_all(root_);
    fs::create_directories(root_ / "drive" / "scans");
    SyntheticConfig config;
    config.seed = 5;
    config.scan_count = scans;
    config.radar.range_bin_count = 840;
    config.radar.range_resolution_m = 0.119;
    config.drive.route_blocks_x = 1;
    config.drive.speed_mps = 40.0;
    const SyntheticSequence drive(config);
    std::ofstream poses(root_ / "drive" / "poses.csv");
    poses << "timestamp,x,y,yaw\n";
    for (std::size_t i = 0; i < drive.size(); ++i) {
      const ScanRecord& record = drive.records()[i];
      const std::string name = fmt::format("{}.png", record.timestamp_ns);
      files_.push_back(root_ / "drive" / "scans" / name);
      cv::imwrite(files_.back().string(), opencv_view(transposed(drive.load_image(i).power)));
      poses << fmt::format("{},{},{},{}\n", record.timestamp_ns, record.pose.x, record.pose.y,
                           record.pose.yaw);
    }
  }
  ~PngFolder() {
    std::error_code ignored;
    fs::remove_all(root_, ignored);
  }
  const fs::path& root() const { return root_; }
  const std::vector<fs::path>& files() const { return files_; }

 private:
  fs::path root_;
  std::vector<fs::path> files_;
};

TEST(PipelineCache, RealFoldersAreReadFromTheCacheUntilAFileChanges) {
  ScopedCache cache;
  const PngFolder folder(40);
  nlohmann::json json = experiment();
  json["datasets"] = nlohmann::json::array();
  json["datasets"].push_back({{"name", "folder"},
                              {"query",
                               {{"type", "folder"},
                                {"root", folder.root().string()},
                                {"sequence", "drive"},
                                {"range_resolution_m", 0.119}}}});
  json["descriptors"] = {"referee"};
  const ExperimentConfig config = parse_experiment_config(json);

  const std::size_t before_first = PolarPngSequence::decodes_in_process();
  const ExperimentRun first = run_experiment(config, false);
  // Every scan once, plus the first scan each time the sequence is opened (the check before the
  // run and the run itself): opening decodes it to fix A x R and the report.
  EXPECT_EQ(PolarPngSequence::decodes_in_process() - before_first, 40u + 2u);

  nlohmann::json changed = json;
  changed["protocol"]["revisit_radius_m"] = 15;
  const std::size_t before_second = PolarPngSequence::decodes_in_process();
  const ExperimentRun second = run_experiment(parse_experiment_config(changed), false);
  EXPECT_EQ(PolarPngSequence::decodes_in_process() - before_second, 2u);  // the openings only
  EXPECT_TRUE(second.datasets[0].descriptors[0].query_values_cached);

  // A scan rewritten in place (same name, same size, new time): the fingerprint changes.
  const fs::path touched = folder.files()[7];
  fs::last_write_time(touched, fs::last_write_time(touched) + std::chrono::seconds(5));
  const std::size_t before_third = PolarPngSequence::decodes_in_process();
  const ExperimentRun third = run_experiment(config, false);
  EXPECT_EQ(PolarPngSequence::decodes_in_process() - before_third, 40u + 2u);
  EXPECT_FALSE(third.datasets[0].descriptors[0].query_values_cached);
  expect_same_results(third, first);
}

}  // namespace
}  // namespace radarpr
