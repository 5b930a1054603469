#include "datasets/synthetic/cached_synthetic_sequence.hpp"

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "datasets/cache_directory.hpp"
#include "datasets/polar_png.hpp"
#include "datasets/real/folder_dataset.hpp"
#include "datasets/stale_temporaries.hpp"
#include "datasets/synthetic/scan_export.hpp"
#include "datasets/warn_once.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

// Written last, holding the fingerprint: its presence means every scan and poses.csv are there.
constexpr const char* kCompleteMarker = "complete";

// FNV-1a, 64 bits: a folder name that is stable across compilers and runs (std::hash is not).
std::string folder_key(const std::string& fingerprint) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (const char c : fingerprint) {
    hash ^= static_cast<std::uint8_t>(c);
    hash *= 0x100000001b3ULL;
  }
  return fmt::format("{:016x}", hash);
}

std::optional<std::string> read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

PolarPngOptions decode_options(const SyntheticConfig& config) {
  PolarPngOptions options;
  options.range_resolution_m = config.radar.range_resolution_m;
  options.layout = PolarPngLayout::oxford;
  return options;
}

// Name, fingerprint, records and description are the generator's; only the pixels' way differs.
class GeneratedSequence : public ScanSequence {
 public:
  explicit GeneratedSequence(std::shared_ptr<const SyntheticSequence> generator)
      : generator_(std::move(generator)) {}

  std::string name() const override { return generator_->name(); }
  std::string fingerprint() const override { return generator_->fingerprint(); }
  const std::vector<ScanRecord>& records() const override { return generator_->records(); }
  PositionFrame position_frame() const override { return generator_->position_frame(); }

 protected:
  const SyntheticSequence& generator() const { return *generator_; }
  // Scan `index` rendered and put in the Oxford layout, as it would be written to disk.
  ByteImage render_oxford_layout(std::size_t index) const {
    return synthetic::to_oxford_layout(generator_->load_image(index));
  }

 private:
  std::shared_ptr<const SyntheticSequence> generator_;
};

// --no-cache: the layout round trip in memory, so the images equal the cached ones.
class UncachedSyntheticSequence final : public GeneratedSequence {
 public:
  using GeneratedSequence::GeneratedSequence;

  PolarImage load_image(std::size_t index) const override {
    return decode_polar_png(render_oxford_layout(index), decode_options(generator().config()),
                            records().at(index).source)
        .image;
  }
  DatasetReport describe() const override {
    DatasetReport report = generator().describe();
    report.layout = "rendered, Oxford layout in memory (no cache)";
    return report;
  }
};

// A cache folder being filled: scans already on disk are decoded from it, the others rendered,
// written and then decoded from their file. The last scan in writes the marker.
class CachingSyntheticSequence final : public GeneratedSequence {
 public:
  CachingSyntheticSequence(std::shared_ptr<const SyntheticSequence> generator, fs::path folder)
      : GeneratedSequence(std::move(generator)),
        folder_(std::move(folder)),
        present_(records().size()) {
    fs::create_directories(folder_ / "scans");
    synthetic::write_folder_poses(folder_, records());
    for (std::size_t i = 0; i < present_.size(); ++i) {
      std::error_code ignored;
      if (fs::is_regular_file(scan_path(i), ignored)) mark_present(i);
    }
  }

  PolarImage load_image(std::size_t index) const override {
    const fs::path path = scan_path(index);
    const PolarPngOptions options = decode_options(generator().config());
    if (present_.at(index).load()) {
      try {
        return read_polar_png(path, options).image;
      } catch (const std::runtime_error& error) {
        // Tampered with or cut short outside radarpr (our writes are atomic): render it again.
        warn_once(
            fmt::format("cached synthetic scan unreadable, rendering it again: {}", error.what()));
      }
    }
    const ByteImage rendered = render_oxford_layout(index);
    try {
      synthetic::write_png_atomically(path, rendered);
    } catch (const std::exception& error) {
      // A full or read-only disk costs the cache, not the run.
      warn_once(fmt::format("cannot cache synthetic scans in {} ({}): rendering in memory",
                            folder_.string(), error.what()));
      return decode_polar_png(rendered, options, records()[index].source).image;
    }
    mark_present(index);
    return read_polar_png(path, options).image;
  }

  DatasetReport describe() const override {
    DatasetReport report = generator().describe();
    report.layout = "rendered into the cache, Oxford-layout PNGs";
    report.location = folder_.string();
    return report;
  }

 private:
  fs::path scan_path(std::size_t index) const {
    return synthetic::scan_png_path(folder_, records()[index]);
  }

  void mark_present(std::size_t index) const {
    if (present_[index].exchange(true)) return;
    if (present_count_.fetch_add(1) + 1 == present_.size()) {
      synthetic::write_text_atomically(folder_ / kCompleteMarker, fingerprint());
    }
  }

  fs::path folder_;
  mutable std::vector<std::atomic<bool>> present_;
  mutable std::atomic<std::size_t> present_count_{0};
};

// A complete cache folder, read by the `folder` loader like anyone's own data.
class CachedSyntheticSequence final : public GeneratedSequence {
 public:
  CachedSyntheticSequence(std::shared_ptr<const SyntheticSequence> generator,
                          std::unique_ptr<ScanSequence> folder, fs::path location)
      : GeneratedSequence(std::move(generator)),
        folder_(std::move(folder)),
        location_(std::move(location)) {}
  // The folder loader's records: the same times and poses (checked), the files as sources.

  const std::vector<ScanRecord>& records() const override { return folder_->records(); }
  PolarImage load_image(std::size_t index) const override {
    try {
      return folder_->load_image(index);
    } catch (const std::runtime_error& error) {
      // Damaged since the folder was opened (our own writes are atomic): render it again.
      warn_once(
          fmt::format("cached synthetic scan unreadable, rendering it again: {}", error.what()));
    }
    const ByteImage rendered = render_oxford_layout(index);
    try {
      synthetic::write_png_atomically(records()[index].source, rendered);
    } catch (const std::exception& error) {
      warn_once(error.what());
    }
    return decode_polar_png(rendered, decode_options(generator().config()), records()[index].source)
        .image;
  }
  DatasetReport describe() const override {
    DatasetReport report = folder_->describe();
    report.type = "synthetic";
    report.location = location_.string() + " (cache of " + name() + ")";
    return report;
  }

 private:
  std::unique_ptr<ScanSequence> folder_;
  fs::path location_;
};

// The folder loader's view must be the generator's exactly, or the cache is not what it claims.
std::optional<std::string> disagreement(const std::vector<ScanRecord>& generated,
                                        const std::vector<ScanRecord>& loaded) {
  if (generated.size() != loaded.size()) {
    return fmt::format("{} scans instead of {}", loaded.size(), generated.size());
  }
  for (std::size_t i = 0; i < generated.size(); ++i) {
    const ScanRecord& g = generated[i];
    const ScanRecord& l = loaded[i];
    if (g.timestamp_ns != l.timestamp_ns || g.pose.x != l.pose.x || g.pose.y != l.pose.y ||
        g.pose.yaw != l.pose.yaw) {
      return fmt::format("scan {} differs in time or pose", i);
    }
  }
  return std::nullopt;
}

std::unique_ptr<ScanSequence> open_complete_folder(
    const std::shared_ptr<const SyntheticSequence>& generator, const fs::path& folder) {
  FolderOptions options;
  options.common.root = folder;
  options.common.range_resolution_m = generator->config().radar.range_resolution_m;
  options.layout = PolarPngLayout::oxford;
  try {
    auto loaded = open_folder(options);
    if (const auto why = disagreement(generator->records(), loaded->records())) {
      warn_once(fmt::format(
          "cached synthetic scans in {} do not match their config ({}): rendering them again",
          folder.string(), *why));
      return nullptr;
    }
    return std::make_unique<CachedSyntheticSequence>(generator, std::move(loaded), folder);
  } catch (const std::runtime_error& error) {
    warn_once(
        fmt::format("cached synthetic scans unusable, rendering them again: {}", error.what()));
    return nullptr;
  }
}

}  // namespace

std::unique_ptr<ScanSequence> open_synthetic(const SyntheticConfig& config) {
  auto generator = std::make_shared<const SyntheticSequence>(config);
  const auto cache = cache_directory();
  if (!cache) return std::make_unique<UncachedSyntheticSequence>(std::move(generator));

  const std::string fingerprint = generator->fingerprint();
  const fs::path folder = *cache / "synthetic" / folder_key(fingerprint);
  // A run killed while writing a scan leaves its temporary file: never read, but kept for good.
  remove_stale_temporary_files(folder);
  remove_stale_temporary_files(folder / "scans");
  if (read_text(folder / kCompleteMarker) == fingerprint) {
    if (auto cached = open_complete_folder(generator, folder)) return cached;
    std::error_code ignored;
    fs::remove(folder / kCompleteMarker, ignored);
  } else if (const auto other = read_text(folder / "fingerprint"); other && *other != fingerprint) {
    // Two fingerprints with one 64-bit key: keep the other's folder, go without a cache.
    return std::make_unique<UncachedSyntheticSequence>(std::move(generator));
  }
  try {
    fs::create_directories(folder);
    synthetic::write_text_atomically(folder / "fingerprint", fingerprint);
    return std::make_unique<CachingSyntheticSequence>(std::move(generator), folder);
  } catch (const std::exception& error) {
    warn_once(fmt::format("cannot cache synthetic scans in {} ({}): rendering in memory",
                          folder.string(), error.what()));
    return std::make_unique<UncachedSyntheticSequence>(std::move(generator));
  }
}

}  // namespace radarpr
