#include "evaluation/results/staging_folder.hpp"

#include <system_error>

#include "datasets/stale_temporaries.hpp"

namespace radarpr {

namespace fs = std::filesystem;

void remove_stale_staging(const fs::path& folder, const std::string& prefix) {
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(folder, error)) {
    const std::string name = entry.path().filename().string();
    if (!name.starts_with(prefix)) continue;
    const std::string digits = name.substr(prefix.size());
    if (digits.empty() || digits.size() > 9 ||
        digits.find_first_not_of("0123456789") != std::string::npos)
      continue;
    const long pid = std::stol(digits);
    // A live run or report keeps its own.
    if (process_has_ended(pid)) {
      std::error_code ignored;
      fs::remove_all(entry.path(), ignored);
    }
  }
}

void publish_staged(const fs::path& staging, const fs::path& target) {
  for (const auto& entry : fs::directory_iterator(staging)) {
    const fs::path destination = target / entry.path().filename();
    // A folder (figures/) is merged file by file: a user's own files there (an edited copy of
    // a script) are kept, only the names the report writes are replaced.
    if (entry.is_directory() && fs::is_directory(destination)) {
      publish_staged(entry.path(), destination);
      continue;
    }
    fs::remove_all(destination);
    fs::rename(entry.path(), destination);
  }
  fs::remove_all(staging);
}

}  // namespace radarpr
