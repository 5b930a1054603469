#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "datasets/dataset_report.hpp"
#include "datasets/polar_image.hpp"

namespace radarpr {

// Planar pose of the sensor in a dataset's world frame (metres, radians).
struct Pose2D {
  double x = 0.0;
  double y = 0.0;
  double yaw = 0.0;
};

// The smallest scan a sequence accepts (real or synthetic): every descriptor here needs more
// (ReFeree's 50 azimuth blocks, RaPlace's Radon projections; a 1 x 1 or 2 x 3 scan gives RaPlace
// one value for every scan), and real sensors give hundreds of each.
inline constexpr int kMinScanAzimuths = 16;
inline constexpr int kMinScanRangeBins = 16;

// What is known about a scan without decoding its image.
struct ScanRecord {
  std::int64_t timestamp_ns = 0;
  Pose2D pose;
  std::string source;  // file path, or a description for generated scans
};

// A scan = image + timestamp + pose.
struct Scan {
  ScanRecord record;
  PolarImage image;
};

// A time-ordered stream of scans. Images are decoded on demand, one at a time, so a sequence
// never holds all of them in memory; callers decode each scan once and share it.
class ScanSequence {
 public:
  virtual ~ScanSequence() = default;

  // Human-readable name, e.g. "synthetic(seed=7,session=0)".
  virtual std::string name() const = 0;
  // Identifies the content (source, parameters): equal fingerprints mean equal scans.
  virtual std::string fingerprint() const = 0;
  // Every usable scan, in time order. Scans without a pose are never listed, except in a
  // sequence without any ground truth (position_frame() == none): there every scan is listed
  // with a zero pose, for extraction and benchmarks; evaluation refuses such a sequence.
  virtual const std::vector<ScanRecord>& records() const = 0;
  // Decodes (or generates) scan `index`. Thread-safe: called concurrently from several threads.
  virtual PolarImage load_image(std::size_t index) const = 0;

  // Where the record poses live; multi-session evaluation needs `global` on both sides.
  virtual PositionFrame position_frame() const { return PositionFrame::global; }
  // What was found: layout, A x R, times, pose coverage, warnings. The default knows only the
  // records; loaders fill in the rest.
  virtual DatasetReport describe() const;

  std::size_t size() const { return records().size(); }
};

}  // namespace radarpr
