#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "datasets/scan_sequence.hpp"
#include "descriptors/descriptor.hpp"

namespace radarpr {

// Descriptor values computed outside radarpr: one row per scan, with the scan's time.
struct PrecomputedTable {
  std::vector<std::int64_t> timestamps_ns;  // one per row, strictly increasing
  std::size_t dimension = 0;                // values per row
  std::vector<float> values;                // rows x dimension, row-major
  std::string source;                       // the file(s), for messages
  std::size_t rows() const { return timestamps_ns.size(); }
};

enum class PrecomputedTimeUnit { ns, us, ms, s };

// Reads the values and their times. `values`: a .npy array N x D (float32 or float64; a 1-D array
// of N is N x 1) or a CSV file with a header row whose columns are the values, plus a `timestamp`
// column when `timestamps` is empty. `timestamps`: a .npy array of N (int64, or float64 for
// seconds and other fractional units) or a text file of one time per line (a header line
// `timestamp` allowed). Times are in `unit` and converted to ns. Throws std::runtime_error naming
// the file: unreadable or malformed files, a row count that differs between values and times,
// non-finite values, and duplicated or decreasing times (the first few offenders listed).
PrecomputedTable read_precomputed_table(const std::filesystem::path& values,
                                        const std::filesystem::path& timestamps,
                                        PrecomputedTimeUnit unit);

// The row of every scan: the row whose time is within `tolerance_ns` of the scan's time. Scans
// without such a row, rows without a scan and a row two scans claim are errors listing the first
// few offenders (with their times), naming `table.source` and `sequence_name`: never a shifted or
// silently dropped row. Each value is dimension x 1.
std::vector<DescriptorValue> match_rows_to_scans(const PrecomputedTable& table,
                                                 const std::vector<ScanRecord>& scans,
                                                 std::int64_t tolerance_ns,
                                                 const std::string& sequence_name);

}  // namespace radarpr
