#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "datasets/mapped_file.hpp"
#include "descriptors/descriptor.hpp"
#include "evaluation/descriptor_training.hpp"
#include "evaluation/retrieval/l2_rows.hpp"

namespace radarpr {

// What a descriptor's values on one sequence depend on. Equal keys mean equal values.
struct DescriptorCacheKey {
  std::string descriptor_id;         // canonical: the name and every non-default parameter
  std::string sequence_fingerprint;  // ScanSequence::fingerprint() of the scans described
  // Trainable descriptors only: what they learnt from ("train_on=...;training=<fingerprint>");
  // empty otherwise.
  std::string training;
  // Plugin descriptors only: the plugin file's identity (DescriptorInfo::plugin_build), so that a
  // rebuilt plugin does not reuse what its previous build extracted; empty for built-ins.
  std::string plugin_build;

  // The key as hashed into its entry's file names (the sidecar stores its parts one by one).
  std::string text() const;
};

// One descriptor's values on one sequence, as a cache entry holds them.
struct CachedDescriptorValues {
  std::vector<DescriptorValue> values;  // one per scan, all of the same shape
  double mean_extract_ms = 0.0;         // measured when they were extracted
  std::optional<TrainingRecord> training;
  // The scans' times (ns), one per value, recorded in the sidecar for readers outside radarpr;
  // may be empty (not recorded).
  std::vector<std::int64_t> timestamps_ns;
};

// One descriptor's values on one sequence read through a memory map of their cache entry
// (DescriptorCache::map): checked whole when opened (sidecar, .npy header, size and checksum, a
// block at a time), then read a block at a time, so that values larger than memory can be
// evaluated. Pages read are let go again, so the process holds the blocks it copied out, not the
// file.
class MappedDescriptorValues {
 public:
  std::size_t size() const { return count_; }
  int rows() const { return rows_; }
  int cols() const { return cols_; }
  std::size_t value_bytes() const { return elements_ * sizeof(float); }
  double mean_extract_ms() const { return mean_extract_ms_; }
  const std::optional<TrainingRecord>& training() const { return training_; }
  const std::vector<std::int64_t>& timestamps_ns() const { return timestamps_ns_; }
  // The entry's .npy file.
  const std::filesystem::path& path() const { return file_.path(); }

  // Values [begin, end) (end <= size()), copied out of the map.
  std::vector<DescriptorValue> read(std::size_t begin, std::size_t end) const;
  // The same into `values`, reusing the memory it holds (a block read after a block of the same
  // size allocates nothing).
  void read(std::size_t begin, std::size_t end, std::vector<DescriptorValue>& values) const;
  // Whether every value equals the first bit for bit (a constant descriptor), compared in place.
  bool all_equal() const;
  // The values in place as one row-major matrix (the payload starts 64-byte aligned), for the
  // blocked L2 search to read a block at a time and let go of again. Valid while this lives and
  // stays where it is.
  L2Rows l2_rows() const;
  // Lets go of the pages of values [begin, end).
  void release(std::size_t begin, std::size_t end) const;

 private:
  friend class DescriptorCache;
  MappedDescriptorValues() = default;
  const std::byte* value_bytes_at(std::size_t index) const;

  MappedFile file_;
  std::size_t payload_offset_ = 0;
  std::size_t count_ = 0;
  int rows_ = 0;
  int cols_ = 0;
  std::size_t elements_ = 0;
  double mean_extract_ms_ = 0.0;
  std::optional<TrainingRecord> training_;
  std::vector<std::int64_t> timestamps_ns_;
};

enum class CacheLookup {
  hit,
  miss,     // no entry
  stale,    // an entry of another radarpr build or cache format: recomputed and replaced
  corrupt,  // unreadable, truncated, another key, wrong count or checksum: recomputed, warned
};

// Extracted descriptor values on disk (architecture.md: "cached on disk, keyed by descriptor id +
// dataset fingerprint"), one entry per key under <root>/descriptors/<descriptor name>/: the values
// as <hash>.npy (float32, count x rows x cols, which numpy.load opens, also with mmap_mode='r')
// and a JSON sidecar <hash>.json (the key's parts, radarpr's version and build, shape, the mean
// extraction time, the training record, the scans' timestamps, and a checksum of the sidecar's
// other fields and the whole .npy file); docs/results.md describes it. Each file is written to a
// temporary name and renamed into place, the values first, so processes sharing the folder see
// whole files. Entries of the older binary format (.bin) are never read: a miss. Nothing here
// throws on a bad entry or a failed write: the caller recomputes, and the problem goes to `warn`.
class DescriptorCache {
 public:
  using Warn = std::function<void(const std::string&)>;

  // nullopt = caching off: every lookup misses and nothing is written. The default `warn`
  // prints "warning: ..." on stderr.
  explicit DescriptorCache(std::optional<std::filesystem::path> root, Warn warn = {});
  // The folder cache_directory() names (RADARPR_CACHE_DIR, --cache-dir, --no-cache ...).
  static DescriptorCache from_environment();

  bool enabled() const { return root_.has_value(); }

  // The values of `key` when an intact entry for exactly `scans` scans exists.
  std::optional<CachedDescriptorValues> load(const DescriptorCacheKey& key, std::size_t scans,
                                             CacheLookup* outcome = nullptr) const;
  // The same entry, checked the same way, as a memory map to read a block at a time (load() reads
  // it this way too). Warns about nothing: when there is no intact entry, `problem` (if given)
  // receives why, naming the file ("no entry", "another radarpr build", "truncated values", ...).
  std::optional<MappedDescriptorValues> map(const DescriptorCacheKey& key, std::size_t scans,
                                            CacheLookup* outcome = nullptr,
                                            std::string* problem = nullptr) const;
  // Replaces the entry of `key`. Values must share one shape; returns false (after warning)
  // when the entry could not be written.
  bool store(const DescriptorCacheKey& key, const CachedDescriptorValues& values) const;

  // Where the entry of `key` lives: its sidecar (for tests and messages), and its values.
  std::filesystem::path entry_path(const DescriptorCacheKey& key) const;
  std::filesystem::path values_path(const DescriptorCacheKey& key) const;

 private:
  std::optional<std::filesystem::path> root_;
  Warn warn_;
};

// Identifies the program computing descriptor values (its executable's size and modification
// time): an entry written by another build may hold values of older descriptor code and is
// recomputed rather than trusted.
const std::string& descriptor_cache_build_identity();

// What the values of a descriptor that loads its codebook from a file depend on besides its id
// ("codebook_sha256=<hash>", for DescriptorCacheKey::training), so that a changed file never
// reuses values of the old one; empty for every other descriptor.
std::string loaded_codebook_key(const Descriptor& descriptor);

// 64-bit checksum of bytes, continuing from `seed` (also names entry files).
std::uint64_t cache_checksum(const void* data, std::size_t size, std::uint64_t seed = 0);

}  // namespace radarpr
