#include "datasets/warn_once.hpp"

#include <cstdio>
#include <mutex>
#include <set>

#include <fmt/format.h>

namespace radarpr {

void warn_once(const std::string& message) {
  static std::mutex mutex;
  static std::set<std::string> said;
  const std::lock_guard lock(mutex);
  if (!said.insert(message).second) return;
  fmt::print(stderr, "warning: {}\n", message);
  std::fflush(stderr);
}

}  // namespace radarpr
