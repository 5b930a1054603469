// A run reads synthetic scans through the cache and the real datasets' decoder and loader: the
// images and records are the same with no cache, a cold cache and a warm one, and a damaged or
// foreign cache is never read as if it were right.
#include "datasets/synthetic/cached_synthetic_sequence.hpp"

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "datasets/cache_directory.hpp"
#include "datasets/synthetic/radar/radar_presets.hpp"
#include "tests/datasets/dataset_tree.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;
using test::TempTree;

SyntheticConfig tiny_config(std::uint64_t seed = 7) {
  SyntheticConfig config;
  config.seed = seed;
  config.scan_count = 6;
  config.radar = synthetic::radar_preset("tiny");
  config.world.traffic = 0.5;
  return config;
}

// Points the cache at `directory` (or switches it off) until destroyed; then the environment's
// choice again (so scopes do not nest).
class CacheAt {
 public:
  explicit CacheAt(const fs::path& directory) { override_cache_directory(directory); }
  ~CacheAt() { override_cache_directory(std::nullopt); }
};

// The sequence as --no-cache gives it: rendered in memory, nothing written.
std::unique_ptr<ScanSequence> open_uncached(const SyntheticConfig& config) {
  const CacheAt off("off");
  return open_synthetic(config);
}

void expect_same_scans(const ScanSequence& a, const ScanSequence& b) {
  EXPECT_EQ(a.fingerprint(), b.fingerprint());
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a.records()[i].timestamp_ns, b.records()[i].timestamp_ns) << i;
    EXPECT_EQ(a.records()[i].pose.x, b.records()[i].pose.x) << i;  // exact, not near
    EXPECT_EQ(a.records()[i].pose.y, b.records()[i].pose.y) << i;
    EXPECT_EQ(a.records()[i].pose.yaw, b.records()[i].pose.yaw) << i;
    const PolarImage x = a.load_image(i);
    const PolarImage y = b.load_image(i);
    EXPECT_TRUE(x.power == y.power) << i;
    EXPECT_EQ(x.azimuths_rad, y.azimuths_rad) << i;
    EXPECT_EQ(x.azimuth_times_ns, y.azimuth_times_ns) << i;
  }
}

// Loads every scan once, as a run does, so that the cache folder is complete.
void fill(const ScanSequence& sequence) {
  for (std::size_t i = 0; i < sequence.size(); ++i) (void)sequence.load_image(i);
}

fs::path only_cache_folder(const fs::path& cache) {
  std::optional<fs::path> found;
  for (const auto& entry : fs::directory_iterator(cache / "synthetic")) {
    EXPECT_FALSE(found) << "more than one cache folder";
    found = entry.path();
  }
  return found.value_or(fs::path());
}

TEST(CachedSynthetic, NoCacheColdCacheAndWarmCacheGiveTheSameScans) {
  TempTree tree;
  const auto uncached = open_uncached(tiny_config());
  const CacheAt cache(tree.path("cache"));
  const auto cold = open_synthetic(tiny_config());
  expect_same_scans(*uncached, *cold);

  const fs::path folder = only_cache_folder(tree.path("cache"));
  ASSERT_TRUE(fs::exists(folder / "complete"));
  const auto warm = open_synthetic(tiny_config());
  // The folder loader read it: the sources are the cached files.
  EXPECT_EQ(fs::path(warm->records()[0].source).parent_path(), folder / "scans");
  EXPECT_EQ(warm->describe().type, "synthetic");
  expect_same_scans(*uncached, *warm);
  EXPECT_EQ(warm->name(), uncached->name());
}

TEST(CachedSynthetic, AnotherConfigGetsAnotherFolder) {
  TempTree tree;
  const CacheAt cache(tree.path("cache"));
  fill(*open_synthetic(tiny_config(7)));
  fill(*open_synthetic(tiny_config(8)));
  int folders = 0;
  for (const auto& entry : fs::directory_iterator(tree.path("cache/synthetic"))) {
    EXPECT_TRUE(fs::exists(entry.path() / "complete")) << entry.path();
    ++folders;
  }
  EXPECT_EQ(folders, 2);
}

TEST(CachedSynthetic, AnIncompleteFolderIsFilledAndThenUsed) {
  TempTree tree;
  const CacheAt cache(tree.path("cache"));
  const auto first = open_synthetic(tiny_config());
  (void)first->load_image(0);
  (void)first->load_image(3);
  const fs::path folder = only_cache_folder(tree.path("cache"));
  EXPECT_FALSE(fs::exists(folder / "complete"));
  const auto second = open_synthetic(tiny_config());  // finds two scans there
  fill(*second);
  EXPECT_TRUE(fs::exists(folder / "complete"));
  expect_same_scans(*first, *open_synthetic(tiny_config()));
}

TEST(CachedSynthetic, ADamagedOrMissingCachedScanIsRenderedAgain) {
  TempTree tree;
  const CacheAt cache(tree.path("cache"));
  const auto original = open_synthetic(tiny_config());
  fill(*original);
  const fs::path folder = only_cache_folder(tree.path("cache"));
  // Reopened, the complete folder is read by the folder loader: sources are the files.
  const fs::path damaged = open_synthetic(tiny_config())->records()[2].source;
  ASSERT_TRUE(fs::exists(damaged));
  fs::resize_file(damaged, fs::file_size(damaged) / 2);  // cut short
  const auto repaired = open_synthetic(tiny_config());   // warns, and renders scan 2 again
  expect_same_scans(*original, *repaired);
  EXPECT_TRUE(fs::exists(folder / "complete"));

  fs::remove(damaged);
  expect_same_scans(*original, *open_synthetic(tiny_config()));
  EXPECT_TRUE(fs::exists(damaged));
}

TEST(CachedSynthetic, AScanDamagedAfterOpeningIsRenderedAgain) {
  TempTree tree;
  const CacheAt cache(tree.path("cache"));
  const auto original = open_synthetic(tiny_config());
  fill(*original);
  const auto warm = open_synthetic(tiny_config());  // the folder loader, headers checked
  const fs::path damaged = warm->records()[4].source;
  fs::resize_file(damaged, fs::file_size(damaged) / 2);
  expect_same_scans(*original, *warm);
  EXPECT_NO_THROW(open_synthetic(tiny_config()));  // repaired on disk too
}

TEST(CachedSynthetic, ACacheThatStopsTakingWritesCostsTheCacheNotTheRun) {
  TempTree tree;
  const auto uncached = open_uncached(tiny_config());
  const CacheAt cache(tree.path("cache"));
  const auto sequence = open_synthetic(tiny_config());
  const fs::path scans = only_cache_folder(tree.path("cache")) / "scans";
  fs::remove_all(scans);
  std::ofstream(scans) << "a file where the scans folder was";
  expect_same_scans(*uncached, *sequence);
}

TEST(CachedSynthetic, AnUnwritableCacheFallsBackToMemory) {
  TempTree tree;
  std::ofstream(tree.path("not_a_folder")) << "x";
  const CacheAt cache(tree.path("not_a_folder"));
  const auto sequence = open_synthetic(tiny_config());
  EXPECT_NE(sequence->describe().layout.find("memory"), std::string::npos);
  EXPECT_EQ(sequence->load_image(1).azimuth_count(), 120);
}

}  // namespace
}  // namespace radarpr
