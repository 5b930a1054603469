#pragma once

#include <optional>
#include <string>
#include <vector>

#include "datasets/scan_sequence.hpp"
#include "descriptors/descriptor_registry.hpp"

namespace radarpr {

// What a trainable descriptor learnt from, for result files.
struct TrainingRecord {
  std::string sequence;    // ScanSequence::name()
  std::size_t scans = 0;   // in the sequence
  std::size_t loaded = 0;  // the distinct scans train() loaded (a capped codebook samples)
  double seconds = 0.0;
  // The descriptor's values came from the descriptor cache, so nothing was trained in this run:
  // this is the record of the run that trained it.
  bool from_cache = false;
  // SHA-256 of the learnt codebook (LearntCodebook::codebook_sha256); empty for descriptors
  // without one.
  std::string codebook_sha256;
};

struct TrainedDescriptors {
  // The experiment's descriptors for one dataset: each trainable one replaced by a fresh instance
  // trained on the training sequence, the others shared as they are.
  std::vector<DescriptorInstance> instances;
  std::vector<std::optional<TrainingRecord>> training;  // per descriptor; empty if not trainable
};

// Trains every trainable descriptor of `descriptors` on `training` (scans loaded on demand). A
// failure names the descriptor and the sequence. With `show_progress`, a line as each training
// starts (its descriptor's `positions` entry appended, when given), the scans read so far every
// few seconds, and the time it took.
TrainedDescriptors train_descriptors(const std::vector<DescriptorInstance>& descriptors,
                                     const ScanSequence& training, bool show_progress,
                                     const std::vector<std::string>& positions = {});

}  // namespace radarpr
