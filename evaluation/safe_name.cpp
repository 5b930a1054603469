#include "evaluation/safe_name.hpp"

#include <cstdint>

#include <fmt/format.h>

namespace radarpr {
namespace {

bool letter_or_digit(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
}

}  // namespace

std::optional<std::string> unsafe_name_reason(std::string_view name) {
  if (name.empty()) return "is empty";
  if (name.size() > kMaxNameLength) {
    return fmt::format("is {} bytes long (at most {})", name.size(), kMaxNameLength);
  }
  if (!letter_or_digit(name.front()) && name.front() != '_') {
    return fmt::format("starts with '{}'",
                       name.front() == '\0' ? std::string("\\0") : std::string(1, name.front()));
  }
  for (char c : name) {
    if (letter_or_digit(c) || c == '_' || c == '-' || c == '.' || c == '=' || c == '+') continue;
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte >= 0x7f) return fmt::format("holds the byte 0x{:02x}", byte);
    return fmt::format("holds '{}'", c);
  }
  return std::nullopt;
}

std::string descriptor_folder_name(const std::string& id) {
  std::string name;
  for (char c : id) {
    if (c == ':') {
      name += "__";
    } else if (c == ',' || c == '/' || c == '\\' || c == '{' || c == '}') {
      // ',' between parameters; the others inside a path-valued parameter (precomputed's files).
      name += '_';
    } else {
      name += c;
    }
  }
  // A path-valued parameter can make the id longer than a name may be: the start of the name, then
  // a hash of the whole id, which keeps different ids in different folders.
  if (name.size() > kMaxNameLength) {
    std::uint64_t hash = 1469598103934665603ull;  // FNV-1a
    for (const char c : id) {
      hash = (hash ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    }
    name = fmt::format("{}-{:016x}", name.substr(0, kMaxNameLength - 17), hash);
  }
  return name;
}

std::string safe_name_rule() {
  return fmt::format(
      "a name of ASCII letters, digits and _ - . = + starting with a letter, digit or _, at most "
      "{} bytes",
      kMaxNameLength);
}

}  // namespace radarpr
