#include "evaluation/config/config_reader.hpp"

#include <cmath>
#include <cstdint>
#include <limits>

#include <fmt/format.h>

#include "evaluation/config/environment_expansion.hpp"

namespace radarpr {
namespace {

std::string type_name(const nlohmann::json& value) {
  return value.type_name();
}

}  // namespace

ConfigReader::ConfigReader(const nlohmann::json& object, std::string path)
    : object_(object), path_(std::move(path)) {
  if (!object_.is_object()) {
    throw ConfigError(path_, fmt::format("expected a JSON object, got {}", type_name(object_)));
  }
}

std::string ConfigReader::path_of(const std::string& key) const {
  if (key.empty()) return path_;
  return path_.empty() ? key : path_ + "." + key;
}

bool ConfigReader::has(const std::string& key) const {
  return object_.contains(key);
}

const nlohmann::json* ConfigReader::find(const std::string& key) {
  asked_.insert(key);
  const auto it = object_.find(key);
  if (it == object_.end()) return nullptr;
  read_.insert(key);
  return &*it;
}

void ConfigReader::fail(const std::string& key, const std::string& message) const {
  throw ConfigError(path_of(key), message);
}

std::string ConfigReader::required_string(const std::string& key) {
  const auto* value = find(key);
  if (value == nullptr) fail(key, "required key is missing (expected a string)");
  if (!value->is_string()) fail(key, fmt::format("expected a string, got {}", type_name(*value)));
  return value->get<std::string>();
}

bool ConfigReader::is_set(const std::string& key) {
  const auto* value = find(key);
  return value != nullptr && !value->is_null();
}

std::string ConfigReader::required_path(const std::string& key) {
  return expand_environment_variables(required_string(key), path_of(key));
}

std::string ConfigReader::string_or(const std::string& key, const std::string& fallback) {
  const auto* value = find(key);
  if (value == nullptr) return fallback;
  if (!value->is_string()) fail(key, fmt::format("expected a string, got {}", type_name(*value)));
  return value->get<std::string>();
}

double ConfigReader::number_or(const std::string& key, double fallback) {
  const auto* value = find(key);
  if (value == nullptr) return fallback;
  if (!value->is_number()) fail(key, fmt::format("expected a number, got {}", value->dump()));
  return value->get<double>();
}

std::int64_t ConfigReader::integer_or(const std::string& key, std::int64_t fallback) {
  const auto* value = find(key);
  if (value == nullptr) return fallback;
  // A JSON integer above 2^63 - 1 is stored unsigned: read as int64 it would wrap to a negative
  // number, and a range check after that would report a value nobody wrote.
  if (value->is_number_unsigned() &&
      value->get<std::uint64_t>() > std::uint64_t(std::numeric_limits<std::int64_t>::max())) {
    fail(key, fmt::format("expected an integer, got {} (beyond {})", value->dump(),
                          std::numeric_limits<std::int64_t>::max()));
  }
  if (value->is_number_integer()) return value->get<std::int64_t>();
  if (value->is_number_float()) {
    const double number = value->get<double>();
    if (std::trunc(number) == number && std::abs(number) < 9e15) {
      return static_cast<std::int64_t>(number);
    }
  }
  fail(key, fmt::format("expected an integer, got {}", value->dump()));
}

bool ConfigReader::boolean_or(const std::string& key, bool fallback) {
  const auto* value = find(key);
  if (value == nullptr) return fallback;
  if (!value->is_boolean()) fail(key, fmt::format("expected true or false, got {}", value->dump()));
  return value->get<bool>();
}

const nlohmann::json& ConfigReader::value(const std::string& key) {
  static const nlohmann::json null_value;
  const auto* found = find(key);
  return found == nullptr ? null_value : *found;
}

ConfigReader ConfigReader::object(const std::string& key) {
  const auto* value = find(key);
  if (value == nullptr) fail(key, "required key is missing (expected an object)");
  return ConfigReader(*value, path_of(key));
}

std::vector<std::pair<const nlohmann::json*, std::string>> ConfigReader::array(
    const std::string& key) {
  const auto* value = find(key);
  if (value == nullptr) fail(key, "required key is missing (expected an array)");
  if (!value->is_array()) fail(key, fmt::format("expected an array, got {}", type_name(*value)));
  std::vector<std::pair<const nlohmann::json*, std::string>> elements;
  for (std::size_t i = 0; i < value->size(); ++i) {
    elements.emplace_back(&(*value)[i], fmt::format("{}[{}]", path_of(key), i));
  }
  return elements;
}

void ConfigReader::finish() const {
  for (const auto& [key, _] : object_.items()) {
    if (read_.count(key) == 0) {
      fail(key, fmt::format("unknown key (expected one of: {})", fmt::join(asked_, ", ")));
    }
  }
}

}  // namespace radarpr
