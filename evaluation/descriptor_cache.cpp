#include "evaluation/descriptor_cache.hpp"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <span>
#include <stdexcept>
#include <system_error>
#include <thread>
#include <utility>

#include <unistd.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "datasets/cache_directory.hpp"
#include "datasets/npy_file.hpp"
#include "datasets/stale_temporaries.hpp"
#include "datasets/warn_once.hpp"
#include "descriptors/learnt_codebook.hpp"
#include "evaluation/text_escaping.hpp"
#include "evaluation/version.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

// Bump when the entry layout changes; entries of another format are recomputed. 1 and 2 were one
// binary ".bin" file per entry; 3 is a .npy of the values and a JSON sidecar.
constexpr int kFormatVersion = 3;
constexpr char kFormatName[] = "radarpr descriptor values";
// A mapped entry is checked and compared this many bytes of values at a time, each block's pages
// let go before the next, so checking a large entry does not hold it in memory.
constexpr std::size_t kChecksumBlockBytes = std::size_t{64} << 20;

fs::path with_extension(fs::path path, const char* extension) {
  path.replace_extension(extension);
  return path;
}

std::string hex(std::uint64_t value) {
  return fmt::format("{:016x}", value);
}

nlohmann::json training_json(const std::optional<TrainingRecord>& training) {
  if (!training) return nullptr;
  return {{"sequence", training->sequence},
          {"scans", training->scans},
          {"loaded", training->loaded},
          {"seconds", training->seconds},
          {"codebook_sha256", training->codebook_sha256}};
}

std::optional<TrainingRecord> training_from(const nlohmann::json& json) {
  if (json.is_null()) return std::nullopt;
  TrainingRecord record;
  record.sequence = json.at("sequence").get<std::string>();
  record.scans = json.at("scans").get<std::size_t>();
  record.loaded = json.at("loaded").get<std::size_t>();
  record.seconds = json.at("seconds").get<double>();
  record.codebook_sha256 = json.at("codebook_sha256").get<std::string>();
  record.from_cache = true;
  return record;
}

// Everything the sidecar says about an entry except its checksum (which covers this text and the
// whole .npy file, so that a change to either is found).
nlohmann::json sidecar_fields(const DescriptorCacheKey& key, const fs::path& values_file,
                              std::size_t count, int rows, int cols, std::size_t values_bytes,
                              const CachedDescriptorValues& values) {
  // Names of files and folders in fingerprints are bytes: any that is not UTF-8 is stored
  // readably (json_string), and the key's own checksum keeps the comparison exact.
  const std::string key_text = key.text();
  nlohmann::json fields = {{"format", kFormatName},
                           {"format_version", kFormatVersion},
                           {"radarpr_version", std::string(radarpr_version())},
                           {"radarpr_build", descriptor_cache_build_identity()},
                           {"descriptor", key.descriptor_id},
                           {"sequence_fingerprint", key.sequence_fingerprint},
                           {"training_key", key.training},
                           {"plugin_build", key.plugin_build},
                           {"key_checksum", hex(cache_checksum(key_text.data(), key_text.size()))},
                           {"values_file", values_file.filename().string()},
                           {"dtype", "float32"},
                           {"shape", {count, rows, cols}},
                           {"values_bytes", values_bytes},
                           {"mean_extract_ms", values.mean_extract_ms},
                           {"training", training_json(values.training)},
                           {"timestamps_ns", values.timestamps_ns}};
  make_json_utf8(fields);
  return fields;
}

std::uint64_t sidecar_seed(const nlohmann::json& fields) {
  const std::string text = fields.dump();
  return cache_checksum(text.data(), text.size());
}

std::optional<std::string> read_text(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) return std::nullopt;
  std::string text{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
  if (file.bad()) return std::nullopt;
  return text;
}

// A name no other writer (thread or process) uses at the same moment.
fs::path temporary_path(const fs::path& entry) {
  static std::atomic<std::uint64_t> counter{0};
  const auto thread = std::hash<std::thread::id>{}(std::this_thread::get_id());
  return fs::path(entry.string() +
                  fmt::format(".tmp-{}-{:x}-{}", ::getpid(), thread, counter.fetch_add(1)));
}

std::uint64_t mix(std::uint64_t word) {
  word ^= word >> 33;
  word *= 0xff51afd7ed558ccdULL;
  word ^= word >> 33;
  return word;
}

}  // namespace

std::string loaded_codebook_key(const Descriptor& descriptor) {
  const LearntCodebook* codebook = learnt_codebook_of(descriptor);
  if (codebook == nullptr || codebook->codebook_loaded_from().empty()) return {};
  return "codebook_sha256=" + codebook->codebook_sha256();
}

std::uint64_t cache_checksum(const void* data, std::size_t size, std::uint64_t seed) {
  // Eight bytes per step so that checking a large entry costs far less than reading it.
  constexpr std::uint64_t kPrime = 0x100000001b3ULL * 0x9E3779B97F4A7C15ULL;
  const auto* bytes = static_cast<const unsigned char*>(data);
  std::uint64_t hash = (seed ^ 0xcbf29ce484222325ULL) + size * 0x9E3779B97F4A7C15ULL;
  std::size_t i = 0;
  for (; i + 8 <= size; i += 8) {
    std::uint64_t word = 0;
    std::memcpy(&word, bytes + i, 8);
    hash = (hash ^ mix(word)) * kPrime;
  }
  std::uint64_t tail = 0;
  for (std::size_t shift = 0; i < size; ++i, shift += 8) tail |= std::uint64_t{bytes[i]} << shift;
  hash = (hash ^ mix(tail)) * kPrime;
  return mix(hash);
}

const std::string& descriptor_cache_build_identity() {
  static const std::string identity = [] {
    std::error_code error;
    const fs::path executable = fs::read_symlink("/proc/self/exe", error);
    if (error) return std::string("unknown");
    const auto size = fs::file_size(executable, error);
    if (error) return std::string("unknown");
    const auto modified = fs::last_write_time(executable, error);
    if (error) return std::string("unknown");
    return fmt::format("{}-{}", size, modified.time_since_epoch().count());
  }();
  return identity;
}

std::string DescriptorCacheKey::text() const {
  std::string text = fmt::format("descriptor={}\nsequence={}\ntraining={}", descriptor_id,
                                 sequence_fingerprint, training);
  // Appended only for plugins: built-in keys, and so existing cache entries, stay as they were.
  if (!plugin_build.empty()) text += "\nplugin=" + plugin_build;
  return text;
}

DescriptorCache::DescriptorCache(std::optional<fs::path> root, Warn warn)
    : root_(std::move(root)), warn_(std::move(warn)) {
  if (!warn_) {
    // Once: the run looks a session's entries up again as another dataset's database.
    warn_ = [](const std::string& message) { warn_once(message); };
  }
}

DescriptorCache DescriptorCache::from_environment() {
  return DescriptorCache(cache_directory());
}

fs::path DescriptorCache::entry_path(const DescriptorCacheKey& key) const {
  const std::string text = key.text();
  const std::string name = key.descriptor_id.substr(0, key.descriptor_id.find(':'));
  return root_.value_or(fs::path()) / "descriptors" / (name.empty() ? "unnamed" : name) /
         fmt::format("{}.json", hex(cache_checksum(text.data(), text.size())));
}

fs::path DescriptorCache::values_path(const DescriptorCacheKey& key) const {
  return with_extension(entry_path(key), ".npy");
}

std::optional<CachedDescriptorValues> DescriptorCache::load(const DescriptorCacheKey& key,
                                                            std::size_t scans,
                                                            CacheLookup* outcome) const {
  CacheLookup ignored;
  CacheLookup& result = outcome ? *outcome : ignored;
  std::string problem;
  const std::optional<MappedDescriptorValues> mapped = map(key, scans, &result, &problem);
  if (!mapped) {
    if (result == CacheLookup::corrupt) {
      warn_(fmt::format("{}; recomputing", problem));
    }
    return std::nullopt;
  }
  CachedDescriptorValues cached;
  cached.mean_extract_ms = mapped->mean_extract_ms();
  cached.training = mapped->training();
  cached.timestamps_ns = mapped->timestamps_ns();
  cached.values = mapped->read(0, mapped->size());
  return cached;
}

std::optional<MappedDescriptorValues> DescriptorCache::map(const DescriptorCacheKey& key,
                                                           std::size_t scans, CacheLookup* outcome,
                                                           std::string* problem) const {
  CacheLookup ignored;
  CacheLookup& result = outcome ? *outcome : ignored;
  std::string unused;
  std::string& why = problem ? *problem : unused;
  result = CacheLookup::miss;
  const fs::path sidecar = entry_path(key);
  const fs::path values = values_path(key);
  why = fmt::format("descriptor cache entry {} ({}): none", sidecar.string(), key.descriptor_id);
  if (!root_) return std::nullopt;
  std::error_code error;
  if (!fs::exists(sidecar, error)) {
    if (fs::exists(with_extension(sidecar, ".bin"), error)) {
      result = CacheLookup::stale;  // an entry of the binary format before 3: never read
      why = fmt::format("descriptor cache entry {} ({}): of an older cache format",
                        with_extension(sidecar, ".bin").string(), key.descriptor_id);
    }
    return std::nullopt;
  }
  const std::optional<std::string> text = read_text(sidecar);
  if (!text) {
    why = fmt::format("descriptor cache entry {} ({}): unreadable", sidecar.string(),
                      key.descriptor_id);
    return std::nullopt;  // unreadable: a miss, as when absent
  }
  auto corrupt = [&](const std::string& cause) -> std::optional<MappedDescriptorValues> {
    result = CacheLookup::corrupt;
    why = fmt::format("descriptor cache entry {} ({}) is unusable: {}", sidecar.string(),
                      key.descriptor_id, cause);
    return std::nullopt;
  };

  nlohmann::json fields = nlohmann::json::parse(*text, nullptr, false);
  if (fields.is_discarded() || !fields.is_object()) return corrupt("malformed sidecar (not JSON)");
  MappedDescriptorValues mapped;
  std::size_t count = 0;
  std::size_t values_bytes = 0;
  std::string checksum;
  try {
    if (fields.at("format").get<std::string>() != kFormatName) {
      return corrupt("not a radarpr descriptor cache entry");
    }
    if (fields.at("format_version").get<int>() != kFormatVersion ||
        fields.at("radarpr_version").get<std::string>() != radarpr_version() ||
        fields.at("radarpr_build").get<std::string>() != descriptor_cache_build_identity()) {
      result = CacheLookup::stale;  // another build or format: quietly recomputed
      why = fmt::format(
          "descriptor cache entry {} ({}): written by another radarpr build or cache format",
          sidecar.string(), key.descriptor_id);
      return std::nullopt;
    }
    const std::string key_text = key.text();
    if (fields.at("descriptor").get<std::string>() != json_string(key.descriptor_id) ||
        fields.at("sequence_fingerprint").get<std::string>() !=
            json_string(key.sequence_fingerprint) ||
        fields.at("training_key").get<std::string>() != json_string(key.training) ||
        fields.at("plugin_build").get<std::string>() != json_string(key.plugin_build) ||
        fields.at("key_checksum").get<std::string>() !=
            hex(cache_checksum(key_text.data(), key_text.size()))) {
      return corrupt("it holds another key");
    }
    const auto shape = fields.at("shape").get<std::vector<std::int64_t>>();
    if (shape.size() != 3 || shape[0] < 0) return corrupt("malformed sidecar: shape");
    count = static_cast<std::size_t>(shape[0]);
    if (count != scans) {
      return corrupt(fmt::format("{} values for a sequence of {} scans", count, scans));
    }
    if (shape[1] < 1 || shape[2] < 1 || shape[1] > std::numeric_limits<int>::max() ||
        shape[2] > std::numeric_limits<int>::max()) {
      return corrupt(fmt::format("shape {} x {}", shape[1], shape[2]));
    }
    mapped.rows_ = static_cast<int>(shape[1]);
    mapped.cols_ = static_cast<int>(shape[2]);
    if (fields.at("dtype").get<std::string>() != "float32") return corrupt("dtype not float32");
    if (fields.at("values_file").get<std::string>() != values.filename().string()) {
      return corrupt(fmt::format("it names the values file '{}', not {}",
                                 fields.at("values_file").get<std::string>(),
                                 values.filename().string()));
    }
    values_bytes = fields.at("values_bytes").get<std::size_t>();
    mapped.mean_extract_ms_ = fields.at("mean_extract_ms").get<double>();
    mapped.training_ = training_from(fields.at("training"));
    mapped.timestamps_ns_ = fields.at("timestamps_ns").get<std::vector<std::int64_t>>();
    if (!mapped.timestamps_ns_.empty() && mapped.timestamps_ns_.size() != count) {
      return corrupt(
          fmt::format("{} timestamps for {} values", mapped.timestamps_ns_.size(), count));
    }
    checksum = fields.at("checksum").get<std::string>();
  } catch (const nlohmann::json::exception& failure) {
    return corrupt(fmt::format("malformed sidecar: {}", failure.what()));
  }
  fields.erase("checksum");

  // The values file: exactly the .npy header of a count x rows x cols float32 array, then the
  // values (checked without overflow: the sidecar's numbers are not trusted yet).
  const auto elements =
      static_cast<std::size_t>(mapped.rows_) * static_cast<std::size_t>(mapped.cols_);
  const std::size_t limit = std::numeric_limits<std::size_t>::max() / 4;
  if (scans != 0 && elements > limit / sizeof(float) / scans) {
    return corrupt(fmt::format("{} values of {} x {} floats do not fit in memory", scans,
                               mapped.rows_, mapped.cols_));
  }
  const std::string npy_header = npy_file_header(
      NpyDtype::float32,
      {count, static_cast<std::size_t>(mapped.rows_), static_cast<std::size_t>(mapped.cols_)});
  const std::size_t expected = npy_header.size() + scans * elements * sizeof(float);
  if (!fs::exists(values, error)) {
    return corrupt(fmt::format("its values file {} is missing", values.string()));
  }
  try {
    mapped.file_ = MappedFile(values);
  } catch (const std::exception& failure) {
    return corrupt(failure.what());
  }
  const std::span<const std::byte> bytes = mapped.file_.bytes();
  if (bytes.size() != expected || values_bytes != expected) {
    return corrupt(fmt::format("{}: {} bytes, expected {} (truncated or overwritten)",
                               values.string(), bytes.size(), expected));
  }
  if (std::memcmp(bytes.data(), npy_header.data(), npy_header.size()) != 0) {
    return corrupt(fmt::format("{}: not the .npy header of a {} x {} x {} float32 array",
                               values.string(), count, mapped.rows_, mapped.cols_));
  }
  mapped.payload_offset_ = npy_header.size();
  mapped.count_ = scans;
  mapped.elements_ = elements;

  // The checksum over the sidecar's fields and the whole values file, a block of values at a
  // time, each let go once summed.
  std::uint64_t sum = cache_checksum(npy_header.data(), npy_header.size(), sidecar_seed(fields));
  const std::size_t value_bytes = mapped.value_bytes();
  const std::size_t per_block = std::max<std::size_t>(1, kChecksumBlockBytes / value_bytes);
  for (std::size_t begin = 0; begin < scans; begin += per_block) {
    const std::size_t end = std::min(scans, begin + per_block);
    for (std::size_t i = begin; i < end; ++i) {
      sum = cache_checksum(mapped.value_bytes_at(i), value_bytes, sum);
    }
    mapped.release(begin, end);
  }
  if (hex(sum) != checksum) {
    // The values or the sidecar changed since they were written.
    return corrupt(fmt::format("{}: checksum mismatch", values.string()));
  }
  result = CacheLookup::hit;
  why.clear();
  return mapped;
}

const std::byte* MappedDescriptorValues::value_bytes_at(std::size_t index) const {
  return file_.bytes().data() + payload_offset_ + index * value_bytes();
}

void MappedDescriptorValues::release(std::size_t begin, std::size_t end) const {
  file_.release(payload_offset_ + begin * value_bytes(), (end - begin) * value_bytes());
}

std::vector<DescriptorValue> MappedDescriptorValues::read(std::size_t begin,
                                                          std::size_t end) const {
  std::vector<DescriptorValue> values;
  read(begin, end, values);
  return values;
}

void MappedDescriptorValues::read(std::size_t begin, std::size_t end,
                                  std::vector<DescriptorValue>& values) const {
  if (begin > end || end > count_) {
    throw std::out_of_range(
        fmt::format("{}: values [{}, {}) asked of {}", path().string(), begin, end, count_));
  }
  values.resize(end - begin);
  for (std::size_t i = begin; i < end; ++i) {
    DescriptorValue& value = values[i - begin];
    value.rows = rows_;
    value.cols = cols_;
    value.values.resize(elements_);
    // memcpy: the payload follows a header of any length, so its floats may be unaligned.
    std::memcpy(value.values.data(), value_bytes_at(i), value_bytes());
  }
  release(begin, end);
}

L2Rows MappedDescriptorValues::l2_rows() const {
  const std::byte* payload = value_bytes_at(0);
  if (reinterpret_cast<std::uintptr_t>(payload) % alignof(float) != 0) {
    // Never for an entry this cache wrote (its header is padded to 64 bytes).
    throw std::runtime_error(
        fmt::format("{}: the values do not start float-aligned", path().string()));
  }
  return L2Rows(reinterpret_cast<const float*>(payload), count_, rows_, cols_,
                [this](std::size_t begin, std::size_t end) { release(begin, end); });
}

bool MappedDescriptorValues::all_equal() const {
  if (count_ < 2) return true;
  const std::vector<DescriptorValue> first = read(0, 1);
  const std::size_t per_block = std::max<std::size_t>(1, kChecksumBlockBytes / value_bytes());
  for (std::size_t begin = 1; begin < count_; begin += per_block) {
    const std::size_t end = std::min(count_, begin + per_block);
    for (std::size_t i = begin; i < end; ++i) {
      if (std::memcmp(value_bytes_at(i), first.front().values.data(), value_bytes()) != 0) {
        release(begin, end);
        return false;
      }
    }
    release(begin, end);
  }
  return true;
}

bool DescriptorCache::store(const DescriptorCacheKey& key,
                            const CachedDescriptorValues& values) const {
  if (!root_) return false;
  const fs::path sidecar = entry_path(key);
  const fs::path values_file = values_path(key);
  const std::size_t count = values.values.size();
  const int rows = values.values.empty() ? 0 : values.values.front().rows;
  const int cols = values.values.empty() ? 0 : values.values.front().cols;
  const auto elements =
      static_cast<std::size_t>(std::max(rows, 0)) * static_cast<std::size_t>(std::max(cols, 0));
  for (const DescriptorValue& value : values.values) {
    if (value.rows != rows || value.cols != cols || value.values.size() != elements) {
      warn_(fmt::format("{}: values of several shapes are not cached", key.descriptor_id));
      return false;
    }
  }
  if (values.values.empty() || elements == 0) return false;
  if (!values.timestamps_ns.empty() && values.timestamps_ns.size() != count) {
    warn_(fmt::format("{}: {} timestamps for {} values are not cached", key.descriptor_id,
                      values.timestamps_ns.size(), count));
    return false;
  }

  const std::string npy_header = npy_file_header(
      NpyDtype::float32, {count, static_cast<std::size_t>(rows), static_cast<std::size_t>(cols)});
  const std::size_t values_bytes = npy_header.size() + count * elements * sizeof(float);
  nlohmann::json fields = sidecar_fields(key, values_file, count, rows, cols, values_bytes, values);
  std::uint64_t checksum =
      cache_checksum(npy_header.data(), npy_header.size(), sidecar_seed(fields));

  const fs::path values_temporary = temporary_path(values_file);
  const fs::path sidecar_temporary = temporary_path(sidecar);
  std::error_code error;
  fs::create_directories(sidecar.parent_path(), error);
  // Those of runs killed while storing: never read, but kept for good.
  remove_stale_temporary_files(sidecar.parent_path());
  auto give_up = [&](const std::string& why) {
    fs::remove(values_temporary, error);
    fs::remove(sidecar_temporary, error);
    warn_(
        fmt::format("cannot write the descriptor cache entry {} ({}){}; the values are not "
                    "cached",
                    sidecar.string(), key.descriptor_id, why));
    return false;
  };
  {
    std::ofstream file(values_temporary, std::ios::binary | std::ios::trunc);
    file.write(npy_header.data(), static_cast<std::streamsize>(npy_header.size()));
    for (const DescriptorValue& value : values.values) {
      file.write(reinterpret_cast<const char*>(value.values.data()),
                 static_cast<std::streamsize>(elements * sizeof(float)));
      checksum = cache_checksum(value.values.data(), elements * sizeof(float), checksum);
    }
    file.close();
    if (!file) return give_up("");
  }
  {
    fields["checksum"] = hex(checksum);
    std::ofstream file(sidecar_temporary, std::ios::binary | std::ios::trunc);
    file << fields.dump() << '\n';
    file.close();
    if (!file) return give_up("");
  }
  // Each rename is atomic: a reader sees the old or the new file. The values go first, so a
  // sidecar is never newer than its values; a reader meeting the old sidecar with the new values
  // (equal keys give equal values, so only after a damaged entry is repaired) finds the checksum
  // wrong and recomputes.
  fs::rename(values_temporary, values_file, error);
  if (!error) fs::rename(sidecar_temporary, sidecar, error);
  if (error) return give_up(": " + error.message());
  fs::remove(with_extension(sidecar, ".bin"), error);  // this key's entry in the older format
  return true;
}

}  // namespace radarpr
