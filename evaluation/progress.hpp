#pragma once

#include <chrono>
#include <cstddef>
#include <mutex>
#include <string>

namespace radarpr {

// Reports progress of long work on stderr: a line at most every 3 seconds and one at the end,
// with the time left at the pace so far, so a run on a terminal or in a CI log shows it is alive
// without flooding either. On a terminal the line updates in place; piped, plain lines.
class Progress {
 public:
  Progress(std::string label, std::size_t total, bool enabled = true);
  void advance();  // thread-safe
  void finish();

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
