#pragma once

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "datasets/dataset_keys.hpp"
#include "evaluation/config/config_error.hpp"

namespace radarpr {

// Reads one JSON object of a config while remembering where it is ("datasets[0].sequence"), so
// every error names its key path, and which keys were read, so a typo'd key is reported rather
// than silently ignored (finish() throws for any key nobody asked for). Dataset types read their
// keys through it as DatasetKeys.
class ConfigReader : public DatasetKeys {
 public:
  ConfigReader(const nlohmann::json& object, std::string path);

  const std::string& path() const override { return path_; }
  std::string path_of(const std::string& key) const;
  bool has(const std::string& key) const override;

  std::string required_string(const std::string& key) override;
  std::string string_or(const std::string& key, const std::string& fallback) override;
  double number_or(const std::string& key, double fallback) override;
  std::int64_t integer_or(const std::string& key, std::int64_t fallback) override;
  bool boolean_or(const std::string& key, bool fallback) override;
  bool is_set(const std::string& key) override;
  // ${NAME} expanded from the environment (environment_expansion.hpp).
  std::string required_path(const std::string& key) override;
  // The raw value (marked as read); null when absent.
  const nlohmann::json& value(const std::string& key);
  ConfigReader object(const std::string& key);  // throws when absent or not an object
  // Elements of an array (throws when absent or not an array), with their key paths.
  std::vector<std::pair<const nlohmann::json*, std::string>> array(const std::string& key);

  // Throws for the first key that was never read, listing the keys this object accepts.
  void finish() const override;

  [[noreturn]] void fail(const std::string& key, const std::string& message) const;

 protected:
  void raise(const std::string& key, const std::string& message) const override {
    fail(key, message);
  }

 private:
  const nlohmann::json* find(const std::string& key);

  const nlohmann::json& object_;
  std::string path_;
  std::set<std::string> read_;
  std::set<std::string> asked_;
};

}  // namespace radarpr
