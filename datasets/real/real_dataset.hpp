#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "datasets/real/scan_window.hpp"

namespace radarpr {

// What every real-dataset loader takes: the config keys {root, sequence, every_nth, start, end,
// range_resolution_m, max_pose_gap_s}.
struct RealDatasetOptions {
  std::filesystem::path root;  // the dataset's top folder
  // The sequence's folder relative to root ("KAIST03", "bellmouth/2021-11-25-12-31-19");
  // empty = root is the sequence folder itself.
  std::string sequence;
  ScanWindow window;
  // Metres per range bin; unset = the dataset's default (by date for Boreas).
  std::optional<double> range_resolution_m;
  // Scans between two pose samples further apart than this get no pose rather than a guess.
  double max_pose_gap_s = 5.0;
};

// The largest max_pose_gap_s (11.6 days): far beyond any drive, and far below the 9.2e9 s at
// which the gap in nanoseconds would overflow a 64-bit integer.
inline constexpr double kMaxPoseGapS = 1e6;
// The largest metres per range bin (the coarsest Navtech sensors use 0.17 m).
inline constexpr double kMaxRangeResolutionM = 100.0;

// root / sequence, after checking both exist. Throws std::runtime_error naming the missing
// folder and what it should hold (`dataset`: "a MulRan copy"; `sequence_contents`: what a
// sequence folder holds), listing the sub-folders of root when the sequence is not among them.
std::filesystem::path resolve_sequence_folder(const RealDatasetOptions& options,
                                              const std::string& dataset,
                                              const std::string& sequence_contents);

// "type(sequence)" or "type(folder name)" for ScanSequence::name().
std::string sequence_name(const std::string& type, const RealDatasetOptions& options);

// Throws std::invalid_argument naming `source` unless `metres` is a positive finite number.
double checked_resolution(double metres, const std::string& source);

}  // namespace radarpr
