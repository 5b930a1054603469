#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "datasets/dataset_report.hpp"
#include "datasets/polar_png.hpp"
#include "datasets/pose_track.hpp"
#include "datasets/real/scan_files.hpp"
#include "datasets/real/scan_window.hpp"
#include "datasets/scan_sequence.hpp"

namespace radarpr {

// Everything a dataset loader works out from a sequence's folder: the scan files, how to decode
// them, the pose track and what it found on the way. PolarPngSequence does the rest.
struct PolarPngSequenceSetup {
  std::string type;                // "mulran", "oxford", ...
  std::string name;                // ScanSequence::name(), e.g. "mulran(KAIST03)"
  std::filesystem::path location;  // the sequence folder
  std::vector<ScanFile> scans;     // every scan found, in time order
  ScanWindow window;
  PolarPngOptions decode;
  // Resample every scan to this many azimuth rows (OORD drops rows); unset = every scan must
  // have the first scan's row count.
  std::optional<int> resample_azimuths;
  // The sensor's range bin count (MulRan 3360, ...): a first scan with another R is reported as a
  // warning, naming `sensor`. Unset = any R (Boreas has several sensors).
  std::optional<int> expected_range_bins;
  std::string sensor;
  std::optional<PoseTrack> poses;  // nullopt: no ground truth, position frame `none`
  PositionFrame frame = PositionFrame::global;
  // Scans between two pose samples further apart than this get no pose.
  double max_pose_gap_s = 5.0;
  // Loader facts: layout, resolution_source, pose_source, notes, warnings.
  DatasetReport report;
  // Loader options that change the scans or poses, for the fingerprint.
  std::string fingerprint_options;
};

// A sequence of polar PNGs on disk with their timestamps and interpolated poses. It lists files
// and poses up front and decodes one PNG per load_image() call, so memory does not grow with
// the sequence's length beyond one record per scan. The first selected scan is decoded when the
// sequence is opened: it fixes A x R and feeds the report. Every other scan's PNG header and end
// are checked then too (a few µs a file), so a truncated or wrong-size file stops the sequence
// from opening instead of failing hours into extraction.
class PolarPngSequence : public ScanSequence {
 public:
  // Throws std::invalid_argument for a bad window; std::runtime_error naming the file for a
  // first scan that cannot be decoded, or a scan whose PNG header differs from the first scan's
  // (size, bit depth, colour type; with resampling: width, and rows outside [0.8 A, A]) or that
  // does not end with an IEND chunk.
  explicit PolarPngSequence(PolarPngSequenceSetup setup);

  std::string name() const override { return name_; }
  std::string fingerprint() const override { return fingerprint_; }
  const std::vector<ScanRecord>& records() const override { return records_; }
  // Throws std::runtime_error naming the file when it is missing, cannot be decoded, or differs
  // in size from the first scan; std::out_of_range for a bad index.
  PolarImage load_image(std::size_t index) const override;
  PositionFrame position_frame() const override { return frame_; }
  DatasetReport describe() const override { return report_; }

  // PNGs decoded by every PolarPngSequence of this process so far (the first scan at each
  // opening included): lets tests check that cached descriptor values spare the decoding.
  static std::size_t decodes_in_process();

 private:
  struct Decoded {
    DecodedPolarPng png;   // resampled when configured
    int raw_azimuths = 0;  // rows before resampling
  };
  Decoded decode(const std::filesystem::path& path) const;
  // Reads every record's PNG header and compares it with the first scan's (`first`).
  void check_headers(const Decoded& first) const;

  std::string name_;
  std::string fingerprint_;
  PolarPngOptions options_;
  std::optional<int> resample_azimuths_;
  PositionFrame frame_ = PositionFrame::global;
  std::vector<ScanRecord> records_;
  std::string first_scan_;  // the file that fixed the geometry
  int azimuths_ = 0;        // as delivered
  int range_bins_ = 0;
  DatasetReport report_;
};

}  // namespace radarpr
