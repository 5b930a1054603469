#include "datasets/real/scan_files.hpp"

#include <algorithm>
#include <stdexcept>
#include <system_error>

#include <fmt/format.h>

#include "datasets/real/text_table.hpp"

namespace radarpr {

void require_folder(const std::filesystem::path& folder, const std::string& what) {
  std::error_code error;
  if (std::filesystem::is_directory(folder, error)) return;
  throw std::runtime_error(fmt::format(
      "{}: {}, expected {}", folder.string(),
      std::filesystem::exists(folder, error) ? "not a folder" : "folder not found", what));
}

std::size_t sort_scans_by_time(std::vector<ScanFile>& scans) {
  std::sort(scans.begin(), scans.end(), [](const ScanFile& a, const ScanFile& b) {
    return a.timestamp_ns != b.timestamp_ns ? a.timestamp_ns < b.timestamp_ns : a.path < b.path;
  });
  std::size_t duplicated = 0;
  for (std::size_t i = 0; i < scans.size(); ++i) {
    const bool same_as_previous = i > 0 && scans[i - 1].timestamp_ns == scans[i].timestamp_ns;
    const bool same_as_next =
        i + 1 < scans.size() && scans[i + 1].timestamp_ns == scans[i].timestamp_ns;
    if (same_as_previous || same_as_next) ++duplicated;
  }
  return duplicated;
}

std::vector<ScanFile> list_timestamped_pngs(const std::filesystem::path& folder,
                                            const std::string& what) {
  require_folder(folder, what);
  std::vector<ScanFile> scans;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    const std::filesystem::path& path = entry.path();
    if (path.extension() != ".png" || !entry.is_regular_file()) continue;
    const auto stamp = parse_unix_time_ns(path.stem().string());
    if (!stamp || path.stem().string().find('.') != std::string::npos) {
      throw std::runtime_error(fmt::format(
          "{}: the file name is not a Unix timestamp; {} must hold PNGs named <µs or ns>.png",
          path.string(), folder.string()));
    }
    scans.push_back({path, *stamp});
  }
  if (scans.empty()) {
    throw std::runtime_error(
        fmt::format("{}: no .png file in the folder, expected {}", folder.string(), what));
  }
  sort_scans_by_time(scans);
  return scans;
}

}  // namespace radarpr
