#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace radarpr {

// One scan on disk, before decoding.
struct ScanFile {
  std::filesystem::path path;
  std::int64_t timestamp_ns = 0;
};

// The *.png files of `folder`, each named by its Unix timestamp (µs or ns, told apart by
// magnitude per name), sorted by time (then by name). Throws std::runtime_error naming the folder
// when it is missing, not a folder or holds no PNG, and naming the file whose name is not a
// timestamp. `what` describes the folder for those messages.
std::vector<ScanFile> list_timestamped_pngs(const std::filesystem::path& folder,
                                            const std::string& what);

// Sorts scans by time (then path) and returns how many share a timestamp with another.
std::size_t sort_scans_by_time(std::vector<ScanFile>& scans);

// Throws std::runtime_error naming `folder` (with `what` it should hold) unless it is a folder.
void require_folder(const std::filesystem::path& folder, const std::string& what);

}  // namespace radarpr
