#include "datasets/real/real_dataset.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "datasets/real/scan_files.hpp"

namespace radarpr {
namespace {

std::string list_subfolders(const std::filesystem::path& root) {
  std::vector<std::string> names;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(root, error)) {
    if (entry.is_directory(error)) names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  if (names.empty()) return "it has no sub-folder";
  constexpr std::size_t kShown = 12;
  const std::size_t shown = std::min(names.size(), kShown);
  return fmt::format(
      "it holds {}{}",
      fmt::join(names.begin(), names.begin() + static_cast<std::ptrdiff_t>(shown), ", "),
      names.size() > shown ? fmt::format(", ... ({} in all)", names.size()) : "");
}

}  // namespace

std::filesystem::path resolve_sequence_folder(const RealDatasetOptions& options,
                                              const std::string& dataset,
                                              const std::string& sequence_contents) {
  if (options.root.empty()) {
    throw std::invalid_argument(fmt::format("the root of {} is empty", dataset));
  }
  require_folder(options.root, "the root of " + dataset);
  if (options.sequence.empty()) return options.root;
  const std::filesystem::path folder = options.root / options.sequence;
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error)) {
    throw std::runtime_error(fmt::format("{}: sequence folder not found, expected {} ({}; {})",
                                         folder.string(), sequence_contents, dataset,
                                         list_subfolders(folder.parent_path())));
  }
  return folder;
}

std::string sequence_name(const std::string& type, const RealDatasetOptions& options) {
  std::filesystem::path root = options.root.lexically_normal();
  if (root.filename().empty()) root = root.parent_path();  // "data/mulran/"
  const std::string label = options.sequence.empty() ? root.filename().string() : options.sequence;
  return fmt::format("{}({})", type, label.empty() ? options.root.string() : label);
}

double checked_resolution(double metres, const std::string& source) {
  if (!(metres > 0.0) || !(metres <= kMaxRangeResolutionM)) {
    throw std::invalid_argument(
        fmt::format("{}: range_resolution_m must be a number of metres per bin in (0, {}], got {}",
                    source, kMaxRangeResolutionM, metres));
  }
  return metres;
}

}  // namespace radarpr
