#pragma once

#include "datasets/dataset_types.hpp"
#include "evaluation/config/config_reader.hpp"

namespace radarpr {

// Reads {"type": ..., <that type's keys>}: the dataset types' table (datasets/dataset_types.hpp)
// parses each type's keys; a real dataset's "root" may hold ${ENV_VARIABLES}. Throws ConfigError
// naming the key path.
inline SequenceConfig parse_sequence_config(ConfigReader reader) {
  return parse_sequence_keys(reader);
}

}  // namespace radarpr
