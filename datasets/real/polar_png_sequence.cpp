#include "datasets/real/polar_png_sequence.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <system_error>
#include <utility>

#include <fmt/format.h>

#include "datasets/png_header.hpp"
#include "datasets/real/azimuth_resampling.hpp"
#include "datasets/real/real_dataset.hpp"

namespace radarpr {
namespace {

std::atomic<std::size_t> decode_count{0};

// Pose gaps longer than this are worth a warning even when they are below the hard limit.
constexpr double kLongPoseGapS = 1.0;

std::size_t count_duplicated(const std::vector<ScanFile>& scans,
                             const std::vector<std::size_t>& selected) {
  std::size_t duplicated = 0;
  for (std::size_t k = 0; k < selected.size(); ++k) {
    const std::int64_t t = scans[selected[k]].timestamp_ns;
    const bool previous = k > 0 && scans[selected[k - 1]].timestamp_ns == t;
    const bool next = k + 1 < selected.size() && scans[selected[k + 1]].timestamp_ns == t;
    if (previous || next) ++duplicated;
  }
  return duplicated;
}

// Boreas-RT alternates the flag byte between chirp directions (0, 255, 0, ...); interpolated
// rows of other sources never alternate over a whole revolution.
bool flags_alternate(const std::vector<std::uint8_t>& flags) {
  if (flags.size() < 4 || flags[0] == flags[1]) return false;
  for (std::size_t i = 2; i < flags.size(); ++i) {
    if (flags[i] != flags[i - 2]) return false;
  }
  return true;
}

// "400 azimuths x 3768 range bins" of an image `width` x `height` pixels in `layout`.
std::string describe_size(int width, int height, PolarPngLayout layout) {
  return layout == PolarPngLayout::oxford
             ? fmt::format("{} azimuths x {} range bins", height, width - kOxfordMetadataColumns)
             : fmt::format("{} azimuths x {} range bins", width, height);
}

// Sources that drop azimuth rows (OORD) are resampled to `azimuths`; more rows than that, or more
// than a fifth missing, is not a scan with a few dropped rows but a wrong file or setting.
void check_azimuth_rows(int rows, int azimuths, const std::string& path) {
  const int fewest = (4 * azimuths + 4) / 5;  // ceil(0.8 A)
  if (rows > azimuths || rows < fewest) {
    throw std::runtime_error(fmt::format(
        "{}: {} azimuth rows, expected {} to {} (the configured azimuths = {}, at most a fifth "
        "dropped): a wrong file, a transposed scan, or a wrong `azimuths` setting",
        path, rows, fewest, azimuths, azimuths));
  }
}

// FNV-1a over the selected scan files' paths, sizes and modification times: a descriptor cache
// keyed by the fingerprint must not outlive a file that was replaced or rewritten in place (a
// stat per file, next to the header check's open and read, costs nothing noticeable).
std::string file_stamps_digest(const std::vector<ScanRecord>& records) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  auto add = [&hash](const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) {
      hash ^= bytes[i];
      hash *= 0x100000001b3ULL;
    }
  };
  for (const ScanRecord& record : records) {
    std::error_code error;
    const std::uintmax_t size = std::filesystem::file_size(record.source, error);
    const auto modified =
        std::filesystem::last_write_time(record.source, error).time_since_epoch().count();
    add(record.source.data(), record.source.size() + 1);  // with the terminating zero
    add(&size, sizeof size);
    add(&modified, sizeof modified);
  }
  return fmt::format("{:016x}", hash);
}

}  // namespace

PolarPngSequence::PolarPngSequence(PolarPngSequenceSetup setup)
    : name_(std::move(setup.name)),
      options_(setup.decode),
      resample_azimuths_(setup.resample_azimuths),
      frame_(setup.poses ? setup.frame : PositionFrame::none),
      report_(std::move(setup.report)) {
  if (!(setup.max_pose_gap_s > 0.0) || !(setup.max_pose_gap_s <= kMaxPoseGapS)) {
    throw std::invalid_argument(fmt::format("{}: max_pose_gap_s must be in (0, {}] seconds, got {}",
                                            name_, kMaxPoseGapS, setup.max_pose_gap_s));
  }
  const std::vector<std::size_t> selected =
      select_scans(setup.window, setup.scans.size(), setup.location.string());
  const auto max_gap_ns = static_cast<std::int64_t>(std::llround(setup.max_pose_gap_s * 1e9));

  records_.reserve(selected.size());
  std::size_t without_pose = 0;
  for (const std::size_t index : selected) {
    const ScanFile& scan = setup.scans[index];
    if (!setup.poses) {
      records_.push_back({scan.timestamp_ns, Pose2D{}, scan.path.string()});
      continue;
    }
    const auto pose = setup.poses->at(scan.timestamp_ns, max_gap_ns);
    if (pose) {
      records_.push_back({scan.timestamp_ns, *pose, scan.path.string()});
    } else {
      ++without_pose;
    }
  }

  // The first usable scan fixes the geometry (the first selected one when none has a pose).
  first_scan_ =
      records_.empty() ? setup.scans[selected.front()].path.string() : records_.front().source;
  const Decoded first = decode(first_scan_);
  azimuths_ = first.png.image.azimuth_count();
  range_bins_ = first.png.image.range_bin_count();
  // A scan of a few cells gives every descriptor a constant value (RaPlace of a 1 x 1 scan):
  // refused here, before any work, rather than scored by tie-breaking.
  if (azimuths_ < kMinScanAzimuths || range_bins_ < kMinScanRangeBins) {
    throw std::runtime_error(fmt::format(
        "{}: {} azimuths x {} range bins; a radar scan needs at least {} azimuths and {} range "
        "bins to be described",
        first_scan_, azimuths_, range_bins_, kMinScanAzimuths, kMinScanRangeBins));
  }
  check_headers(first);

  DatasetReport& r = report_;
  r.type = setup.type;
  r.name = name_;
  r.location = setup.location.string();
  r.azimuths = azimuths_;
  r.range_bins = range_bins_;
  r.range_resolution_m = options_.range_resolution_m;
  r.scan_files = setup.scans.size();
  r.window = radarpr::describe(setup.window);
  r.scans_selected = selected.size();
  r.scan_times = TimeSpan{setup.scans[selected.front()].timestamp_ns,
                          setup.scans[selected.back()].timestamp_ns};
  r.duplicated_scan_timestamps = count_duplicated(setup.scans, selected);
  r.position_frame = frame_;
  if (setup.poses) {
    const PoseTrack& track = *setup.poses;
    r.pose_samples = track.size();
    r.duplicated_pose_timestamps = track.duplicated_timestamps();
    if (!track.empty()) {
      r.pose_times = TimeSpan{track.first_ns(), track.last_ns()};
      if (track.size() > 1) {
        r.largest_pose_gap_s = static_cast<double>(track.largest_gap_ns(r.scan_times->first_ns,
                                                                        r.scan_times->last_ns)) *
                               1e-9;
      }
    }
    r.posed_scans = records_.size();
    r.scans_without_pose = without_pose;
    r.notes.push_back(
        fmt::format("poses interpolated at each scan's time; none across gaps over {} s",
                    setup.max_pose_gap_s));
  }
  if (!options_.layout) {
    r.layout = fmt::format("{}, detected from the first scan's shape{}{}",
                           to_string(first.png.layout), r.layout.empty() ? "" : " ", r.layout);
  }
  if (azimuths_ != first.raw_azimuths) {
    r.notes.push_back(fmt::format(
        "the first scan has {} azimuth rows, resampled to {} (azimuths assumed uniform)",
        first.raw_azimuths, azimuths_));
  }
  const auto& flags = first.png.row_flags;
  if (flags_alternate(flags)) {
    // Boreas-RT stores the chirp direction in the flag byte: not a validity flag.
    r.notes.push_back("row flags alternate between two values: chirp direction, not validity");
  } else if (!flags.empty()) {
    r.invalid_azimuth_rows = static_cast<int>(
        std::count_if(flags.begin(), flags.end(), [](std::uint8_t flag) { return flag != 255; }));
  }
  if (setup.expected_range_bins && range_bins_ != *setup.expected_range_bins) {
    r.warnings.push_back(fmt::format(
        "the first scan has {} range bins, but the {} gives {}: another sensor, or a cropped or "
        "resized copy? The range resolution ({} m/bin, {}) may not apply",
        range_bins_, setup.sensor, *setup.expected_range_bins, options_.range_resolution_m,
        r.resolution_source));
  }
  r.notes.push_back(fmt::format(
      "PNG header and end checked for all {} scans to be read: every one is {}", records_.size(),
      resample_azimuths_ ? "as wide as the first, its rows resampled" : "the first scan's size"));
  add_standard_warnings(r, kLongPoseGapS);

  fingerprint_ = fmt::format(
      "{}-v1(location={},window={},files={},first_ns={},last_ns={},resolution_m={},layout={},"
      "row_metadata={},resample={},frame={},pose_samples={},max_pose_gap_s={},scans={},"
      "file_stamps={}{}{})",
      setup.type, r.location, r.window, setup.scans.size(), setup.scans.front().timestamp_ns,
      setup.scans.back().timestamp_ns, options_.range_resolution_m,
      options_.layout ? std::string(to_string(*options_.layout)) : std::string("auto"),
      options_.use_row_metadata, resample_azimuths_.value_or(0), to_string(frame_), r.pose_samples,
      setup.max_pose_gap_s, records_.size(), file_stamps_digest(records_),
      setup.fingerprint_options.empty() ? "" : ",", setup.fingerprint_options);
}

std::size_t PolarPngSequence::decodes_in_process() {
  return decode_count.load();
}

PolarPngSequence::Decoded PolarPngSequence::decode(const std::filesystem::path& path) const {
  decode_count.fetch_add(1, std::memory_order_relaxed);
  Decoded decoded{read_polar_png(path, options_), 0};
  PolarImage& image = decoded.png.image;
  decoded.raw_azimuths = image.azimuth_count();
  if (resample_azimuths_)
    check_azimuth_rows(image.azimuth_count(), *resample_azimuths_, path.string());
  if (resample_azimuths_ && image.azimuth_count() != *resample_azimuths_) {
    image.power = resample_azimuth_rows(image.power, *resample_azimuths_);
    image.azimuths_rad = uniform_azimuths(*resample_azimuths_);
    image.azimuth_times_ns.clear();
    decoded.png.row_flags.clear();
  }
  return decoded;
}

void PolarPngSequence::check_headers(const Decoded& first) const {
  const PngHeader expected = read_png_header(first_scan_);
  const PolarPngLayout layout = first.png.layout;
  for (const ScanRecord& record : records_) {
    const PngHeader header = read_png_header(record.source);
    const bool same_pixels =
        header.bit_depth == expected.bit_depth && header.colour_type == expected.colour_type;
    if (!same_pixels) {
      throw std::runtime_error(fmt::format(
          "{}: PNG bit depth {} colour type {}, but the first scan of {} ({}) has bit depth {} "
          "colour type {}: every scan must be 8-bit grayscale like it",
          record.source, header.bit_depth, header.colour_type, name_, first_scan_,
          expected.bit_depth, expected.colour_type));
    }
    if (resample_azimuths_) {
      // Rows may be dropped, so only the width (the range bins) must match.
      if (header.width == expected.width) {
        check_azimuth_rows(header.height, *resample_azimuths_, record.source);
        continue;
      }
    } else if (header.width == expected.width && header.height == expected.height) {
      continue;
    }
    throw std::runtime_error(fmt::format(
        "{}: {} x {} pixels ({}), but the first scan of {} ({}) is {} x {} ({}): every scan of a "
        "sequence must have the same size",
        record.source, header.width, header.height,
        describe_size(header.width, header.height, layout), name_, first_scan_, expected.width,
        expected.height, describe_size(expected.width, expected.height, layout)));
  }
}

PolarImage PolarPngSequence::load_image(std::size_t index) const {
  if (index >= records_.size()) {
    throw std::out_of_range(fmt::format("{}: scan index {} out of range (the sequence has {})",
                                        name_, index, records_.size()));
  }
  const std::string& path = records_[index].source;
  Decoded decoded = decode(path);
  PolarImage& image = decoded.png.image;
  if (image.azimuth_count() != azimuths_ || image.range_bin_count() != range_bins_) {
    throw std::runtime_error(fmt::format(
        "{}: {} azimuths x {} range bins, but the first scan of {} ({}) has {} x {}: every scan "
        "of a sequence must have the same size",
        path, image.azimuth_count(), image.range_bin_count(), name_, first_scan_, azimuths_,
        range_bins_));
  }
  return std::move(image);
}

}  // namespace radarpr
