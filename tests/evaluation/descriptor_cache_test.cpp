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
#include <nlohmann/json.hpp>

#include "datasets/npy_file.hpp"
#include "evaluation/version.hpp"

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
  values.timestamps_ns = {1'700'000'000'000'000'000, 1'700'000'000'250'000'000,
                          1'700'000'000'500'000'000};
  return values;
}

std::size_t files_in(const fs::path& folder) {
  return static_cast<std::size_t>(
      std::distance(fs::directory_iterator(folder), fs::directory_iterator()));
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
  EXPECT_EQ(loaded->timestamps_ns, stored.timestamps_ns);
  EXPECT_TRUE(recording.warnings.empty());
  // Under <root>/descriptors/<name>/: a sidecar and its values, no temporary file left behind.
  const fs::path entry = recording.cache.entry_path(sample_key());
  const fs::path values = recording.cache.values_path(sample_key());
  EXPECT_EQ(entry.parent_path(), folder.root() / "descriptors" / "referee_r");
  EXPECT_EQ(entry.extension(), ".json");
  EXPECT_EQ(values.parent_path(), entry.parent_path());
  EXPECT_EQ(values.stem(), entry.stem());
  EXPECT_EQ(values.extension(), ".npy");
  EXPECT_EQ(files_in(entry.parent_path()), 2u);
}

// The values are a plain .npy (count x rows x cols float32) any reader opens, and the sidecar
// says what they are.
TEST(DescriptorCache, AnEntryIsANpyFileAndAJsonSidecar) {
  CacheFolder folder;
  RecordingCache recording(folder.root());
  CachedDescriptorValues stored = sample_values();
  stored.training = TrainingRecord{"synthetic(seed=7,session=0)", 600, 120, 3.25};
  ASSERT_TRUE(recording.cache.store(sample_key(), stored));

  const NpyFile npy = NpyFile::open(recording.cache.values_path(sample_key()));
  EXPECT_EQ(npy.dtype(), NpyDtype::float32);
  EXPECT_EQ(npy.shape(), (std::vector<std::size_t>{3, 2, 3}));
  const std::vector<float> elements = npy.as_floats();
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(
        std::memcmp(elements.data() + 6 * i, stored.values[i].values.data(), 6 * sizeof(float)), 0)
        << "value " << i;
  }

  const auto sidecar = nlohmann::json::parse(read_bytes(recording.cache.entry_path(sample_key())));
  EXPECT_EQ(sidecar.at("format"), "radarpr descriptor values");
  EXPECT_EQ(sidecar.at("format_version"), 3);
  EXPECT_EQ(sidecar.at("descriptor"), sample_key().descriptor_id);
  EXPECT_EQ(sidecar.at("sequence_fingerprint"), sample_key().sequence_fingerprint);
  EXPECT_EQ(sidecar.at("training_key"), "");
  EXPECT_EQ(sidecar.at("radarpr_version"), std::string(radarpr_version()));
  EXPECT_EQ(sidecar.at("radarpr_build"), descriptor_cache_build_identity());
  EXPECT_EQ(sidecar.at("values_file"),
            recording.cache.values_path(sample_key()).filename().string());
  EXPECT_EQ(sidecar.at("dtype"), "float32");
  EXPECT_EQ(sidecar.at("shape"), nlohmann::json({3, 2, 3}));
  EXPECT_EQ(sidecar.at("values_bytes"), fs::file_size(recording.cache.values_path(sample_key())));
  EXPECT_EQ(sidecar.at("mean_extract_ms"), 12.5);
  EXPECT_EQ(sidecar.at("training").at("scans"), 600);
  EXPECT_EQ(sidecar.at("timestamps_ns").get<std::vector<std::int64_t>>(), stored.timestamps_ns);
  EXPECT_EQ(sidecar.at("checksum").get<std::string>().size(), 16u);
}

// Fingerprints name files, and file names are bytes: a key that is not UTF-8 is stored and found
// again, and one differing only in such a byte is another key.
TEST(DescriptorCache, KeysThatAreNotUtf8RoundTrip) {
  CacheFolder folder;
  RecordingCache recording(folder.root());
  DescriptorCacheKey key = sample_key();
  key.sequence_fingerprint = "folder(dr\xffve\nline)";
  ASSERT_TRUE(recording.cache.store(key, sample_values()));
  EXPECT_TRUE(recording.cache.load(key, 3).has_value());
  DescriptorCacheKey other = key;
  other.sequence_fingerprint = "folder(dr\xfeve\nline)";
  fs::copy_file(recording.cache.entry_path(key), recording.cache.entry_path(other));
  fs::copy_file(recording.cache.values_path(key), recording.cache.values_path(other));
  CacheLookup outcome = CacheLookup::hit;
  EXPECT_FALSE(recording.cache.load(other, 3, &outcome).has_value());
  EXPECT_EQ(outcome, CacheLookup::corrupt);
  EXPECT_TRUE(recording.warnings.size() == 1 &&
              recording.warnings[0].find("another key") != std::string::npos);
}

// An entry of the binary format before the .npy one is never read: a quiet miss (recomputed), and
// storing the key again removes it.
TEST(DescriptorCache, AnEntryOfTheOlderBinaryFormatIsStaleAndReplaced) {
  CacheFolder folder;
  RecordingCache recording(folder.root());
  fs::path old_entry = recording.cache.entry_path(sample_key());
  old_entry.replace_extension(".bin");
  fs::create_directories(old_entry.parent_path());
  write_bytes(old_entry, std::string("RPRDVALS") + std::string(200, '\x01'));
  CacheLookup outcome = CacheLookup::hit;
  std::string problem;
  EXPECT_FALSE(recording.cache.map(sample_key(), 3, &outcome, &problem).has_value());
  EXPECT_EQ(outcome, CacheLookup::stale);
  EXPECT_NE(problem.find(old_entry.string()), std::string::npos) << problem;
  EXPECT_FALSE(recording.cache.load(sample_key(), 3, &outcome).has_value());
  EXPECT_TRUE(recording.warnings.empty());
  ASSERT_TRUE(recording.cache.store(sample_key(), sample_values()));
  EXPECT_FALSE(fs::exists(old_entry));
  EXPECT_TRUE(recording.cache.load(sample_key(), 3).has_value());
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

// The damages a cache entry is checked against: of the values file and of the sidecar, each with
// the file it is done to.
struct Damage {
  std::string what;
  fs::path file;
  std::string bytes;
};

std::vector<Damage> damages_of(const DescriptorCache& cache) {
  const fs::path values = cache.values_path(sample_key());
  const fs::path sidecar = cache.entry_path(sample_key());
  const std::string good = read_bytes(values);
  const std::string good_sidecar = read_bytes(sidecar);
  std::string flipped = good;
  flipped[good.size() - 20] ^= 0x01;  // a bit of the last value
  std::string header_flipped = good;
  header_flipped[20] ^= 0x01;  // a bit of the .npy header
  std::string bad_magic = good;
  bad_magic[0] = 'X';
  std::string time_changed = good_sidecar;
  const auto digit = time_changed.find("1700000000250000000");
  time_changed[digit + 10] = '3';
  std::string ms_changed = good_sidecar;
  const auto ms = ms_changed.find("12.5");
  ms_changed[ms] = '2';
  std::string renamed = good_sidecar;
  renamed.replace(renamed.find(".npy\""), 5, ".npz\"");
  return {
      {"a flipped bit in the values", values, flipped},
      {"a flipped bit in the .npy header", values, header_flipped},
      {"a truncated values file", values, good.substr(0, good.size() - 9)},
      {"values cut in the middle", values, good.substr(0, good.size() / 2)},
      {"an empty values file", values, ""},
      {"one byte of values", values, good.substr(0, 1)},
      {"a foreign values file", values, bad_magic},
      {"trailing garbage after the values", values, good + "xyz"},
      {"a timestamp changed in the sidecar", sidecar, time_changed},
      {"the extraction time changed in the sidecar", sidecar, ms_changed},
      {"the sidecar names another values file", sidecar, renamed},
      {"a truncated sidecar", sidecar, good_sidecar.substr(0, good_sidecar.size() / 2)},
      {"an empty sidecar", sidecar, ""},
      {"a sidecar that is not an object", sidecar, "[1, 2, 3]"},
      {"a sidecar lacking the checksum", sidecar,
       [&] {
         auto json = nlohmann::json::parse(good_sidecar);
         json.erase("checksum");
         return json.dump();
       }()},
  };
}

// Each damage: the lookup misses with one warning naming the entry and the damaged file; a later
// store repairs it.
TEST(DescriptorCache, DamagedEntriesAreWarnedAndMissed) {
  CacheFolder folder;
  RecordingCache recording(folder.root());
  ASSERT_TRUE(recording.cache.store(sample_key(), sample_values()));
  const fs::path entry = recording.cache.entry_path(sample_key());
  const fs::path values = recording.cache.values_path(sample_key());
  const std::string good = read_bytes(values);
  const std::string good_sidecar = read_bytes(entry);
  for (const auto& [what, file, bytes] : damages_of(recording.cache)) {
    write_bytes(file, bytes);
    recording.warnings.clear();
    CacheLookup outcome = CacheLookup::hit;
    EXPECT_FALSE(recording.cache.load(sample_key(), 3, &outcome).has_value()) << what;
    EXPECT_EQ(outcome, CacheLookup::corrupt) << what;
    ASSERT_EQ(recording.warnings.size(), 1u) << what;
    EXPECT_NE(recording.warnings[0].find(entry.string()), std::string::npos)
        << recording.warnings[0];
    if (file == values) {
      EXPECT_NE(recording.warnings[0].find(values.string()), std::string::npos)
          << what << ": " << recording.warnings[0];
    }
    write_bytes(values, good);
    write_bytes(entry, good_sidecar);
    ASSERT_TRUE(recording.cache.load(sample_key(), 3).has_value()) << what;
  }
  fs::remove(values);
  recording.warnings.clear();
  CacheLookup outcome = CacheLookup::hit;
  EXPECT_FALSE(recording.cache.load(sample_key(), 3, &outcome).has_value());
  EXPECT_EQ(outcome, CacheLookup::corrupt);
  ASSERT_EQ(recording.warnings.size(), 1u);
  EXPECT_NE(recording.warnings[0].find(values.string() + " is missing"), std::string::npos)
      << recording.warnings[0];
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
  EXPECT_EQ(mapped->path(), recording.cache.values_path(sample_key()));
  EXPECT_EQ(mapped->timestamps_ns(), stored.timestamps_ns);
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

// A truncated, padded or damaged values file or sidecar is never mapped: map() says why, naming
// the file, and nothing crashes (the map is checked against the file's size before any value is
// read).
TEST(DescriptorCache, DamagedEntriesAreNeverMappedAndTheProblemNamesTheFile) {
  CacheFolder folder;
  RecordingCache recording(folder.root());
  ASSERT_TRUE(recording.cache.store(sample_key(), sample_values()));
  const fs::path entry = recording.cache.entry_path(sample_key());
  const fs::path values = recording.cache.values_path(sample_key());
  const std::string good = read_bytes(values);
  const std::string good_sidecar = read_bytes(entry);
  for (const auto& [what, file, bytes] : damages_of(recording.cache)) {
    write_bytes(file, bytes);
    CacheLookup outcome = CacheLookup::hit;
    std::string problem;
    EXPECT_FALSE(recording.cache.map(sample_key(), 3, &outcome, &problem).has_value()) << what;
    EXPECT_EQ(outcome, CacheLookup::corrupt) << what;
    EXPECT_NE(problem.find(file.string()), std::string::npos) << what << ": " << problem;
    EXPECT_NE(problem.find("unusable"), std::string::npos) << what << ": " << problem;
    write_bytes(values, good);
    write_bytes(entry, good_sidecar);
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
  fs::copy_file(recording.cache.values_path(other), recording.cache.values_path(sample_key()),
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
  const auto quoted = bytes.find("\"" + build + "\"");
  ASSERT_NE(quoted, std::string::npos);
  const auto at = quoted + 1;
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

// Processes sharing a cache folder write the same entry at once (equal keys give equal values;
// only what each measured differs): a reader always finds a whole entry, never a mixture or a
// warning, and no temporary file stays behind.
TEST(DescriptorCache, ConcurrentWritersLeaveOneWholeEntry) {
  CacheFolder folder;
  RecordingCache recording(folder.root());
  std::vector<std::thread> writers;
  for (int w = 0; w < 4; ++w) {
    writers.emplace_back([&recording, w] {
      CachedDescriptorValues values = sample_values();
      values.mean_extract_ms = w;
      for (auto& value : values.values) value.values.assign(value.values.size(), 5.0f);
      for (int repeat = 0; repeat < 20; ++repeat) recording.cache.store(sample_key(), values);
    });
  }
  // Reads before the first rename miss; every later one sees some writer's whole entry.
  for (int read = 0; read < 200; ++read) {
    const auto loaded = recording.cache.load(sample_key(), 3);
    if (!loaded) continue;
    EXPECT_GE(loaded->mean_extract_ms, 0.0);
    EXPECT_LE(loaded->mean_extract_ms, 3.0);
    for (const auto& value : loaded->values) {
      for (const float element : value.values) ASSERT_EQ(element, 5.0f);
    }
  }
  for (auto& writer : writers) writer.join();
  EXPECT_TRUE(recording.warnings.empty());
  EXPECT_TRUE(recording.cache.load(sample_key(), 3).has_value());
  const fs::path entry = recording.cache.entry_path(sample_key());
  EXPECT_EQ(files_in(entry.parent_path()), 2u);
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
