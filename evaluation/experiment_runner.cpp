#include "evaluation/experiment_runner.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <stdexcept>

#include <fmt/format.h>

#include "evaluation/dataset_inspection.hpp"
#include "evaluation/descriptor_extraction.hpp"

namespace radarpr {
namespace {

// Every scan of a descriptor must give the same shape, or retrieval would compare unlike things.
void check_uniform_shape(const std::string& id, const std::string& sequence,
                         const std::vector<DescriptorValue>& values) {
  for (std::size_t i = 1; i < values.size(); ++i) {
    if (values[i].rows != values[0].rows || values[i].cols != values[0].cols ||
        values[i].values.size() != values[0].values.size()) {
      throw std::runtime_error(fmt::format(
          "{}: descriptor {} gave shape {}x{} on scan 0 but {}x{} on scan {} (scans of one "
          "dataset must share A and R)",
          sequence, id, values[0].rows, values[0].cols, values[i].rows, values[i].cols, i));
    }
  }
}

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

// Trainable descriptors learn per dataset, from the scans protocol.train_on names; the training
// sequence is only opened when some descriptor needs it.
TrainedDescriptors train_where_needed(const ExperimentConfig& config, const DatasetConfig& dataset,
                                      const ScanSequence& query, const ScanSequence* database,
                                      bool show_progress) {
  const bool any_trainable =
      std::any_of(config.descriptors.begin(), config.descriptors.end(),
                  [](const DescriptorInstance& d) { return d.descriptor->trainable(); });
  if (!any_trainable) {
    return {config.descriptors,
            std::vector<std::optional<TrainingRecord>>(config.descriptors.size())};
  }
  if (config.protocol.train_on == TrainingSource::training_sequence) {
    if (!dataset.training) {
      throw std::logic_error(fmt::format("dataset '{}' has no training sequence", dataset.name));
    }
    const auto training = open_sequence(*dataset.training);
    if (training->size() == 0) {
      throw std::runtime_error(fmt::format("dataset '{}': the training sequence {} has no scans",
                                           dataset.name, training->name()));
    }
    return train_descriptors(config.descriptors, *training, show_progress);
  }
  return train_descriptors(config.descriptors, database ? *database : query, show_progress);
}

DatasetRun run_dataset(const ExperimentConfig& config, const DatasetConfig& dataset,
                       bool show_progress) {
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
    fmt::print(stderr, "dataset {}: {} ({} scans){}\n", dataset.name, query->name(), query->size(),
               database ? fmt::format(" against {} ({} scans)", database->name(), database->size())
                        : std::string(", single session"));
  }

  DatasetRun run;
  run.name = dataset.name;
  run.multi_session = database != nullptr;
  run.query_sequence = query->name();
  run.database_sequence = database ? database->name() : query->name();
  run.query_records = query->records();
  if (database) run.database_records = database->records();

  const TrainedDescriptors trained =
      train_where_needed(config, dataset, *query, database.get(), show_progress);
  const std::vector<DescriptorInstance>& descriptors = trained.instances;
  const auto query_values = extract_descriptors(*query, descriptors, config.threads,
                                                "extracting " + query->name(), show_progress);
  ExtractedDescriptors database_values;
  if (database) {
    database_values = extract_descriptors(*database, descriptors, config.threads,
                                          "extracting " + database->name(), show_progress);
  }

  for (std::size_t d = 0; d < descriptors.size(); ++d) {
    const DescriptorInstance& instance = descriptors[d];
    check_uniform_shape(instance.id, query->name(), query_values.values[d]);
    if (database) check_uniform_shape(instance.id, database->name(), database_values.values[d]);
    const DescriptorValue& first = query_values.values[d].front();
    if (database && database_values.values[d].front().values.size() != first.values.size()) {
      throw std::runtime_error(fmt::format(
          "dataset '{}': descriptor {} has {} values on the query session but {} on the database "
          "session",
          dataset.name, instance.id, first.values.size(),
          database_values.values[d].front().values.size()));
    }

    DescriptorRun descriptor_run;
    descriptor_run.id = instance.id;
    descriptor_run.label = instance.display_name();
    const DescriptorShape shape{first.rows, first.cols};
    descriptor_run.rows = shape.rows;
    descriptor_run.cols = shape.cols;
    descriptor_run.payload_bytes = shape.payload_bytes();
    descriptor_run.paper_bytes = shape.paper_bytes();
    descriptor_run.rotation_invariant = instance.descriptor->rotation_invariant();
    descriptor_run.mean_extract_ms = query_values.mean_extract_ms[d];
    descriptor_run.training = trained.training[d];
    if (show_progress) fmt::print(stderr, "  evaluating {}\n", instance.id);
    descriptor_run.evaluation =
        evaluate_descriptor(*instance.descriptor, query_values.values[d], run.query_records,
                            database ? &database_values.values[d] : nullptr,
                            database ? &run.database_records : nullptr, config.protocol);
    warn_if_sweep_accepts_nothing(descriptor_run, config.protocol);
    run.descriptors.push_back(std::move(descriptor_run));
  }
  // Revisits depend on poses and the protocol only, so every descriptor has the same count.
  const Metrics* counts =
      run.descriptors.empty() ? nullptr : &run.descriptors.front().evaluation.metrics;
  if (counts && counts->revisits > 0 && counts->revisits == counts->queries &&
      config.protocol.labels == LabelRule::standard) {
    fmt::print(stderr,
               "warning: in dataset '{}' every query is a revisit: with the standard labels no "
               "query can be a true negative, so ROC AUC is undefined (F1-max and recall are "
               "not)\n",
               dataset.name);
  }
  // No revisit, or no eligible query at all, is reported by check_datasets_before_run before any
  // work (the second stops the run), with the cause: the radius or the exclusion.
  return run;
}

}  // namespace

ExperimentRun run_experiment(const ExperimentConfig& config, bool show_progress) {
  const auto start = std::chrono::steady_clock::now();
  check_datasets_before_run(config);  // fatal data problems stop the run before any extraction
  ExperimentRun run;
  for (const auto& dataset : config.datasets) {
    run.datasets.push_back(run_dataset(config, dataset, show_progress));
  }
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

}  // namespace radarpr
