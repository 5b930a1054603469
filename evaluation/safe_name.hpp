#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace radarpr {

// Names that become file or folder names under --out or the cache (experiment and dataset
// names, descriptor ids once made folder names, figure names) must name exactly one entry inside
// that folder: an absolute path, '..', a '/', a NUL or a very long name must not take a write
// (or a read) anywhere else. The alphabet is ASCII letters, digits and _ - . = + (a parameter value
// of 1e+16 in a descriptor id); the first character is a letter, digit or '_' (no hidden files,
// nothing a program reads as an option); at most kMaxNameLength bytes, well under the file systems'
// 255 with room for suffixes.
inline constexpr std::size_t kMaxNameLength = 100;

// Why `name` is not a safe name (a sentence fragment, e.g. "holds '/'"), or nothing when it is.
std::optional<std::string> unsafe_name_reason(std::string_view name);

inline bool is_safe_name(std::string_view name) {
  return !unsafe_name_reason(name);
}

// The folder name of a descriptor id: ':' -> "__", ',' -> '_' (built-in ids hold
// [a-z0-9_=.:,-]); '/', '\\', '{' and '}' (a path-valued parameter) -> '_'; a name longer than
// kMaxNameLength is cut and ends in '-' and a 16-hex-digit hash of the id. The result is then
// checked with unsafe_name_reason like any other name.
std::string descriptor_folder_name(const std::string& id);

// The rule above in words, for error messages.
std::string safe_name_rule();

}  // namespace radarpr
