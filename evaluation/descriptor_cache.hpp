#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "descriptors/descriptor.hpp"
#include "evaluation/descriptor_training.hpp"

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

  // The key as stored in an entry's header and hashed into its file name.
  std::string text() const;
};

// One descriptor's values on one sequence, as a cache entry holds them.
struct CachedDescriptorValues {
  std::vector<DescriptorValue> values;  // one per scan, all of the same shape
  double mean_extract_ms = 0.0;         // measured when they were extracted
  std::optional<TrainingRecord> training;
};

enum class CacheLookup {
  hit,
  miss,     // no entry
  stale,    // an entry of another radarpr build or cache format: recomputed and replaced
  corrupt,  // unreadable, truncated, another key, wrong count or checksum: recomputed, warned
};

// Extracted descriptor values on disk (architecture.md: "cached on disk, keyed by descriptor id +
// dataset fingerprint"), one file per key under <root>/descriptors/<descriptor name>/. An entry
// is a header (the key, radarpr's version and build, count, rows, cols, the mean extraction time,
// the training record) followed by the float32 values and a checksum of everything before it.
// Entries are written to a temporary file and renamed into place, so processes sharing the
// folder see a whole entry or none. Nothing here throws on a bad entry or a failed write: the
// caller recomputes, and the problem goes to `warn`.
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
  // Replaces the entry of `key`. Values must share one shape; returns false (after warning)
  // when the entry could not be written.
  bool store(const DescriptorCacheKey& key, const CachedDescriptorValues& values) const;

  // Where the entry of `key` lives (for tests and messages).
  std::filesystem::path entry_path(const DescriptorCacheKey& key) const;

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
