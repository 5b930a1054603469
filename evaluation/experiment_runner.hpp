#pragma once

#include <optional>
#include <string>
#include <vector>

#include "evaluation/config/experiment_config.hpp"
#include "evaluation/descriptor_evaluation.hpp"
#include "evaluation/descriptor_training.hpp"

namespace radarpr {

// The codebook a descriptor with a learnt codebook used (LearntCodebook), for result files.
struct CodebookRecord {
  std::string sha256;
  std::string loaded_from;  // the file given as codebook=; empty when trained in the run
  std::string saved_to;     // the file given as save_codebook=; empty when none
};

// One descriptor on one dataset, with the size facts every result row carries (descriptors.md §7).
struct DescriptorRun {
  std::string id;
  std::string label;  // the name tables use: the config's label, or the id
  int rows = 0;
  int cols = 0;
  std::size_t payload_bytes = 0;  // elements x 4 (float32, as stored)
  std::size_t paper_bytes =
      0;  // elements x 8 + 128 (float64 numpy file, the ReFeree paper's convention)
  bool rotation_invariant = false;
  double mean_extract_ms = 0.0;  // query session; measured by the run that extracted the values
  // The values were read from the descriptor cache rather than extracted in this run.
  bool query_values_cached = false;
  bool database_values_cached = false;     // multi session only
  std::optional<TrainingRecord> training;  // trainable descriptors only
  std::optional<CodebookRecord> codebook;  // descriptors with a learnt codebook only
  DescriptorEvaluation evaluation;
};

struct DatasetRun {
  std::string name;
  bool multi_session = false;
  std::string query_sequence;     // ScanSequence::name()
  std::string database_sequence;  // same as query_sequence in a single session
  std::vector<ScanRecord> query_records;
  std::vector<ScanRecord> database_records;  // empty in a single session (= query_records)
  std::vector<DescriptorRun> descriptors;

  const std::vector<ScanRecord>& database() const {
    return multi_session ? database_records : query_records;
  }
};

struct ExperimentRun {
  std::vector<DatasetRun> datasets;
  double seconds = 0.0;
};

// Runs every dataset of `config`; a session matrix's pairs share their sessions' values.
ExperimentRun run_experiment(const ExperimentConfig& config, bool show_progress);

class MatrixSequences;
struct SessionValues;
class MappedDescriptorValues;

// A dataset's DatasetRun without descriptors: names and records of its sessions.
DatasetRun describe_dataset(const std::string& name, const ScanSequence& query,
                            const ScanSequence* database);
// A matrix pair's DatasetRun without descriptors: names and records of its two sessions.
DatasetRun describe_matrix_pair(const ExperimentConfig& config, const SessionMatrixConfig& matrix,
                                std::size_t pair, MatrixSequences& sequences);

// One descriptor's values evaluated on `run` (its records set): retrieval, metrics, the size
// facts of the result row. Single session when `database_values` is null. `position` is appended
// to its progress line (" (dataset 3/6, descriptor 5/7)").
DescriptorRun evaluate_dataset_descriptor(const ExperimentConfig& config, const DatasetRun& run,
                                          const DescriptorInstance& instance,
                                          const SessionValues& query_values,
                                          const SessionValues* database_values,
                                          const std::optional<TrainingRecord>& training,
                                          bool show_progress, const std::string& position = "");

// How many bytes of values evaluate_mapped_pair_descriptor reads at a time, per session: 256 MiB
// is 2,048 Open-RadVLAD values of 128 KiB, 8 blocks of queries for the exhaustive L2 search's
// threads (blocked_l2_search.hpp), while a ReFeree session of a million scans is one block.
inline constexpr std::size_t kEvaluationBlockBytes = std::size_t{256} << 20;

// The same for two sessions whose values are memory-mapped cache entries (a plan's evaluate
// unit), read `block_bytes` of values at a time per session (evaluate_descriptor_in_blocks): the
// evaluation holds at most two such blocks of values, whatever the sessions' sizes. The result is
// the one evaluate_dataset_descriptor gives on the same values, read whole.
DescriptorRun evaluate_mapped_pair_descriptor(const ExperimentConfig& config, const DatasetRun& run,
                                              const DescriptorInstance& instance,
                                              const MappedDescriptorValues& query_values,
                                              const MappedDescriptorValues& database_values,
                                              const std::optional<TrainingRecord>& training,
                                              bool show_progress,
                                              std::size_t block_bytes = kEvaluationBlockBytes);

}  // namespace radarpr
