#pragma once

#include <memory>
#include <string>
#include <vector>

#include "datasets/dataset_keys.hpp"
#include "datasets/dataset_types.hpp"
#include "datasets/real/real_dataset.hpp"

namespace radarpr {

// Reads the keys every real dataset type takes: root (required; ${VARIABLES} expanded),
// sequence, every_nth, start, end, range_resolution_m, max_pose_gap_s. Fails (keys.fail) naming
// the key of a bad value.
RealDatasetOptions read_real_dataset_keys(DatasetKeys& keys);

// A string key that must be one of `choices`; absent = the first.
std::string read_choice(DatasetKeys& keys, const std::string& key,
                        const std::vector<std::string>& choices);

// The keys are checked now; the folder is only read when the sequence is opened.
template <typename Options>
SequenceConfig real_sequence_config(const std::string& type, Options options,
                                    std::unique_ptr<ScanSequence> (*open)(const Options&)) {
  return {type, [options, open] { return open(options); }, nullptr};
}

}  // namespace radarpr
