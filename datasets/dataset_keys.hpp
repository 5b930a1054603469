#pragma once

#include <cstdint>
#include <exception>
#include <string>

namespace radarpr {

// The keys of one sequence entry of an experiment config ({"type": ..., "root": ..., ...}), as a
// dataset type's parser reads them. The experiment's config reader implements it
// (evaluation/config/config_reader.hpp), so datasets parse their own keys without knowing JSON
// or the experiment, and every error still names the file and the key path. Each getter marks
// its key as known; finish() refuses any key no getter asked for.
class DatasetKeys {
 public:
  virtual ~DatasetKeys() = default;

  // "datasets[0].query": where these keys are, for messages.
  virtual const std::string& path() const = 0;
  virtual bool has(const std::string& key) const = 0;
  // Present and not null.
  virtual bool is_set(const std::string& key) = 0;
  virtual std::string required_string(const std::string& key) = 0;
  virtual std::string string_or(const std::string& key, const std::string& fallback) = 0;
  // A required path; "${NAME}" in it is replaced by the environment variable NAME (an unset one
  // is an error saying how to set it or override the key).
  virtual std::string required_path(const std::string& key) = 0;
  virtual double number_or(const std::string& key, double fallback) = 0;
  virtual std::int64_t integer_or(const std::string& key, std::int64_t fallback) = 0;
  virtual bool boolean_or(const std::string& key, bool fallback) = 0;
  // Throws for the first key that no getter asked for, listing the accepted keys.
  virtual void finish() const = 0;
  // Throws the config's error naming `key` (empty: these keys as a whole) and `message`.
  [[noreturn]] void fail(const std::string& key, const std::string& message) const {
    raise(key, message);
    std::terminate();  // raise() broke its contract
  }

 protected:
  // Throws (never returns) the implementation's error type for fail().
  virtual void raise(const std::string& key, const std::string& message) const = 0;
};

}  // namespace radarpr
