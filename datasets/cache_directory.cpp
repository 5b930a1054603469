#include "datasets/cache_directory.hpp"

#include <cstdlib>
#include <mutex>
#include <string>
#include <utility>

namespace radarpr {
namespace {

std::mutex override_mutex;
std::optional<std::filesystem::path> overridden;

std::optional<std::filesystem::path> unless_off(const std::filesystem::path& directory) {
  if (directory == "off") return std::nullopt;
  return directory;
}

const char* non_empty_environment(const char* name) {
  const char* value = std::getenv(name);
  return value != nullptr && *value != '\0' ? value : nullptr;
}

}  // namespace

std::optional<std::filesystem::path> cache_directory() {
  {
    const std::lock_guard lock(override_mutex);
    if (overridden) return unless_off(*overridden);
  }
  if (const char* dir = non_empty_environment("RADARPR_CACHE_DIR")) return unless_off(dir);
  if (const char* xdg = non_empty_environment("XDG_CACHE_HOME")) {
    return std::filesystem::path(xdg) / "radarpr";
  }
  if (const char* home = non_empty_environment("HOME")) {
    return std::filesystem::path(home) / ".cache" / "radarpr";
  }
  // No home (a bare container): the system's temporary folder still outlives one run.
  return std::filesystem::temp_directory_path() / "radarpr-cache";
}

void override_cache_directory(std::optional<std::filesystem::path> directory) {
  const std::lock_guard lock(override_mutex);
  overridden = std::move(directory);
}

}  // namespace radarpr
