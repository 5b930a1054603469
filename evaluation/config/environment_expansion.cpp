#include "evaluation/config/environment_expansion.hpp"

#include <cstdlib>

#include <fmt/format.h>

#include "evaluation/config/config_error.hpp"

namespace radarpr {

std::string override_path(const std::string& key_path) {
  std::string path;
  path.reserve(key_path.size());
  for (const char c : key_path) {
    if (c == '[') {
      path += '.';
    } else if (c != ']') {
      path += c;
    }
  }
  return path;
}

std::string expand_environment_variables(const std::string& text, const std::string& key_path) {
  std::string expanded;
  std::size_t position = 0;
  while (true) {
    const auto start = text.find("${", position);
    if (start == std::string::npos) break;
    const auto close = text.find('}', start + 2);
    if (close == std::string::npos) {
      throw ConfigError(key_path, fmt::format("unterminated '${{' in '{}'", text));
    }
    const std::string name = text.substr(start + 2, close - start - 2);
    if (name.empty()) throw ConfigError(key_path, fmt::format("empty '${{}}' in '{}'", text));
    const char* value = std::getenv(name.c_str());
    if (value == nullptr || *value == '\0') {
      throw ConfigError(
          key_path,
          fmt::format("environment variable {} is {}; set it to your copy of the dataset "
                      "(export {}=/path/to/dataset) or pass --set {}=/path/to/dataset",
                      name, value == nullptr ? "not set" : "empty", name, override_path(key_path)));
    }
    expanded += text.substr(position, start - position);
    expanded += value;
    position = close + 1;
  }
  return expanded + text.substr(position);
}

}  // namespace radarpr
