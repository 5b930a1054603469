#include "evaluation/progress.hpp"

#include <cstdio>

#include <fmt/format.h>

namespace radarpr {

Progress::Progress(std::string label, std::size_t total, bool enabled)
    : label_(std::move(label)),
      total_(total),
      enabled_(enabled),
      start_(std::chrono::steady_clock::now()),
      last_print_(start_) {}

void Progress::advance() {
  std::lock_guard lock(mutex_);
  ++done_;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_print_ >= std::chrono::seconds(3) && done_ < total_) {
    last_print_ = now;
    print(done_);
  }
}

void Progress::finish() {
  std::lock_guard lock(mutex_);
  print(done_);
}

void Progress::print(std::size_t done) {
  if (!enabled_) return;
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  fmt::print(stderr, "  {}: {}/{} ({:.1f} s)\n", label_, done, total_, seconds);
  std::fflush(stderr);
}

}  // namespace radarpr
