#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "datasets/dataset_keys.hpp"
#include "datasets/scan_sequence.hpp"
#include "datasets/synthetic/synthetic_sequence.hpp"

namespace radarpr {

// A sequence named in a config ("query", "database" or "training"), checked when the config is
// read; its scans are only generated or decoded when it is opened.
struct SequenceConfig {
  std::string type;  // a row of dataset_types(): "synthetic", "mulran", ...
  std::function<std::unique_ptr<ScanSequence>()> open;
  // Type "synthetic" only: the generator's config, for `radarpr simulate` to render from.
  std::shared_ptr<const SyntheticConfig> synthetic;
};

inline std::unique_ptr<ScanSequence> open_sequence(const SequenceConfig& config) {
  return config.open();
}

// A dataset type: the name a config gives as "type", and the parser of that type's keys (which
// reads every key it accepts, checks them, and calls keys.finish()).
struct DatasetType {
  std::string name;
  SequenceConfig (*parse)(DatasetKeys& keys);
};

// Every dataset type, one row each (datasets/dataset_types.cpp). Adding a type is one loader
// file with its parser, and one row.
const std::vector<DatasetType>& dataset_types();

// Reads {"type": ..., <that type's keys>}: the row named by "type" parses the rest. An unknown
// type is an error (through keys.fail) listing the known ones.
SequenceConfig parse_sequence_keys(DatasetKeys& keys);

}  // namespace radarpr
