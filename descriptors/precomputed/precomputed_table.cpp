#include "descriptors/precomputed/precomputed_table.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string_view>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "datasets/npy_file.hpp"
#include "datasets/real/text_table.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

// How many offenders an error lists: enough to see a pattern (a shift, a gap), short enough to
// read.
constexpr std::size_t kListedOffenders = 5;

std::int64_t ns_per_unit(PrecomputedTimeUnit unit) {
  switch (unit) {
    case PrecomputedTimeUnit::ns:
      return 1;
    case PrecomputedTimeUnit::us:
      return 1000;
    case PrecomputedTimeUnit::ms:
      return 1000000;
    case PrecomputedTimeUnit::s:
      return 1000000000;
  }
  return 1;
}

bool is_npy(const fs::path& path) {
  return path.extension() == ".npy";
}

[[noreturn]] void fail(const fs::path& path, const std::string& what) {
  throw std::runtime_error(fmt::format("{}: {}", path.string(), what));
}

std::int64_t to_ns(double time, PrecomputedTimeUnit unit, const fs::path& path, std::size_t row) {
  const double ns = std::round(time * static_cast<double>(ns_per_unit(unit)));
  if (!std::isfinite(ns) || std::abs(ns) > 9.2e18) {
    fail(path, fmt::format("time of row {} ({}) is not a representable time", row, time));
  }
  return static_cast<std::int64_t>(ns);
}

std::int64_t to_ns(std::int64_t time, PrecomputedTimeUnit unit, const fs::path& path,
                   std::size_t row) {
  const std::int64_t factor = ns_per_unit(unit);
  if (time > std::numeric_limits<std::int64_t>::max() / factor ||
      time < std::numeric_limits<std::int64_t>::min() / factor) {
    fail(path, fmt::format("time of row {} ({}) overflows in ns", row, time));
  }
  return time * factor;
}

std::vector<std::int64_t> read_npy_times(const fs::path& path, PrecomputedTimeUnit unit) {
  const NpyFile file = NpyFile::open(path);
  if (file.shape().size() != 1) {
    fail(path,
         fmt::format("timestamps must be a 1-D array, got {} dimensions", file.shape().size()));
  }
  std::vector<std::int64_t> times;
  if (file.dtype() == NpyDtype::int64) {
    const std::vector<std::int64_t> raw = file.as_int64s();
    for (std::size_t i = 0; i < raw.size(); ++i) times.push_back(to_ns(raw[i], unit, path, i));
  } else if (file.dtype() == NpyDtype::float64) {
    const std::vector<double> raw = file.as_doubles();
    for (std::size_t i = 0; i < raw.size(); ++i) times.push_back(to_ns(raw[i], unit, path, i));
  } else {
    fail(path, fmt::format("timestamps must be int64 or float64, got {}", to_string(file.dtype())));
  }
  return times;
}

std::int64_t text_time(const TextTable& table, std::size_t column, PrecomputedTimeUnit unit,
                       std::size_t row) {
  const std::string_view text = table.text(column);
  if (text.find_first_of(".eE") == std::string_view::npos) {
    return to_ns(table.integer(column), unit, table.path(), row);
  }
  return to_ns(table.number(column), unit, table.path(), row);
}

std::vector<std::int64_t> read_text_times(const fs::path& path, PrecomputedTimeUnit unit) {
  TextTable table(path, TextTable::Separator::comma, "the precomputed descriptor's timestamps");
  std::vector<std::int64_t> times;
  bool first = true;
  while (table.next()) {
    if (table.field_count() != 1) table.fail("expected one time per line");
    if (first && (table.text(0) == "timestamp" || table.text(0) == "timestamp_ns")) {
      first = false;
      continue;
    }
    first = false;
    times.push_back(text_time(table, 0, unit, times.size()));
  }
  return times;
}

void check_finite(const std::vector<float>& values, std::size_t dimension, const fs::path& path) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) {
      fail(path, fmt::format("row {} column {} is {}: descriptor values must be finite",
                             i / dimension, i % dimension, values[i]));
    }
  }
}

void check_increasing(const std::vector<std::int64_t>& times, const std::string& source) {
  std::vector<std::string> offenders;
  std::size_t count = 0;
  for (std::size_t i = 1; i < times.size(); ++i) {
    if (times[i] > times[i - 1]) continue;
    ++count;
    if (offenders.size() < kListedOffenders) {
      offenders.push_back(fmt::format("row {} ({} ns) {} row {} ({} ns)", i, times[i],
                                      times[i] == times[i - 1] ? "repeats" : "is before", i - 1,
                                      times[i - 1]));
    }
  }
  if (count > 0) {
    throw std::runtime_error(fmt::format(
        "{}: times must be strictly increasing (one row per scan, in time order); {} rows are "
        "not: {}{}",
        source, count, fmt::join(offenders, "; "), count > offenders.size() ? "; ..." : ""));
  }
}

}  // namespace

PrecomputedTable read_precomputed_table(const fs::path& values, const fs::path& timestamps,
                                        PrecomputedTimeUnit unit) {
  if (values.empty()) {
    throw std::runtime_error("precomputed: parameter 'values' names no file (a .npy or .csv)");
  }
  PrecomputedTable table;
  table.source = timestamps.empty()
                     ? values.string()
                     : fmt::format("{} with {}", values.string(), timestamps.string());
  std::vector<std::int64_t> csv_times;
  if (is_npy(values)) {
    const NpyFile file = NpyFile::open(values);
    if (file.dtype() != NpyDtype::float32 && file.dtype() != NpyDtype::float64) {
      fail(values,
           fmt::format("values must be float32 or float64, got {}", to_string(file.dtype())));
    }
    if (file.shape().empty() || file.shape().size() > 2) {
      fail(values, fmt::format("values must be an N x D array (one row per scan), got {} "
                               "dimensions",
                               file.shape().size()));
    }
    table.dimension = file.shape().size() == 2 ? file.shape()[1] : 1;
    if (table.dimension == 0) fail(values, "values have 0 columns");
    table.values = file.as_floats();
    if (timestamps.empty()) {
      fail(values,
           "a .npy of values needs the 'timestamps' parameter (a file of one time per row)");
    }
  } else {
    TextTable csv(values, TextTable::Separator::comma, "the precomputed descriptor's values");
    csv.read_header();
    const std::optional<std::size_t> time_column =
        timestamps.empty() ? csv.find_column({"timestamp", "timestamp_ns"}) : std::nullopt;
    if (timestamps.empty() && !time_column) {
      fail(values, "no 'timestamp' column, and no 'timestamps' parameter naming a file of times");
    }
    const std::size_t columns = csv.header().size();
    table.dimension = columns - (time_column ? 1 : 0);
    if (table.dimension == 0) fail(values, "no value columns besides the timestamp");
    while (csv.next()) {
      if (csv.field_count() != columns) {
        csv.fail(fmt::format("expected {} fields, got {}", columns, csv.field_count()));
      }
      for (std::size_t c = 0; c < columns; ++c) {
        if (time_column && c == *time_column) {
          csv_times.push_back(text_time(csv, c, unit, csv_times.size()));
        } else {
          const double number = csv.number(c);
          if (std::abs(number) > std::numeric_limits<float>::max()) {
            csv.fail(fmt::format("column {} ({}) does not fit in float32", c + 1, number));
          }
          table.values.push_back(static_cast<float>(number));
        }
      }
    }
  }
  check_finite(table.values, table.dimension, values);
  const std::size_t rows = table.values.size() / table.dimension;
  if (timestamps.empty()) {
    table.timestamps_ns = std::move(csv_times);
  } else {
    table.timestamps_ns =
        is_npy(timestamps) ? read_npy_times(timestamps, unit) : read_text_times(timestamps, unit);
    if (table.timestamps_ns.size() != rows) {
      throw std::runtime_error(fmt::format("{}: {} rows of values but {} times in {}",
                                           values.string(), rows, table.timestamps_ns.size(),
                                           timestamps.string()));
    }
  }
  check_increasing(table.timestamps_ns, table.source);
  return table;
}

std::vector<DescriptorValue> match_rows_to_scans(const PrecomputedTable& table,
                                                 const std::vector<ScanRecord>& scans,
                                                 std::int64_t tolerance_ns,
                                                 const std::string& sequence_name) {
  const auto& times = table.timestamps_ns;
  std::vector<std::size_t> row_of_scan(scans.size());
  std::vector<std::size_t> scan_of_row(times.size(), scans.size());
  std::vector<std::string> unmatched;
  std::size_t unmatched_count = 0;
  for (std::size_t i = 0; i < scans.size(); ++i) {
    const std::int64_t t = scans[i].timestamp_ns;
    const auto after = std::lower_bound(times.begin(), times.end(), t);
    std::size_t best = times.size();
    std::int64_t best_gap = std::numeric_limits<std::int64_t>::max();
    if (after != times.end()) {
      best = static_cast<std::size_t>(after - times.begin());
      best_gap = *after - t;
    }
    if (after != times.begin() && t - *(after - 1) <= best_gap) {
      best = static_cast<std::size_t>(after - times.begin()) - 1;
      best_gap = t - *(after - 1);
    }
    if (best == times.size() || best_gap > tolerance_ns) {
      ++unmatched_count;
      if (unmatched.size() < kListedOffenders) {
        unmatched.push_back(best == times.size()
                                ? fmt::format("scan {} ({} ns)", i, t)
                                : fmt::format("scan {} ({} ns; nearest row {} is {} ns away)", i, t,
                                              best, best_gap));
      }
      continue;
    }
    if (scan_of_row[best] != scans.size()) {
      throw std::runtime_error(fmt::format(
          "{} on {}: row {} ({} ns) is within the tolerance of both scan {} and scan {}; lower "
          "the tolerance below half the scan spacing",
          table.source, sequence_name, best, times[best], scan_of_row[best], i));
    }
    scan_of_row[best] = i;
    row_of_scan[i] = best;
  }
  if (unmatched_count > 0) {
    throw std::runtime_error(fmt::format("{} on {}: {} of {} scans have no row within {} ns: {}{}",
                                         table.source, sequence_name, unmatched_count, scans.size(),
                                         tolerance_ns, fmt::join(unmatched, "; "),
                                         unmatched_count > unmatched.size() ? "; ..." : ""));
  }
  std::vector<std::string> extra;
  std::size_t extra_count = 0;
  for (std::size_t r = 0; r < times.size(); ++r) {
    if (scan_of_row[r] != scans.size()) continue;
    ++extra_count;
    if (extra.size() < kListedOffenders)
      extra.push_back(fmt::format("row {} ({} ns)", r, times[r]));
  }
  if (extra_count > 0) {
    throw std::runtime_error(fmt::format(
        "{} on {}: {} of {} rows match no scan within {} ns: {}{} (the values must be of exactly "
        "this sequence's scans)",
        table.source, sequence_name, extra_count, times.size(), tolerance_ns,
        fmt::join(extra, "; "), extra_count > extra.size() ? "; ..." : ""));
  }
  std::vector<DescriptorValue> values(scans.size());
  const auto width = static_cast<std::ptrdiff_t>(table.dimension);
  for (std::size_t i = 0; i < scans.size(); ++i) {
    const auto begin = table.values.begin() + static_cast<std::ptrdiff_t>(row_of_scan[i]) * width;
    values[i] = {static_cast<int>(table.dimension), 1, std::vector<float>(begin, begin + width)};
  }
  return values;
}

}  // namespace radarpr
