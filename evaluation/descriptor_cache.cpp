#include "evaluation/descriptor_cache.hpp"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <span>
#include <stdexcept>
#include <system_error>
#include <thread>
#include <utility>

#include <unistd.h>

#include <fmt/format.h>

#include "datasets/cache_directory.hpp"
#include "datasets/stale_temporaries.hpp"
#include "descriptors/learnt_codebook.hpp"
#include "evaluation/version.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

// Bump when the entry layout changes; entries of another format are recomputed.
constexpr std::uint32_t kFormatVersion = 2;  // 2: the training record holds the codebook hash
constexpr char kMagic[8] = {'R', 'P', 'R', 'D', 'V', 'A', 'L', 'S'};
constexpr std::uint32_t kByteOrderMark = 0x01020304;
// A header is a few hundred bytes (fingerprints included); anything far larger is garbage.
constexpr std::uint64_t kMaxHeaderBytes = std::uint64_t{1} << 20;
// A mapped entry is checked and compared this many bytes of values at a time, each block's pages
// let go before the next, so checking a large entry does not hold it in memory.
constexpr std::size_t kChecksumBlockBytes = std::size_t{64} << 20;

// Appends and reads the header's fields in the machine's byte order (the mark tells).
class HeaderWriter {
 public:
  template <typename T>
  void put(T value) {
    bytes_.append(reinterpret_cast<const char*>(&value), sizeof(T));
  }
  void put_string(const std::string& text) {
    put(static_cast<std::uint32_t>(text.size()));
    bytes_ += text;
  }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

class HeaderReader {
 public:
  explicit HeaderReader(const std::string& bytes) : bytes_(bytes) {}
  template <typename T>
  bool get(T& value) {
    if (bytes_.size() - position_ < sizeof(T)) return false;
    std::memcpy(&value, bytes_.data() + position_, sizeof(T));
    position_ += sizeof(T);
    return true;
  }
  bool get_string(std::string& text) {
    std::uint32_t size = 0;
    if (!get(size) || bytes_.size() - position_ < size) return false;
    text.assign(bytes_, position_, size);
    position_ += size;
    return true;
  }
  bool at_end() const { return position_ == bytes_.size(); }

 private:
  const std::string& bytes_;
  std::size_t position_ = 0;
};

std::string producer() {
  return fmt::format("radarpr {} build {}", radarpr_version(), descriptor_cache_build_identity());
}

// The part of the header a reader compares before trusting anything else.
struct EntryHeader {
  std::uint32_t byte_order = 0;
  std::uint32_t format = 0;
  std::string producer;
  std::string key;
  std::uint64_t count = 0;
  std::int32_t rows = 0;
  std::int32_t cols = 0;
  double mean_extract_ms = 0.0;
  std::optional<TrainingRecord> training;
};

std::string serialise(const EntryHeader& header) {
  HeaderWriter writer;
  writer.put(header.byte_order);
  writer.put(header.format);
  writer.put_string(header.producer);
  writer.put_string(header.key);
  writer.put(header.count);
  writer.put(header.rows);
  writer.put(header.cols);
  writer.put(header.mean_extract_ms);
  writer.put(static_cast<std::uint8_t>(header.training.has_value()));
  if (header.training) {
    writer.put_string(header.training->sequence);
    writer.put(static_cast<std::uint64_t>(header.training->scans));
    writer.put(static_cast<std::uint64_t>(header.training->loaded));
    writer.put(header.training->seconds);
    writer.put_string(header.training->codebook_sha256);
  }
  return writer.bytes();
}

// nullopt when the bytes are not a whole header.
std::optional<EntryHeader> parse(const std::string& bytes) {
  HeaderReader reader(bytes);
  EntryHeader header;
  std::uint8_t has_training = 0;
  if (!reader.get(header.byte_order) || !reader.get(header.format)) return std::nullopt;
  if (header.byte_order != kByteOrderMark || header.format != kFormatVersion) return header;
  if (!reader.get_string(header.producer) || !reader.get_string(header.key) ||
      !reader.get(header.count) || !reader.get(header.rows) || !reader.get(header.cols) ||
      !reader.get(header.mean_extract_ms) || !reader.get(has_training)) {
    return std::nullopt;
  }
  if (has_training != 0) {
    TrainingRecord record;
    std::uint64_t scans = 0;
    std::uint64_t loaded = 0;
    if (!reader.get_string(record.sequence) || !reader.get(scans) || !reader.get(loaded) ||
        !reader.get(record.seconds) || !reader.get_string(record.codebook_sha256)) {
      return std::nullopt;
    }
    record.scans = static_cast<std::size_t>(scans);
    record.loaded = static_cast<std::size_t>(loaded);
    record.from_cache = true;
    header.training = std::move(record);
  }
  if (!reader.at_end()) return std::nullopt;
  return header;
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
    warn_ = [](const std::string& message) { fmt::print(stderr, "warning: {}\n", message); };
  }
}

DescriptorCache DescriptorCache::from_environment() {
  return DescriptorCache(cache_directory());
}

fs::path DescriptorCache::entry_path(const DescriptorCacheKey& key) const {
  const std::string text = key.text();
  const std::string name = key.descriptor_id.substr(0, key.descriptor_id.find(':'));
  return root_.value_or(fs::path()) / "descriptors" / (name.empty() ? "unnamed" : name) /
         fmt::format("{:016x}.bin", cache_checksum(text.data(), text.size()));
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
  const fs::path path = entry_path(key);
  why = fmt::format("descriptor cache entry {} ({}): none", path.string(), key.descriptor_id);
  if (!root_) return std::nullopt;
  MappedDescriptorValues mapped;
  try {
    std::error_code error;
    if (!fs::exists(path, error)) return std::nullopt;
    mapped.file_ = MappedFile(path);
  } catch (const std::exception& error) {
    why = fmt::format("descriptor cache entry {} ({}): {}", path.string(), key.descriptor_id,
                      error.what());
    return std::nullopt;  // unreadable: a miss, as when absent
  }
  auto corrupt = [&](const std::string& cause) -> std::optional<MappedDescriptorValues> {
    result = CacheLookup::corrupt;
    why = fmt::format("descriptor cache entry {} ({}) is unusable: {}", path.string(),
                      key.descriptor_id, cause);
    return std::nullopt;
  };

  const std::span<const std::byte> bytes = mapped.file_.bytes();
  std::uint64_t header_size = 0;
  if (bytes.size() < sizeof kMagic || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0) {
    return corrupt("not a radarpr descriptor cache entry");
  }
  if (bytes.size() < sizeof kMagic + sizeof header_size) {
    return corrupt("truncated or malformed header");
  }
  std::memcpy(&header_size, bytes.data() + sizeof kMagic, sizeof header_size);
  if (header_size > kMaxHeaderBytes) return corrupt("truncated or malformed header");
  const std::size_t header_start = sizeof kMagic + sizeof header_size;
  if (bytes.size() - header_start < header_size) return corrupt("truncated header");
  const std::string header_bytes(reinterpret_cast<const char*>(bytes.data()) + header_start,
                                 static_cast<std::size_t>(header_size));
  const std::optional<EntryHeader> header = parse(header_bytes);
  if (!header) return corrupt("malformed header");
  if (header->byte_order != kByteOrderMark || header->format != kFormatVersion ||
      header->producer != producer()) {
    result = CacheLookup::stale;  // another build or format: quietly recomputed
    why = fmt::format(
        "descriptor cache entry {} ({}): written by another radarpr build or cache "
        "format",
        path.string(), key.descriptor_id);
    return std::nullopt;
  }
  if (header->key != key.text()) return corrupt("it holds another key");
  if (header->count != scans) {
    return corrupt(fmt::format("{} values for a sequence of {} scans", header->count, scans));
  }
  if (header->rows < 1 || header->cols < 1) {
    return corrupt(fmt::format("shape {} x {}", header->rows, header->cols));
  }
  const auto elements =
      static_cast<std::size_t>(header->rows) * static_cast<std::size_t>(header->cols);
  // The payload and the checksum must be exactly what is left of the file (checked without
  // overflow: the header's numbers are not trusted yet).
  const std::size_t payload_start = header_start + static_cast<std::size_t>(header_size);
  const std::size_t remaining = bytes.size() - payload_start;
  const std::size_t limit = std::numeric_limits<std::size_t>::max() / 2;
  const bool fits = scans == 0 || elements <= limit / sizeof(float) / scans;
  const std::size_t expected = fits ? scans * elements * sizeof(float) + sizeof(std::uint64_t) : 0;
  if (!fits || remaining != expected) {
    return corrupt(fmt::format("{} bytes of values, expected {}", remaining,
                               fits ? fmt::to_string(expected) : std::string("more than fit")));
  }
  mapped.payload_offset_ = payload_start;
  mapped.count_ = scans;
  mapped.rows_ = header->rows;
  mapped.cols_ = header->cols;
  mapped.elements_ = elements;
  mapped.mean_extract_ms_ = header->mean_extract_ms;
  mapped.training_ = header->training;

  // The checksum over the whole entry, a block of values at a time, each let go once summed.
  std::uint64_t checksum = cache_checksum(header_bytes.data(), header_bytes.size());
  const std::size_t value_bytes = mapped.value_bytes();
  const std::size_t per_block = std::max<std::size_t>(1, kChecksumBlockBytes / value_bytes);
  for (std::size_t begin = 0; begin < scans; begin += per_block) {
    const std::size_t end = std::min(scans, begin + per_block);
    for (std::size_t i = begin; i < end; ++i) {
      checksum = cache_checksum(mapped.value_bytes_at(i), value_bytes, checksum);
    }
    mapped.release(begin, end);
  }
  std::uint64_t stored = 0;
  std::memcpy(&stored, bytes.data() + payload_start + scans * value_bytes, sizeof stored);
  if (stored != checksum) return corrupt("checksum mismatch");
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
  const fs::path path = entry_path(key);
  EntryHeader header;
  header.byte_order = kByteOrderMark;
  header.format = kFormatVersion;
  header.producer = producer();
  header.key = key.text();
  header.count = values.values.size();
  header.rows = values.values.empty() ? 0 : values.values.front().rows;
  header.cols = values.values.empty() ? 0 : values.values.front().cols;
  header.mean_extract_ms = values.mean_extract_ms;
  header.training = values.training;
  const auto elements = static_cast<std::size_t>(std::max(header.rows, 0)) *
                        static_cast<std::size_t>(std::max(header.cols, 0));
  for (const DescriptorValue& value : values.values) {
    if (value.rows != header.rows || value.cols != header.cols || value.values.size() != elements) {
      warn_(fmt::format("{}: values of several shapes are not cached", key.descriptor_id));
      return false;
    }
  }
  if (values.values.empty() || elements == 0) return false;

  const std::string header_bytes = serialise(header);
  const std::uint64_t header_size = header_bytes.size();
  const fs::path temporary = temporary_path(path);
  std::error_code error;
  fs::create_directories(path.parent_path(), error);
  // Those of runs killed while storing: never read, but kept for good.
  remove_stale_temporary_files(path.parent_path());
  {
    std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
    std::uint64_t checksum = cache_checksum(header_bytes.data(), header_bytes.size());
    file.write(kMagic, sizeof kMagic);
    file.write(reinterpret_cast<const char*>(&header_size), sizeof header_size);
    file.write(header_bytes.data(), static_cast<std::streamsize>(header_bytes.size()));
    for (const DescriptorValue& value : values.values) {
      file.write(reinterpret_cast<const char*>(value.values.data()),
                 static_cast<std::streamsize>(elements * sizeof(float)));
      checksum = cache_checksum(value.values.data(), elements * sizeof(float), checksum);
    }
    file.write(reinterpret_cast<const char*>(&checksum), sizeof checksum);
    file.close();
    if (!file) {
      fs::remove(temporary, error);
      warn_(
          fmt::format("cannot write the descriptor cache entry {} ({}); the values are not "
                      "cached",
                      path.string(), key.descriptor_id));
      return false;
    }
  }
  fs::rename(temporary, path, error);  // atomic: readers see the old entry or the new one
  if (error) {
    const std::string why = error.message();
    fs::remove(temporary, error);
    warn_(fmt::format("cannot write the descriptor cache entry {} ({}): {}", path.string(),
                      key.descriptor_id, why));
    return false;
  }
  return true;
}

}  // namespace radarpr
