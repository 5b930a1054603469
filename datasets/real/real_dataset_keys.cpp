#include "datasets/real/real_dataset_keys.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

namespace radarpr {
namespace {

// A number in (0, high]: checked before it is converted (seconds to nanoseconds, metres to
// bins), so that a huge value cannot wrap into a negative or meaningless one.
std::optional<double> positive_number(DatasetKeys& keys, const std::string& key, double high) {
  const double value = keys.number_or(key, 0.0);  // also lists the key among the accepted ones
  if (!keys.has(key)) return std::nullopt;
  if (!(value > 0.0) || !(value <= high)) {
    keys.fail(key, fmt::format("must be a number in (0, {}], got {}", high, value));
  }
  return value;
}

}  // namespace

RealDatasetOptions read_real_dataset_keys(DatasetKeys& keys) {
  RealDatasetOptions options;
  const std::string root = keys.required_path("root");
  if (root.empty()) keys.fail("root", "must name the dataset's folder");
  options.root = root;
  options.sequence = keys.string_or("sequence", "");
  const auto every_nth = keys.integer_or("every_nth", 1);
  if (every_nth < 1 || every_nth > 1'000'000) {
    keys.fail("every_nth", fmt::format("must be in [1, 1000000], got {}", every_nth));
  }
  options.window.every_nth = static_cast<std::size_t>(every_nth);
  const auto start = keys.integer_or("start", 0);
  if (start < 0) keys.fail("start", fmt::format("must be a scan index >= 0, got {}", start));
  options.window.start = static_cast<std::size_t>(start);
  if (keys.is_set("end")) {
    const auto end = keys.integer_or("end", 0);
    if (end <= start) {
      keys.fail("end", fmt::format("must be a scan index > start ({}), got {} (end is exclusive)",
                                   start, end));
    }
    options.window.end = static_cast<std::size_t>(end);
  }
  options.range_resolution_m = positive_number(keys, "range_resolution_m", kMaxRangeResolutionM);
  options.max_pose_gap_s =
      positive_number(keys, "max_pose_gap_s", kMaxPoseGapS).value_or(options.max_pose_gap_s);
  return options;
}

std::string read_choice(DatasetKeys& keys, const std::string& key,
                        const std::vector<std::string>& choices) {
  const std::string value = keys.string_or(key, choices.front());
  if (std::find(choices.begin(), choices.end(), value) == choices.end()) {
    keys.fail(key, fmt::format("'{}' is not one of: {}", value, fmt::join(choices, ", ")));
  }
  return value;
}

}  // namespace radarpr
