#pragma once

#include <chrono>
#include <cstddef>
#include <mutex>
#include <string>

namespace radarpr {

// Reports progress of long work on stderr: a line at most every 3 seconds and one at the end,
// with the time left at the pace so far, so a run on a terminal or in a CI log shows it is alive
// without flooding either. On a terminal the line updates in place; piped, plain lines.
// Where a long run is, for its progress lines: "dataset 3/6", with ", descriptor 5/7" when
// `descriptor` is given (1-based `index` of `count`); empty when the dataset's place is unknown
// (a dataset run on its own).
struct RunPosition {
  std::size_t dataset = 0;  // 1-based; 0: not part of a counted run
  std::size_t datasets = 0;

  std::string text() const;
  std::string text(std::size_t descriptor, std::size_t descriptors) const;
  // " (dataset 3/6)" / " (dataset 3/6, descriptor 5/7)", or "" when unknown, to append to a label.
  std::string suffix() const;
  std::string suffix(std::size_t descriptor, std::size_t descriptors) const;
};

class Progress {
 public:
  Progress(std::string label, std::size_t total, bool enabled = true);
  void advance();  // thread-safe
  void finish();
  // Ends with `line` instead of the count (on a terminal it replaces the updating line).
  void finish(const std::string& line);

 private:
  void print(std::size_t done, bool last);

  std::string label_;
  std::size_t total_;
  bool enabled_;
  std::size_t done_ = 0;
  std::mutex mutex_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_print_;
};

}  // namespace radarpr
