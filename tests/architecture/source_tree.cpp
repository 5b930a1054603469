#include "source_tree.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace radarpr::test {

std::filesystem::path source_root() {
  return RADARPR_SOURCE_DIR;
}

namespace {

bool is_skipped_folder(const std::filesystem::path& folder) {
  const std::string name = folder.filename().string();
  return name == ".git" || name == "build" || name.starts_with("build-");
}

bool has_suffix(const std::string& name, const std::vector<std::string>& suffixes) {
  return std::any_of(suffixes.begin(), suffixes.end(),
                     [&](const std::string& suffix) { return name.ends_with(suffix); });
}

}  // namespace

std::vector<std::filesystem::path> files_under(const std::filesystem::path& root,
                                               const std::string& folder,
                                               const std::vector<std::string>& suffixes) {
  std::vector<std::filesystem::path> files;
  const std::filesystem::path start = folder.empty() ? root : root / folder;
  if (!std::filesystem::is_directory(start)) return files;
  for (auto it = std::filesystem::recursive_directory_iterator(start);
       it != std::filesystem::recursive_directory_iterator(); ++it) {
    if (it->is_directory() && is_skipped_folder(it->path())) {
      it.disable_recursion_pending();
      continue;
    }
    if (it->is_regular_file() && has_suffix(it->path().filename().string(), suffixes)) {
      files.push_back(it->path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace radarpr::test
