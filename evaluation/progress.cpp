#include "evaluation/progress.hpp"

#include <unistd.h>

#include <cstdio>

#include <fmt/format.h>

namespace radarpr {

std::string RunPosition::text() const {
  return dataset == 0 ? std::string() : fmt::format("dataset {}/{}", dataset, datasets);
}

std::string RunPosition::text(std::size_t descriptor, std::size_t descriptors) const {
  const std::string where = fmt::format("descriptor {}/{}", descriptor, descriptors);
  return dataset == 0 ? where : text() + ", " + where;
}

std::string RunPosition::suffix() const {
  return dataset == 0 ? std::string() : " (" + text() + ")";
}

std::string RunPosition::suffix(std::size_t descriptor, std::size_t descriptors) const {
  return " (" + text(descriptor, descriptors) + ")";
}

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
    print(done_, /*last=*/false);
  }
}

void Progress::finish() {
  std::lock_guard lock(mutex_);
  print(done_, /*last=*/true);
}

void Progress::finish(const std::string& line) {
  std::lock_guard lock(mutex_);
  if (!enabled_) return;
  static const bool terminal = ::isatty(STDERR_FILENO) == 1;
  fmt::print(stderr, "{}  {}\n", terminal ? "\r\033[K" : "", line);
  std::fflush(stderr);
}

void Progress::print(std::size_t done, bool last) {
  if (!enabled_) return;
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  // The time left at the pace so far, while there is work left.
  const std::string eta =
      done > 0 && done < total_
          ? fmt::format(", about {:.0f} s left",
                        seconds * static_cast<double>(total_ - done) / static_cast<double>(done))
          : "";
  // On a terminal one line that updates in place ("\r", cleared to its end), ended at the
  // finish; piped or in a log, plain lines.
  static const bool terminal = ::isatty(STDERR_FILENO) == 1;
  if (terminal) {
    fmt::print(stderr, "\r\033[K  {}: {}/{} ({:.1f} s{}){}", label_, done, total_, seconds, eta,
               last ? "\n" : "");
  } else {
    fmt::print(stderr, "  {}: {}/{} ({:.1f} s{})\n", label_, done, total_, seconds, eta);
  }
  std::fflush(stderr);
}

}  // namespace radarpr
