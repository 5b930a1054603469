#pragma once

#include <stdexcept>
#include <string>

namespace radarpr {

// A problem in an experiment config. The message leads with the file (when known) and the
// offending key path: "configs/x.json: protocol.revisit_radius_m: must be > 0, got -5".
class ConfigError : public std::runtime_error {
 public:
  ConfigError(const std::string& key_path, const std::string& message, const std::string& file = "")
      : std::runtime_error((file.empty() ? "" : file + ": ") +
                           (key_path.empty() ? std::string("(top level)") : key_path) + ": " +
                           message),
        key_path_(key_path),
        message_(message) {}

  const std::string& key_path() const { return key_path_; }
  const std::string& message() const { return message_; }
  // The same error, now naming the config file it came from.
  ConfigError in_file(const std::string& file) const { return {key_path_, message_, file}; }

 protected:
  // For an error with no key path to name: "<source>: <message>".
  struct Unkeyed {};
  ConfigError(Unkeyed, const std::string& source, const std::string& message)
      : std::runtime_error(source + ": " + message), message_(message) {}

 private:
  std::string key_path_;
  std::string message_;
};

}  // namespace radarpr
