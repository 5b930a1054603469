#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace radarpr::bench {

// What a speed target compares with its limit (measured <= limit is met).
enum class TargetMeasure {
  extraction_over_floor,       // whole extraction / the plain pass over the same scan
  extraction_milliseconds,     // whole extraction, one thread
  extraction_over_png_decode,  // whole extraction / decoding the scan's PNG
  search_seconds,              // the whole search at the database size (extrapolated if sampled)
  // the search ran at that size, its peak resident memory (peak_rss_bytes) at most `limit` GB
  search_within_memory,
  search_over_product,      // search / the Eigen product of the same shapes, largest size
  startup_milliseconds,     // a whole radarpr process, wall clock
  startup_over_extraction,  // a whole `radarpr extract` / PNG decode + extraction in-process
};

// One row of the speed targets. The targets are data: adding or changing one edits this table
// (speed_targets.cpp), not the code that checks them (bench_report.cpp).
struct SpeedTarget {
  std::string_view part;  // "extraction", "retrieval" or "start-up"
  TargetMeasure measure = TargetMeasure::extraction_over_floor;
  std::string_view descriptor;  // a descriptor id; a trailing '*' = every id starting so
  // extraction, start-up: the scan label (empty: none); retrieval: "single" or "multi"
  std::string_view where;
  std::size_t database_size = 0;  // search_seconds, search_within_memory: N
  double limit = 0.0;
  std::string_view wording;  // the target, for the report
};

std::span<const SpeedTarget> speed_targets();

// The descriptor ids the extraction targets name (without wildcards), so that the default run
// measures every one of them.
std::vector<std::string> extraction_target_descriptor_ids();

}  // namespace radarpr::bench
