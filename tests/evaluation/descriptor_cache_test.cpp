// The descriptor cache on its own: entries round-trip bit for bit, every key part selects its own
// entry, and a damaged, mismatched or foreign entry is a warning and a miss, never a crash or a
// wrong value.
#include "evaluation/descriptor_cache.hpp"

#include <atomic>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

namespace radarpr {
namespace {

namespace fs = std::filesystem;

// A fresh cache folder per test, removed afterwards.
class CacheFolder {
 public:
  CacheFolder() {
    static std::atomic<int> counter{0};
    root_ =
        fs::temp_directory_path() / ("radarpr_descriptor_cache_test_" + std::to_string(::getpid()) +
                                     "_" + std::to_string(counter++));
    fs::remove_all(root_);
  }
  ~CacheFolder() {
    std::error_code ignored;
    fs::remove_all(root_, ignored);
  }
  const fs::path& root() const { return root_; }

 private:
  fs::path root_;
};

// A cache that records its warnings instead of printing them.
struct RecordingCache {
  explicit RecordingCache(const fs::path& root)
      : cache(root, [this](const std::string& message) { warnings.push_back(message); }) {}
  std::vector<std::string> warnings;
  DescriptorCache cache;
};

DescriptorCacheKey sample_key() {
  return {"referee_r:kernel=box,z_q=3", "synthetic-v3(seed=7,session=0,scans=3)", ""};
}

// Three 2 x 3 values with awkward floats (negative zero, a denormal, the largest float).
CachedDescriptorValues sample_values() {
  CachedDescriptorValues values;
  values.mean_extract_ms = 12.5;
  for (int scan = 0; scan < 3; ++scan) {
    DescriptorValue value{2, 3, {}};
    for (int i = 0; i < 6; ++i) value.values.push_back(static_cast<float>(scan * 10 + i) / 7.0f);
    values.values.push_back(value);
  }
  values.values[1].values[0] = -0.0f;
  values.values[1].values[1] = std::numeric_limits<float>::denorm_min();
  values.values[2].values[5] = std::numeric_limits<float>::max();
  return values;
}

std::string read_bytes(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

void write_bytes(const fs::path& path, const std::string& bytes) {
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  file << bytes;
}

void expect_bitwise_equal(const std::vector<DescriptorValue>& actual,
                          const std::vector<DescriptorValue>& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(actual[i].rows, expected[i].rows);
    EXPECT_EQ(actual[i].cols, expected[i].cols);
    ASSERT_EQ(actual[i].values.size(), expected[i].values.size());
    EXPECT_EQ(std::memcmp(actual[i].values.data(), expected[i].values.data(),
                          expected[i].values.size() * sizeof(float)),
              0)
        << "value " << i;
  }
}

TEST(DescriptorCache, RoundTripsValuesBitForBitWithTimeAndTraining) {
  CacheFolder folder;
  RecordingCache recording(folder.root());
  CachedDescriptorValues stored = sample_values();
  stored.training = TrainingRecord{"synthetic(seed=7,session=0)", 600, 120, 3.25};
  ASSERT_TRUE(recording.cache.store(sample_key(), stored));

  CacheLookup outcome = CacheLookup::miss;
  const auto loaded = recording.cache.load(sample_key(), 3, &outcome);
  ASSERT_TRUE(loaded.has_value());
  EXPECT_EQ(outcome, CacheLookup::hit);
  expect_bitwise_equal(loaded->values, stored.values);
  EXPECT_EQ(loaded->mean_extract_ms, 12.5);
  ASSERT_TRUE(loaded->training.has_value());
  EXPECT_EQ(loaded->training->sequence, "synthetic(seed=7,session=0)");
  EXPECT_EQ(loaded->training->scans, 600u);
  EXPECT_EQ(loaded->training->loaded, 120u);
  EXPECT_EQ(loaded->training->seconds, 3.25);
  EXPECT_TRUE(loaded->training->from_cache);  // this run trained nothing
  EXPECT_TRUE(recording.warnings.empty());
  // Under <root>/descriptors/<name>/, and no temporary file left behind.
  const fs::path entry = recording.cache.entry_path(sample_key());
  EXPECT_EQ(entry.parent_path(), folder.root() / "descriptors" / "referee_r");
  EXPECT_EQ(std::distance(fs::directory_iterator(entry.parent_path()), fs::directory_iterator()),
            1);
}

TEST(DescriptorCache, EveryKeyPartSelectsItsOwnEntry) {
  CacheFolder folder;
  RecordingCache recording(folder.root());
  ASSERT_TRUE(recording.cache.store(sample_key(), sample_values()));
  DescriptorCacheKey other_id = sample_key();
  other_id.descriptor_id = "referee_r:kernel=box,z_q=4";
  DescriptorCacheKey other_sequence = sample_key();
  other_sequence.sequence_fingerprint += "x";
  DescriptorCacheKey other_training = sample_key();
  other_training.training = "train_on=database;fingerprint=abc";
  for (const auto& key : {other_id, other_sequence, other_training}) {
    CacheLookup outcome = CacheLookup::hit;
    EXPECT_FALSE(recording.cache.load(key, 3, &outcome).has_value()) << key.text();
    EXPECT_EQ(outcome, CacheLookup::miss) << key.text();
    EXPECT_NE(recording.cache.entry_path(key), recording.cache.entry_path(sample_key()));
  }
  EXPECT_TRUE(recording.warnings.empty());
}

TEST(DescriptorCache, OffMeansNoReadsAndNoWrites) {
  std::vector<std::string> warnings;
  const DescriptorCache off(std::nullopt,
                            [&](const std::string& message) { warnings.push_back(message); });
  EXPECT_FALSE(off.enabled());
  EXPECT_FALSE(off.store(sample_key(), sample_values()));
  CacheLookup outcome = CacheLookup::hit;
  EXPECT_FALSE(off.load(sample_key(), 3, &outcome).has_value());
  EXPECT_EQ(outcome, CacheLookup::miss);
  EXPECT_TRUE(warnings.empty());
}

// Each damage: the lookup misses with one warning naming the entry; a later store repairs it.
TEST(DescriptorCache, DamagedEntriesAreWarnedAndMissed) {
  CacheFolder folder;
  RecordingCache recording(folder.root());
  ASSERT_TRUE(recording.cache.store(sample_key(), sample_values()));
  const fs::path entry = recording.cache.entry_path(sample_key());
  const std::string good = read_bytes(entry);

  std::string flipped = good;
  flipped[good.size() - 20] ^= 0x01;  // a bit of the last value
  std::string bad_magic = good;
  bad_magic[0] = 'X';
  const std::vector<std::pair<std::string, std::string>> damages = {
      {"a flipped bit in the values", flipped},
      {"a truncated file", good.substr(0, good.size() - 9)},
      {"an empty file", ""},
      {"one byte", good.substr(0, 1)},
      {"a foreign file", bad_magic},
      {"trailing garbage", good + "xyz"},
  };
  for (const auto& [what, bytes] : damages) {
    write_bytes(entry, bytes);
    recording.warnings.clear();
    CacheLookup outcome = CacheLookup::hit;
    EXPECT_FALSE(recording.cache.load(sample_key(), 3, &outcome).has_value()) << what;
    EXPECT_EQ(outcome, CacheLookup::corrupt) << what;
    ASSERT_EQ(recording.warnings.size(), 1u) << what;
    EXPECT_NE(recording.warnings[0].find(entry.string()), std::string::npos)
        << recording.warnings[0];
  }
  ASSERT_TRUE(recording.cache.store(sample_key(), sample_values()));
  EXPECT_TRUE(recording.cache.load(sample_key(), 3).has_value());
}

// The memory-mapped reading an evaluate unit uses: the same values a block at a time, the same
// header facts, and in-place comparison for constant values.
TEST(DescriptorCache, MappedEntriesReadTheSameValuesABlockAtATime) {
  CacheFolder folder;
  RecordingCache recording(folder.root());
  CachedDescriptorValues stored = sample_values();
  stored.training = TrainingRecord{"synthetic(seed=7,session=0)", 600, 120, 3.25};
  ASSERT_TRUE(recording.cache.store(sample_key(), stored));
  CacheLookup outcome = CacheLookup::miss;
  std::string problem = "untouched";
  const auto mapped = recording.cache.map(sample_key(), 3, &outcome, &problem);
  ASSERT_TRUE(mapped.has_value()) << problem;
  EXPECT_EQ(outcome, CacheLookup::hit);
  EXPECT_TRUE(problem.empty());
  EXPECT_EQ(mapped->size(), 3u);
  EXPECT_EQ(mapped->rows(), 2);
  EXPECT_EQ(mapped->cols(), 3);
  EXPECT_EQ(mapped->value_bytes(), 6 * sizeof(float));
  EXPECT_EQ(mapped->mean_extract_ms(), 12.5);
  ASSERT_TRUE(mapped->training().has_value());
  EXPECT_EQ(mapped->training()->scans, 600u);
  EXPECT_EQ(mapped->path(), recording.cache.entry_path(sample_key()));
  expect_bitwise_equal(mapped->read(0, 3), stored.values);
  const std::vector<DescriptorValue> middle = mapped->read(1, 2);
  expect_bitwise_equal(middle, {stored.values[1]});
  EXPECT_TRUE(mapped->read(2, 2).empty());
  EXPECT_THROW(mapped->read(2, 4), std::out_of_range);
  EXPECT_FALSE(mapped->all_equal());
  EXPECT_TRUE(recording.warnings.empty());

  CachedDescriptorValues constant = sample_values();
  constant.values[1] = constant.values[0];
  constant.values[2] = constant.values[0];
  ASSERT_TRUE(recording.cache.store(sample_key(), constant));
  // The entry was replaced by a rename: the map opened before still reads the old one.
  expect_bitwise_equal(mapped->read(0, 3), stored.values);
  const auto remapped = recording.cache.map(sample_key(), 3);
  ASSERT_TRUE(remapped.has_value());
  EXPECT_TRUE(remapped->all_equal());
}

// A truncated, padded or damaged values file is never mapped: map() says why, naming the file,
// and nothing crashes (the map is checked against the file's size before any value is read).
TEST(DescriptorCache, DamagedEntriesAreNeverMappedAndTheProblemNamesTheFile) {
  CacheFolder folder;
  RecordingCache recording(folder.root());
  ASSERT_TRUE(recording.cache.store(sample_key(), sample_values()));
  const fs::path entry = recording.cache.entry_path(sample_key());
  const std::string good = read_bytes(entry);
  std::string flipped = good;
  flipped[good.size() - 20] ^= 0x01;
  const std::vector<std::pair<std::string, std::string>> damages = {
      {"a flipped bit in the values", flipped},
      {"a truncated file", good.substr(0, good.size() - 9)},
      {"values cut in the middle", good.substr(0, good.size() / 2)},
      {"an empty file", ""},
      {"the magic only", good.substr(0, 8)},
      {"trailing garbage", good + "xyz"},
  };
  for (const auto& [what, bytes] : damages) {
    write_bytes(entry, bytes);
    CacheLookup outcome = CacheLookup::hit;
    std::string problem;
    EXPECT_FALSE(recording.cache.map(sample_key(), 3, &outcome, &problem).has_value()) << what;
    EXPECT_EQ(outcome, CacheLookup::corrupt) << what;
    EXPECT_NE(problem.find(entry.string()), std::string::npos) << what << ": " << problem;
    EXPECT_NE(problem.find("unusable"), std::string::npos) << what << ": " << problem;
  }
  EXPECT_TRUE(recording.warnings.empty());  // map() leaves warning to its caller

  fs::remove(entry);
  CacheLookup outcome = CacheLookup::hit;
  std::string problem;
  EXPECT_FALSE(recording.cache.map(sample_key(), 3, &outcome, &problem).has_value());
  EXPECT_EQ(outcome, CacheLookup::miss);
  EXPECT_NE(problem.find(entry.string()), std::string::npos) << problem;
}

// The sequence now has another scan count than the entry: the fingerprint should have changed,
// so the entry is not trusted.
TEST(DescriptorCache, AnEntryForAnotherScanCountIsMissedWithAWarning) {
  CacheFolder folder;
  RecordingCache recording(folder.root());
  ASSERT_TRUE(recording.cache.store(sample_key(), sample_values()));
  CacheLookup outcome = CacheLookup::hit;
  EXPECT_FALSE(recording.cache.load(sample_key(), 4, &outcome).has_value());
  EXPECT_EQ(outcome, CacheLookup::corrupt);
  ASSERT_EQ(recording.warnings.size(), 1u);
  EXPECT_NE(recording.warnings[0].find("3 values for a sequence of 4 scans"), std::string::npos)
      << recording.warnings[0];
}

// An entry holding another key at this key's file name (a hash collision or a hand-copied file).
TEST(DescriptorCache, AnEntryOfAnotherKeyIsNeverReturned) {
  CacheFolder folder;
  RecordingCache recording(folder.root());
  DescriptorCacheKey other = sample_key();
  other.descriptor_id = "referee_r";
  ASSERT_TRUE(recording.cache.store(other, sample_values()));
  fs::create_directories(recording.cache.entry_path(sample_key()).parent_path());
  fs::copy_file(recording.cache.entry_path(other), recording.cache.entry_path(sample_key()),
                fs::copy_options::overwrite_existing);
  CacheLookup outcome = CacheLookup::hit;
  EXPECT_FALSE(recording.cache.load(sample_key(), 3, &outcome).has_value());
  EXPECT_EQ(outcome, CacheLookup::corrupt);
  ASSERT_EQ(recording.warnings.size(), 1u);
  EXPECT_NE(recording.warnings[0].find("another key"), std::string::npos);
}

// Entries of another build may hold values of other descriptor code: recomputed quietly.
TEST(DescriptorCache, AnEntryOfAnotherBuildIsStale) {
  CacheFolder folder;
  RecordingCache recording(folder.root());
  ASSERT_TRUE(recording.cache.store(sample_key(), sample_values()));
  const fs::path entry = recording.cache.entry_path(sample_key());
  std::string bytes = read_bytes(entry);
  const std::string& build = descriptor_cache_build_identity();
  const auto at = bytes.find(build);
  ASSERT_NE(at, std::string::npos);
  bytes[at] = bytes[at] == '1' ? '2' : '1';  // same length, another build
  write_bytes(entry, bytes);
  CacheLookup outcome = CacheLookup::hit;
  EXPECT_FALSE(recording.cache.load(sample_key(), 3, &outcome).has_value());
  EXPECT_EQ(outcome, CacheLookup::stale);
  EXPECT_TRUE(recording.warnings.empty());
}

TEST(DescriptorCache, ValuesOfSeveralShapesOrNoneAreNotStored) {
  CacheFolder folder;
  RecordingCache recording(folder.root());
  CachedDescriptorValues mixed = sample_values();
  mixed.values[2] = DescriptorValue{3, 2, mixed.values[2].values};
  EXPECT_FALSE(recording.cache.store(sample_key(), mixed));
  EXPECT_EQ(recording.warnings.size(), 1u);
  EXPECT_FALSE(recording.cache.store(sample_key(), CachedDescriptorValues{}));
  EXPECT_FALSE(fs::exists(recording.cache.entry_path(sample_key())));
}

TEST(DescriptorCache, AnUnwritableFolderIsAWarningNotAnError) {
  CacheFolder folder;
  fs::create_directories(folder.root());
  std::ofstream(folder.root() / "descriptors") << "a file where the folder should be";
  RecordingCache recording(folder.root());
  EXPECT_FALSE(recording.cache.store(sample_key(), sample_values()));
  ASSERT_EQ(recording.warnings.size(), 1u);
  EXPECT_FALSE(recording.cache.load(sample_key(), 3).has_value());
}

// Processes sharing a cache folder write the same entry at once: a reader always finds a whole
// entry (one writer's), never a mixture, and no temporary file stays behind.
TEST(DescriptorCache, ConcurrentWritersLeaveOneWholeEntry) {
  CacheFolder folder;
  RecordingCache recording(folder.root());
  std::vector<std::thread> writers;
  for (int w = 0; w < 4; ++w) {
    writers.emplace_back([&recording, w] {
      CachedDescriptorValues values = sample_values();
      values.mean_extract_ms = w;
      for (auto& value : values.values) value.values.assign(value.values.size(), float(w));
      for (int repeat = 0; repeat < 20; ++repeat) recording.cache.store(sample_key(), values);
    });
  }
  // Reads before the first rename miss; every later one sees some writer's whole entry.
  for (int read = 0; read < 200; ++read) {
    const auto loaded = recording.cache.load(sample_key(), 3);
    if (!loaded) continue;
    const float w = static_cast<float>(loaded->mean_extract_ms);
    for (const auto& value : loaded->values) {
      for (const float element : value.values) ASSERT_EQ(element, w);
    }
  }
  for (auto& writer : writers) writer.join();
  EXPECT_TRUE(recording.warnings.empty());
  EXPECT_TRUE(recording.cache.load(sample_key(), 3).has_value());
  const fs::path entry = recording.cache.entry_path(sample_key());
  EXPECT_EQ(std::distance(fs::directory_iterator(entry.parent_path()), fs::directory_iterator()),
            1);
}

TEST(DescriptorCache, ChecksumChangesWithAnyByteAndContinuesFromItsSeed) {
  // Every length up to two words, so the tail of every size is covered.
  const std::string text = "0123456789abcdef!";
  for (std::size_t size = 0; size <= text.size(); ++size) {
    std::string changed = text.substr(0, size);
    const std::uint64_t base = cache_checksum(changed.data(), changed.size());
    for (std::size_t i = 0; i < size; ++i) {
      changed[i] ^= 0x20;
      EXPECT_NE(cache_checksum(changed.data(), changed.size()), base) << size << " " << i;
      changed[i] ^= 0x20;
    }
    // A zero byte appended is a different input.
    const std::string longer = changed + std::string(1, '\0');
    EXPECT_NE(cache_checksum(longer.data(), longer.size()), base) << size;
  }
  const std::uint64_t first = cache_checksum("ab", 2);
  EXPECT_NE(cache_checksum("cd", 2, first), cache_checksum("cd", 2));
}

}  // namespace
}  // namespace radarpr
