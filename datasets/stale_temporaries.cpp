#include "datasets/stale_temporaries.hpp"

#include <signal.h>

#include <cerrno>
#include <optional>
#include <string>
#include <system_error>

namespace radarpr {
namespace {

// The writer's process id in a temporary file's name, if the name is one.
std::optional<long> writer_of(const std::string& name) {
  for (const char* marker : {".tmp-", ".tmp."}) {
    const std::size_t at = name.rfind(marker);
    if (at == std::string::npos) continue;
    const std::size_t first = at + 5;
    std::size_t last = first;
    while (last < name.size() && name[last] >= '0' && name[last] <= '9') ++last;
    // Process ids have at most 7 digits on Linux (pid_max <= 2^22); 9 keeps any in range of a
    // long and refuses what is no id.
    if (last == first || last - first > 9) continue;
    if (last < name.size() && name[last] != '-' && name[last] != '.') continue;
    return std::stol(name.substr(first, last - first));
  }
  return std::nullopt;
}

}  // namespace

bool process_has_ended(long pid) {
  return pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
}

void remove_stale_temporary_files(const std::filesystem::path& folder) {
  std::error_code error;
  for (auto it = std::filesystem::directory_iterator(folder, error);
       !error && it != std::filesystem::directory_iterator(); it.increment(error)) {
    const auto writer = writer_of(it->path().filename().string());
    if (!writer || !process_has_ended(*writer)) continue;
    std::error_code ignored;
    if (it->is_regular_file(ignored)) std::filesystem::remove(it->path(), ignored);
  }
}

}  // namespace radarpr
