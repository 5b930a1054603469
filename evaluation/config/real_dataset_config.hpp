#pragma once

#include <string>

#include "evaluation/config/sequence_config.hpp"

namespace radarpr {

class ConfigReader;

// mulran, oxford, boreas, oord, radiate, folder.
bool is_real_dataset_type(const std::string& type);

// Reads a real dataset's keys (README, "Real datasets"): {type, root, sequence, every_nth, start,
// end, range_resolution_m, max_pose_gap_s} and the type's own. "${VARIABLE}" in root is
// expanded from the environment. Throws ConfigError naming the key path; the files are only
// read when the sequence is opened.
SequenceConfig parse_real_dataset_config(const std::string& type, ConfigReader& reader);

}  // namespace radarpr
