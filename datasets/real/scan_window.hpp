#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace radarpr {

// Which of a sequence's scans to use. start and end are 0-based indices into the scans found,
// in time order (end exclusive; unset = to the last), applied before every_nth: the window
// {start 100, end 500, every_nth 4} keeps scans 100, 104, ..., 496. Scans without a pose are
// dropped afterwards, so indices never depend on the pose file.
struct ScanWindow {
  std::size_t start = 0;
  std::optional<std::size_t> end;
  std::size_t every_nth = 1;
};

// "all", "[100, 500) every 4th", ...
std::string describe(const ScanWindow& window);

// Indices of the selected scans among `count`. Throws std::invalid_argument naming `source`
// when every_nth is 0, start >= end, or start / end exceed `count`.
std::vector<std::size_t> select_scans(const ScanWindow& window, std::size_t count,
                                      const std::string& source);

}  // namespace radarpr
