#include "evaluation/config/config_overrides.hpp"

#include <charconv>
#include <cmath>

#include <fmt/format.h>

namespace radarpr {
namespace {

std::vector<std::string> split_path(const std::string& path) {
  std::vector<std::string> segments;
  std::size_t start = 0;
  while (true) {
    const auto dot = path.find('.', start);
    segments.push_back(path.substr(start, dot - start));
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  return segments;
}

// Whether the value holds a number JSON cannot spell (nlohmann reads 1e999 as infinity).
bool holds_non_finite(const nlohmann::json& value) {
  if (value.is_number_float()) return !std::isfinite(value.get<double>());
  if (value.is_structured()) {
    for (const auto& element : value) {
      if (holds_non_finite(element)) return true;
    }
  }
  return false;
}

// "datasets[0].query" -> "datasets.0.query", the spelling of an override's path.
std::string dotted(const std::string& key_path) {
  std::string path;
  for (const char c : key_path) {
    if (c == '[') {
      path += '.';
    } else if (c != ']') {
      path += c;
    }
  }
  return path;
}

// Whether `text` is valid UTF-8, by the JSON library's own rule for strings.
bool is_utf8(const std::string& text) {
  try {
    static_cast<void>(nlohmann::json(text).dump());
    return true;
  } catch (const nlohmann::json::type_error&) {
    return false;
  }
}

}  // namespace

std::string override_behind(const std::string& key_path,
                            const std::vector<std::string>& overrides) {
  const std::string key = dotted(key_path);
  if (key.empty()) return "";
  for (auto it = overrides.rbegin(); it != overrides.rend(); ++it) {
    const std::string path = it->substr(0, it->find('='));
    if (path == key || key.starts_with(path + ".") || path.starts_with(key + ".")) return *it;
  }
  return "";
}

void apply_config_override(nlohmann::json& config, const std::string& assignment) {
  const auto equals = assignment.find('=');
  if (equals == std::string::npos || equals == 0) {
    throw OverrideError(assignment, "expected KEY.PATH=VALUE");
  }
  // A config file is UTF-8 (the JSON reader refuses other bytes); an override may not smuggle
  // other bytes in, which every later message quoting the value would fail to show.
  if (!is_utf8(assignment)) {
    throw OverrideError(assignment, "not UTF-8 text (a config holds UTF-8 text only)");
  }
  const std::string path = assignment.substr(0, equals);
  const std::string text = assignment.substr(equals + 1);
  nlohmann::json value = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (value.is_discarded()) value = text;
  if (holds_non_finite(value)) {
    throw OverrideError(assignment, path, fmt::format("'{}' is not a finite number", text));
  }

  const auto segments = split_path(path);
  nlohmann::json* node = &config;
  std::string walked;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const std::string& segment = segments[i];
    const bool last = i + 1 == segments.size();
    if (segment.empty()) throw OverrideError(assignment, path, "empty key in the path");
    walked += (walked.empty() ? "" : ".") + segment;
    if (node->is_array()) {
      std::size_t index = 0;
      const auto [ptr, ec] =
          std::from_chars(segment.data(), segment.data() + segment.size(), index);
      if (ec != std::errc() || ptr != segment.data() + segment.size() || index >= node->size()) {
        throw OverrideError(
            assignment, walked,
            fmt::format("no element '{}' in an array of {}", segment, node->size()));
      }
      node = &(*node)[index];
    } else if (node->is_object()) {
      if (!last && !node->contains(segment)) {
        throw OverrideError(assignment, walked, "no such key in the config");
      }
      node = &(*node)[segment];
    } else {
      throw OverrideError(assignment, walked,
                          fmt::format("cannot descend into a {}", node->type_name()));
    }
  }
  *node = std::move(value);
}

}  // namespace radarpr
