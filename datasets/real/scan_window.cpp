#include "datasets/real/scan_window.hpp"

#include <stdexcept>

#include <fmt/format.h>

namespace radarpr {
namespace {

std::string ordinal(std::size_t n) {
  const std::size_t tens = n % 100;
  const char* suffix = (tens >= 11 && tens <= 13) ? "th"
                       : n % 10 == 1              ? "st"
                       : n % 10 == 2              ? "nd"
                       : n % 10 == 3              ? "rd"
                                                  : "th";
  return fmt::format("{}{}", n, suffix);
}

}  // namespace

std::string describe(const ScanWindow& window) {
  if (window.start == 0 && !window.end && window.every_nth == 1) return "all";
  std::string text = fmt::format("[{}, {})", window.start,
                                 window.end ? fmt::format("{}", *window.end) : std::string("end"));
  if (window.every_nth != 1) text += " every " + ordinal(window.every_nth);
  return text;
}

std::vector<std::size_t> select_scans(const ScanWindow& window, std::size_t count,
                                      const std::string& source) {
  if (window.every_nth < 1) {
    throw std::invalid_argument(fmt::format("{}: every_nth must be >= 1, got 0", source));
  }
  const std::size_t end = window.end.value_or(count);
  if (end > count) {
    throw std::invalid_argument(
        fmt::format("{}: end = {} is beyond the {} scans found (end is an exclusive scan index)",
                    source, end, count));
  }
  if (window.start >= end) {
    throw std::invalid_argument(
        fmt::format("{}: the window [start = {}, end = {}) selects no scan of the {} found", source,
                    window.start, end, count));
  }
  std::vector<std::size_t> selected;
  selected.reserve((end - window.start + window.every_nth - 1) / window.every_nth);
  for (std::size_t i = window.start; i < end; i += window.every_nth) selected.push_back(i);
  return selected;
}

}  // namespace radarpr
