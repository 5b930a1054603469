#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "datasets/scan_sequence.hpp"
#include "descriptors/descriptor_registry.hpp"
#include "evaluation/config/experiment_config.hpp"
#include "evaluation/descriptor_cache.hpp"
#include "evaluation/descriptor_training.hpp"
#include "evaluation/progress.hpp"

namespace radarpr {

// One descriptor's values on one session of a dataset.
struct SessionValues {
  std::vector<DescriptorValue> values;  // one per scan of the session
  double mean_extract_ms = 0.0;         // wall time per scan when they were extracted
  bool from_cache = false;              // read from the descriptor cache, not extracted now
  // Instead of `values` (then empty): the cache entry memory-mapped, read in place by the
  // blocked L2 search (obtain_dataset_values with map_single_session_l2).
  std::shared_ptr<const MappedDescriptorValues> mapped;
};

struct DatasetValues {
  // The experiment's descriptors, each trainable one trained for this dataset when some of its
  // values had to be extracted (a descriptor whose values all came from the cache is not
  // trained: evaluation uses only its distance, which must not depend on training).
  std::vector<DescriptorInstance> instances;
  std::vector<SessionValues> query;                     // [descriptor]
  std::vector<SessionValues> database;                  // [descriptor]; empty in a single session
  std::vector<std::optional<TrainingRecord>> training;  // [descriptor]
};

// Whether a descriptor's values may be cached: only descriptors of the global registry, whose
// canonical id fixes what they compute (a test's or a plugin's stand-in with a registered-looking
// id does not qualify).
bool cacheable(const DescriptorInstance& instance);

// Every descriptor's values on `query` (and `database`): read from `cache` where an entry
// exists; otherwise trainable descriptors are trained (on the sequence protocol.train_on names:
// the dataset's training sequence, opened only then, or the database session, or the query
// sequence itself in a single session), each sequence's scans are decoded once for all its
// missing descriptors, in parallel over scans, and the new values are stored in `cache`. When
// every value is cached, no scan is decoded and nothing is trained. Throws like
// extract_descriptors and train_descriptors, and std::runtime_error when a descriptor's values
// differ in shape between scans or sessions. `position` (the dataset's place in the run) goes
// into the progress lines. `map_single_session_l2`: in a single session, the cached values of
// exhaustive_l2 descriptors are memory-mapped (SessionValues::mapped) rather than read, so that
// their search holds a block of them at a time whatever the sequence's length.
DatasetValues obtain_dataset_values(const ExperimentConfig& config, const DatasetConfig& dataset,
                                    const ScanSequence& query, const ScanSequence* database,
                                    const DescriptorCache& cache, bool show_progress,
                                    const RunPosition& position = {},
                                    bool map_single_session_l2 = false);

}  // namespace radarpr
