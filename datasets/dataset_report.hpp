#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace radarpr {

// Where a sequence's positions live. Only positions in one world frame can be compared across
// sessions, so multi-session evaluation needs `global` on both sides.
enum class PositionFrame {
  global,  // a frame shared by every session of the dataset (UTM, ENU, MulRan's global_pose)
  local,   // integrated odometry: each sequence starts at its own origin
  none,    // no ground truth: records carry zero poses; extraction and benchmarks only
};

std::string_view to_string(PositionFrame frame);

// First and last time of a set of stamps, in Unix ns.
struct TimeSpan {
  std::int64_t first_ns = 0;
  std::int64_t last_ns = 0;

  double seconds() const { return static_cast<double>(last_ns - first_ns) * 1e-9; }
  bool overlaps(const TimeSpan& other) const {
    return first_ns <= other.last_ns && other.first_ns <= last_ns;
  }
};

// What a loader found on disk: everything `radarpr inspect` prints about one sequence. Counts
// refer to the scans selected by start/end/every_nth unless they say otherwise.
struct DatasetReport {
  std::string type;      // "mulran", "oxford", ..., "synthetic"
  std::string name;      // ScanSequence::name()
  std::string location;  // the folder read (or a description of generated data)
  std::string layout;    // e.g. "oxford (sensor_data/radar/polar_oxford_form/)"

  int azimuths = 0;    // A of the first scan as delivered (after any resampling); 0 = unknown
  int range_bins = 0;  // R of the first scan; 0 = unknown
  double range_resolution_m = 0.0;
  std::string resolution_source;  // "MulRan default", "configured", "by date: ...", ...

  // Which moment of the sweep a scan's time, and so its pose, refers to ("the first azimuth");
  // empty = not stated.
  std::string scan_time_reference;

  std::size_t scan_files = 0;      // scans found, before the window
  std::string window;              // "all", "[100, 500) every 2nd", ...
  std::size_t scans_selected = 0;  // after the window
  std::optional<TimeSpan> scan_times;
  std::size_t duplicated_scan_timestamps = 0;  // selected scans sharing a stamp with another

  PositionFrame position_frame = PositionFrame::global;
  std::string pose_source;  // "gps/ins.csv (easting, northing)", ...
  std::size_t pose_samples = 0;
  std::optional<TimeSpan> pose_times;
  std::optional<double> largest_pose_gap_s;
  std::size_t duplicated_pose_timestamps = 0;
  std::size_t posed_scans = 0;         // = records().size() when the sequence has poses
  std::size_t scans_without_pose = 0;  // selected scans outside the pose track or in a long gap

  // Oxford layout: rows of the first scan whose flag byte is not 255 (interpolated azimuths).
  std::optional<int> invalid_azimuth_rows;

  std::vector<std::string> notes;     // facts worth knowing ("azimuths resampled to 400 rows")
  std::vector<std::string> warnings;  // problems that may distort results
};

// Adds the warnings every sequence gets from its own counts: scans left without a pose, clocks
// that do not overlap, duplicated timestamps, interpolated azimuth rows, long pose gaps.
void add_standard_warnings(DatasetReport& report, double long_pose_gap_s);

// "2019-01-10 14:37:26.353 UTC"
std::string format_utc(std::int64_t unix_ns);

// The report as indented "key  value" lines, for `radarpr inspect`.
std::string format_report(const DatasetReport& report, const std::string& indent);

}  // namespace radarpr
