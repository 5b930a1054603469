#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "datasets/scan_sequence.hpp"
#include "evaluation/config/experiment_config.hpp"
#include "evaluation/descriptor_cache.hpp"
#include "evaluation/descriptor_training.hpp"
#include "evaluation/descriptor_values.hpp"

namespace radarpr {

// A trainable descriptor trained on the matrix's own "training" sequence
// (protocol.train_on = training_sequence) rather than on one of its sessions.
inline constexpr std::size_t kMatrixTrainingSequence = static_cast<std::size_t>(-1);

// One descriptor's values on one session of a matrix. A trainable descriptor's values also
// depend on what it learnt from: the database session of the pair (train_on = database) or the
// matrix's training sequence, so one session has one set of values per codebook.
struct MatrixValueJob {
  std::size_t descriptor = 0;
  std::size_t session = 0;
  std::optional<std::size_t> trained_on;  // a session index or kMatrixTrainingSequence

  friend auto operator<=>(const MatrixValueJob&, const MatrixValueJob&) = default;
};

struct MatrixJobValues {
  SessionValues values;
  std::optional<TrainingRecord> training;  // trainable descriptors
};

// The sequences of a matrix, each opened on first use and then kept (a unit of a plan opens only
// the sessions it describes).
class MatrixSequences {
 public:
  explicit MatrixSequences(const SessionMatrixConfig& matrix) : matrix_(matrix) {}
  const ScanSequence& session(std::size_t index);
  const ScanSequence& training();  // the matrix's "training" sequence
  const SessionMatrixConfig& matrix() const { return matrix_; }
  const ScanSequence& source(std::size_t session_or_training) {
    return session_or_training == kMatrixTrainingSequence ? training()
                                                          : session(session_or_training);
  }

 private:
  const SessionMatrixConfig& matrix_;
  std::map<std::size_t, std::unique_ptr<ScanSequence>> opened_;
};

// The values evaluating `pair` with `descriptor` needs: its query and its database session,
// each under the codebook the descriptor learns for that pair.
std::vector<MatrixValueJob> matrix_pair_jobs(const ExperimentConfig& config,
                                             const SessionMatrixConfig& matrix, std::size_t pair,
                                             std::size_t descriptor);

// What a job's values are stored under in the descriptor cache (the same key an ordinary
// multi-session dataset of that pair uses).
DescriptorCacheKey matrix_job_key(const ExperimentConfig& config, const MatrixValueJob& job,
                                  MatrixSequences& sequences);

// A trainable descriptor trained by another process (a plan's training unit): the instance, as
// trained, and the record of that training.
struct TrainedInstance {
  DescriptorInstance instance;
  TrainingRecord record;
};
// Where obtain_matrix_values gets a trained descriptor from instead of training it: called with
// the descriptor's index and its training source (a session or kMatrixTrainingSequence); it
// throws when it has none.
using TrainedLookup =
    std::function<TrainedInstance(std::size_t descriptor, std::size_t training_source)>;

// The values of `jobs` (duplicates allowed): read from `cache` where an entry exists; otherwise
// each trainable descriptor is trained once per training source, and each session's scans are
// decoded once for all of its missing jobs; new values are stored in `cache`. With
// `keep_values` false (a unit that only fills the cache) the returned entries hold no values, and
// a session's values are let go once stored, so memory holds one session's at a time. With
// `trained`, a trainable descriptor is taken from it, never trained here.
std::map<MatrixValueJob, MatrixJobValues> obtain_matrix_values(
    const ExperimentConfig& config, const std::vector<MatrixValueJob>& jobs,
    MatrixSequences& sequences, const DescriptorCache& cache, bool show_progress,
    bool keep_values = true, const TrainedLookup& trained = {});

// The values of `job` as a memory-mapped cache entry, checked whole (a plan's evaluate unit reads
// them a block at a time: evaluate_mapped_pair_descriptor). Throws std::runtime_error naming the
// job and the entry file when it is missing, of another build or damaged (truncated, wrong size,
// wrong checksum).
MappedDescriptorValues map_matrix_job_values(const ExperimentConfig& config,
                                             const MatrixValueJob& job, MatrixSequences& sequences,
                                             const DescriptorCache& cache);

}  // namespace radarpr
