#pragma once

#include <filesystem>
#include <system_error>

namespace radarpr {

// Whether `path` is `folder` or lies inside it, symbolic links resolved as far as they exist
// (so "a/../b", a link to `folder` and a folder not yet created are all judged by where they
// lead). Used to refuse an output folder that would hold, or sit inside, what a command reads.
inline bool is_inside(const std::filesystem::path& path, const std::filesystem::path& folder) {
  std::error_code error;
  const auto inner = std::filesystem::weakly_canonical(std::filesystem::absolute(path), error);
  if (error) return false;
  const auto outer = std::filesystem::weakly_canonical(std::filesystem::absolute(folder), error);
  if (error) return false;
  auto i = inner.begin();
  for (auto o = outer.begin(); o != outer.end(); ++o, ++i) {
    if (o->empty()) continue;  // the empty last element of "a/b/"
    if (i == inner.end() || *i != *o) return false;
  }
  return true;
}

}  // namespace radarpr
