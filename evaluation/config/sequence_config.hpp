#pragma once

#include <functional>
#include <memory>
#include <string>

#include "datasets/scan_sequence.hpp"
#include "datasets/synthetic/synthetic_sequence.hpp"

namespace radarpr {

class ConfigReader;

// A sequence named in a config ("query" or "database"), validated when the config is read; the
// scans are only generated or decoded when the runner opens it.
struct SequenceConfig {
  std::string type;  // "synthetic", "mulran", "oxford", "boreas", "oord", "radiate", "folder"
  std::function<std::unique_ptr<ScanSequence>()> open;
  // Type "synthetic" only: the generator's config, for `radarpr simulate` to render from.
  std::shared_ptr<const SyntheticConfig> synthetic;
};

// Reads {"type": ..., <that type's keys>} (README, "Real datasets"; a real dataset's "root" may
// hold ${ENV_VARIABLES}); throws ConfigError naming the key path.
SequenceConfig parse_sequence_config(ConfigReader reader);

inline std::unique_ptr<ScanSequence> open_sequence(const SequenceConfig& spec) {
  return spec.open();
}

}  // namespace radarpr
