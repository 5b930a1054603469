#include "evaluation/experiment_runner.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include <fmt/format.h>

#include "descriptors/learnt_codebook.hpp"
#include "evaluation/dataset_inspection.hpp"
#include "evaluation/descriptor_cache.hpp"
#include "evaluation/descriptor_values.hpp"
#include "evaluation/session_matrix_values.hpp"

namespace radarpr {
namespace {

// A fixed grid (mulran_grid, thresholds in [0, 1]) can miss a descriptor's distance range
// entirely; say why its ROC AUC is then undefined instead of leaving a bare "n/a".
void warn_if_sweep_accepts_nothing(const DescriptorRun& run, const Protocol& protocol) {
  const auto& curve = run.evaluation.curve;
  const bool accepts_any = std::any_of(curve.begin(), curve.end(), [](const CurvePoint& point) {
    return point.counts.tp + point.counts.fp > 0;
  });
  if (accepts_any || run.evaluation.results.empty()) return;
  const auto [smallest, largest] = std::minmax_element(
      run.evaluation.results.begin(), run.evaluation.results.end(),
      [](const QueryResult& a, const QueryResult& b) { return a.distance < b.distance; });
  fmt::print(
      stderr,
      "warning: the {} sweep accepts no query of {}: its top-1 distances lie in [{:.4g}, {:.4g}], "
      "above every threshold; ROC AUC and F1-max are undefined\n",
      to_string(protocol.sweep), run.id, smallest->distance, largest->distance);
}

void warn_if_every_query_is_a_revisit(const ExperimentConfig& config, const DatasetRun& run);
// A descriptor that gives every scan of a session the same value ranks the database by
// tie-breaking alone, yet the metrics would look plausible (all-blank scans gave Recall@1 0.291):
// such a run is refused, naming the likely causes.
// `scans`: how many values there are when `values` holds only the first few of them.
void refuse_constant_values(const std::vector<DescriptorValue>& values, const std::string& dataset,
                            const std::string& descriptor, const std::string& sequence,
                            std::size_t scans = 0) {
  if (values.size() < 2) return;
  // Bitwise: a descriptor giving NaN for every scan is constant too (and NaN != NaN).
  const auto same = [&](const DescriptorValue& v) {
    const auto& first = values.front();
    return v.rows == first.rows && v.cols == first.cols && v.values.size() == first.values.size() &&
           std::memcmp(v.values.data(), first.values.data(), v.values.size() * sizeof(float)) == 0;
  };
  if (!std::all_of(values.begin() + 1, values.end(), same)) return;
  throw std::runtime_error(fmt::format(
      "dataset '{}': descriptor '{}' gives the same value for all {} scans of {}, so every "
      "database frame ties and the metrics would come from tie-breaking alone; are the scans "
      "blank, too small for the descriptor, or is its range window (min_range) beyond them?",
      dataset, descriptor, std::max(scans, values.size()), sequence));
}

DatasetRun run_dataset(const ExperimentConfig& config, const DatasetConfig& dataset,
                       bool show_progress, const RunPosition& position) {
  const auto query = open_sequence(dataset.query);
  const auto database = dataset.database ? open_sequence(*dataset.database) : nullptr;
  if (query->size() == 0) {
    throw std::runtime_error(
        fmt::format("dataset '{}': {} has no scans with a pose", dataset.name, query->name()));
  }
  if (database && database->size() == 0) {
    throw std::runtime_error(
        fmt::format("dataset '{}': {} has no scans with a pose", dataset.name, database->name()));
  }
  if (show_progress) {
    fmt::print(stderr, "dataset {} ({}/{}): {} ({} scans){}\n", dataset.name, position.dataset,
               position.datasets, query->name(), query->size(),
               database ? fmt::format(" against {} ({} scans)", database->name(), database->size())
                        : std::string(", single session"));
  }

  DatasetRun run = describe_dataset(dataset.name, *query, database.get());

  const DatasetValues values =
      obtain_dataset_values(config, dataset, *query, database.get(),
                            DescriptorCache::from_environment(), show_progress, position,
                            /*map_single_session_l2=*/true);
  for (std::size_t d = 0; d < values.instances.size(); ++d) {
    run.descriptors.push_back(evaluate_dataset_descriptor(
        config, run, values.instances[d], values.query[d], database ? &values.database[d] : nullptr,
        values.training[d], show_progress, position.suffix(d + 1, values.instances.size())));
  }
  warn_if_every_query_is_a_revisit(config, run);
  return run;
}

void warn_if_every_query_is_a_revisit(const ExperimentConfig& config, const DatasetRun& run) {
  // Revisits depend on poses and the protocol only, so every descriptor has the same count.
  const Metrics* counts =
      run.descriptors.empty() ? nullptr : &run.descriptors.front().evaluation.metrics;
  if (counts && counts->revisits > 0 && counts->revisits == counts->queries &&
      config.protocol.labels == LabelRule::standard) {
    fmt::print(stderr,
               "warning: in dataset '{}' every query is a revisit: with the standard labels no "
               "query can be a true negative, so ROC AUC is undefined (F1-max and recall are "
               "not)\n",
               run.name);
  }
  // No revisit, or no eligible query at all, is reported by check_datasets_before_run before any
  // work (the second stops the run), with the cause: the radius or the exclusion.
}

// A session matrix: every session opened once, each session's values obtained once for all its
// pairs (trainable descriptors trained once per training source), then every pair evaluated.
std::vector<DatasetRun> run_matrix(const ExperimentConfig& config,
                                   const SessionMatrixConfig& matrix, bool show_progress,
                                   const RunPosition& position) {
  MatrixSequences sequences(matrix);
  std::vector<MatrixValueJob> jobs;
  for (std::size_t p = 0; p < matrix.pairs.size(); ++p) {
    for (std::size_t d = 0; d < config.descriptors.size(); ++d) {
      for (const auto& job : matrix_pair_jobs(config, matrix, p, d)) jobs.push_back(job);
    }
  }
  if (show_progress) {
    fmt::print(stderr, "session matrix {} ({}/{}): {} sessions, {} pairs\n", matrix.name,
               position.dataset, position.datasets, matrix.sessions.size(), matrix.pairs.size());
  }
  const auto values = obtain_matrix_values(config, jobs, sequences,
                                           DescriptorCache::from_environment(), show_progress);
  std::vector<DatasetRun> runs;
  for (std::size_t p = 0; p < matrix.pairs.size(); ++p) {
    DatasetRun run = describe_matrix_pair(config, matrix, p, sequences);
    for (std::size_t d = 0; d < config.descriptors.size(); ++d) {
      const auto pair_jobs = matrix_pair_jobs(config, matrix, p, d);
      const MatrixJobValues& query = values.at(pair_jobs[0]);
      const MatrixJobValues& database = values.at(pair_jobs[1]);
      run.descriptors.push_back(evaluate_dataset_descriptor(
          config, run, config.descriptors[d], query.values, &database.values,
          database.training ? database.training : query.training, show_progress,
          position.suffix(d + 1, config.descriptors.size())));
    }
    warn_if_every_query_is_a_revisit(config, run);
    runs.push_back(std::move(run));
  }
  return runs;
}

}  // namespace

DatasetRun describe_dataset(const std::string& name, const ScanSequence& query,
                            const ScanSequence* database) {
  DatasetRun run;
  run.name = name;
  run.multi_session = database != nullptr;
  run.query_sequence = query.name();
  run.database_sequence = database ? database->name() : query.name();
  run.query_records = query.records();
  if (database) run.database_records = database->records();
  return run;
}

DatasetRun describe_matrix_pair(const ExperimentConfig& config, const SessionMatrixConfig& matrix,
                                std::size_t pair, MatrixSequences& sequences) {
  const auto [query, database] = matrix.pairs.at(pair);
  return describe_dataset(config.datasets.at(matrix.first_dataset + pair).name,
                          sequences.session(query), &sequences.session(database));
}

namespace {

// The row facts of a descriptor's run that do not come from the evaluation.
DescriptorRun describe_descriptor_run(const DescriptorInstance& instance,
                                      const DescriptorShape& shape, double mean_extract_ms,
                                      bool query_cached, bool database_cached,
                                      const std::optional<TrainingRecord>& training) {
  DescriptorRun descriptor_run;
  descriptor_run.id = instance.id;
  descriptor_run.label = instance.display_name();
  descriptor_run.rows = shape.rows;
  descriptor_run.cols = shape.cols;
  descriptor_run.payload_bytes = shape.payload_bytes();
  descriptor_run.paper_bytes = shape.paper_bytes();
  descriptor_run.rotation_invariant = instance.descriptor->rotation_invariant();
  descriptor_run.mean_extract_ms = mean_extract_ms;
  descriptor_run.query_values_cached = query_cached;
  descriptor_run.database_values_cached = database_cached;
  descriptor_run.training = training;
  if (const LearntCodebook* codebook = learnt_codebook_of(*instance.descriptor)) {
    // A loaded codebook is in the instance; a trained one is known from its training record
    // (also when the values came from the cache and nothing was trained in this run).
    const std::string sha256 = codebook->codebook_loaded_from().empty()
                                   ? (training ? training->codebook_sha256 : std::string())
                                   : codebook->codebook_sha256();
    if (!sha256.empty()) {
      descriptor_run.codebook =
          CodebookRecord{sha256, codebook->codebook_loaded_from(), codebook->codebook_saved_to()};
    }
  }
  return descriptor_run;
}

void refuse_different_lengths(const DatasetRun& run, const DescriptorInstance& instance,
                              std::size_t query_length, std::size_t database_length) {
  if (query_length == database_length) return;
  throw std::runtime_error(fmt::format(
      "dataset '{}': descriptor {} has {} values on the query session but {} on the database "
      "session",
      run.name, instance.id, query_length, database_length));
}

}  // namespace

DescriptorRun evaluate_dataset_descriptor(const ExperimentConfig& config, const DatasetRun& run,
                                          const DescriptorInstance& instance,
                                          const SessionValues& query_values,
                                          const SessionValues* database_values,
                                          const std::optional<TrainingRecord>& training,
                                          bool show_progress, const std::string& position) {
  if (query_values.mapped && database_values == nullptr) {
    // A single session read in place from its cache entry: the same refusals, decided in the
    // map, and the search streamed from it.
    const MappedDescriptorValues& mapped = *query_values.mapped;
    DescriptorRun descriptor_run =
        describe_descriptor_run(instance, {mapped.rows(), mapped.cols()},
                                query_values.mean_extract_ms, true, false, training);
    if (mapped.size() >= 2 && mapped.all_equal()) {
      refuse_constant_values(mapped.read(0, 2), run.name, instance.id, run.query_sequence,
                             mapped.size());
    }
    if (show_progress) fmt::print(stderr, "  evaluating {}{}\n", instance.id, position);
    descriptor_run.evaluation = evaluate_single_session_rows(
        *instance.descriptor, mapped.l2_rows(), run.query_records, config.protocol,
        static_cast<std::size_t>(config.report.recall_curve_n));
    warn_if_sweep_accepts_nothing(descriptor_run, config.protocol);
    return descriptor_run;
  }
  const DescriptorValue& first = query_values.values.front();
  DescriptorRun descriptor_run = describe_descriptor_run(
      instance, {first.rows, first.cols}, query_values.mean_extract_ms, query_values.from_cache,
      database_values && database_values->from_cache, training);
  refuse_constant_values(query_values.values, run.name, instance.id, run.query_sequence);
  if (database_values) {
    refuse_constant_values(database_values->values, run.name, instance.id, run.database_sequence);
  }
  if (database_values && !database_values->values.empty()) {
    refuse_different_lengths(run, instance, first.values.size(),
                             database_values->values.front().values.size());
  }
  if (show_progress) fmt::print(stderr, "  evaluating {}{}\n", instance.id, position);
  descriptor_run.evaluation =
      evaluate_descriptor(*instance.descriptor, query_values.values, run.query_records,
                          database_values ? &database_values->values : nullptr,
                          database_values ? &run.database_records : nullptr, config.protocol,
                          static_cast<std::size_t>(config.report.recall_curve_n));
  warn_if_sweep_accepts_nothing(descriptor_run, config.protocol);
  return descriptor_run;
}

DescriptorRun evaluate_mapped_pair_descriptor(const ExperimentConfig& config, const DatasetRun& run,
                                              const DescriptorInstance& instance,
                                              const MappedDescriptorValues& query_values,
                                              const MappedDescriptorValues& database_values,
                                              const std::optional<TrainingRecord>& training,
                                              bool show_progress, std::size_t block_bytes) {
  DescriptorRun descriptor_run =
      describe_descriptor_run(instance, {query_values.rows(), query_values.cols()},
                              query_values.mean_extract_ms(), true, true, training);
  // The same refusals as evaluate_dataset_descriptor, decided in place in the maps.
  for (const auto* values : {&query_values, &database_values}) {
    if (values->all_equal() && values->size() >= 2) {
      refuse_constant_values(values->read(0, 2), run.name, instance.id,
                             values == &query_values ? run.query_sequence : run.database_sequence,
                             values->size());
    }
  }
  refuse_different_lengths(run, instance, query_values.value_bytes() / sizeof(float),
                           database_values.value_bytes() / sizeof(float));
  if (show_progress) fmt::print(stderr, "  evaluating {}\n", instance.id);
  auto blocks_of = [block_bytes](const MappedDescriptorValues& values) {
    return ValueBlocks{
        values.size(),
        std::max<std::size_t>(1, block_bytes / std::max<std::size_t>(1, values.value_bytes())),
        [&values](std::size_t begin, std::size_t end, std::vector<DescriptorValue>& into) {
          values.read(begin, end, into);
        }};
  };
  descriptor_run.evaluation = evaluate_descriptor_in_blocks(
      *instance.descriptor, blocks_of(query_values), run.query_records, blocks_of(database_values),
      run.database_records, config.protocol,
      static_cast<std::size_t>(config.report.recall_curve_n));
  warn_if_sweep_accepts_nothing(descriptor_run, config.protocol);
  return descriptor_run;
}

ExperimentRun run_experiment(const ExperimentConfig& config, bool show_progress) {
  const auto start = std::chrono::steady_clock::now();
  check_datasets_before_run(config);  // fatal data problems stop the run before any extraction
  ExperimentRun run;
  // The progress lines count the datasets run on their own and the session matrices (each run
  // as one).
  const auto is_run_unit = [&config](const DatasetConfig& dataset) {
    return !dataset.matrix_pair ||
           dataset.name ==
               config.datasets[config.matrices[dataset.matrix_pair->matrix].first_dataset].name;
  };
  RunPosition position;
  position.datasets = static_cast<std::size_t>(
      std::count_if(config.datasets.begin(), config.datasets.end(), is_run_unit));
  for (const auto& dataset : config.datasets) {
    if (!is_run_unit(dataset)) continue;
    ++position.dataset;
    if (!dataset.matrix_pair) {
      run.datasets.push_back(run_dataset(config, dataset, show_progress, position));
    } else {
      for (auto& pair : run_matrix(config, config.matrices[dataset.matrix_pair->matrix],
                                   show_progress, position)) {
        run.datasets.push_back(std::move(pair));
      }
    }
  }
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

}  // namespace radarpr
