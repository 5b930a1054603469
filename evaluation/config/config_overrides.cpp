#include "evaluation/config/config_overrides.hpp"

#include <charconv>

#include <fmt/format.h>

#include "evaluation/config/config_error.hpp"

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

}  // namespace

void apply_config_override(nlohmann::json& config, const std::string& assignment) {
  const auto equals = assignment.find('=');
  if (equals == std::string::npos || equals == 0) {
    throw ConfigError("--set", fmt::format("expected key.path=value, got '{}'", assignment));
  }
  const std::string path = assignment.substr(0, equals);
  const std::string text = assignment.substr(equals + 1);
  nlohmann::json value = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (value.is_discarded()) value = text;

  const auto segments = split_path(path);
  nlohmann::json* node = &config;
  std::string walked;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const std::string& segment = segments[i];
    const bool last = i + 1 == segments.size();
    if (segment.empty()) throw ConfigError(path, "empty key in --set path");
    walked += (walked.empty() ? "" : ".") + segment;
    if (node->is_array()) {
      std::size_t index = 0;
      const auto [ptr, ec] =
          std::from_chars(segment.data(), segment.data() + segment.size(), index);
      if (ec != std::errc() || ptr != segment.data() + segment.size() || index >= node->size()) {
        throw ConfigError(walked,
                          fmt::format("no element '{}' in an array of {}", segment, node->size()));
      }
      node = &(*node)[index];
    } else if (node->is_object()) {
      if (!last && !node->contains(segment)) {
        throw ConfigError(walked, "no such key in the config");
      }
      node = &(*node)[segment];
    } else {
      throw ConfigError(walked, fmt::format("cannot descend into a {}", node->type_name()));
    }
  }
  *node = std::move(value);
}

}  // namespace radarpr
