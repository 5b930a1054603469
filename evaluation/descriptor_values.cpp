#include "evaluation/descriptor_values.hpp"

#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "descriptors/learnt_codebook.hpp"
#include "descriptors/precomputed/external_values.hpp"
#include "descriptors/runtime_defined.hpp"
#include "evaluation/descriptor_extraction.hpp"

namespace radarpr {
namespace {

// The sequence trainable descriptors learn from, opened on first use: a dataset's own training
// sequence is only opened when some descriptor is trainable.
class TrainingSequence {
 public:
  TrainingSequence(const DatasetConfig& dataset, const Protocol& protocol,
                   const ScanSequence& query, const ScanSequence* database)
      : dataset_(dataset), protocol_(protocol), query_(query), database_(database) {}

  const ScanSequence& get() {
    if (protocol_.train_on != TrainingSource::training_sequence) {
      return database_ ? *database_ : query_;
    }
    if (!opened_) {
      if (!dataset_.training) {
        throw std::logic_error(fmt::format("dataset '{}' has no training sequence", dataset_.name));
      }
      opened_ = open_sequence(*dataset_.training);
      if (opened_->size() == 0) {
        throw std::runtime_error(fmt::format("dataset '{}': the training sequence {} has no scans",
                                             dataset_.name, opened_->name()));
      }
    }
    return *opened_;
  }

  // What a trainable descriptor's values depend on besides its id and the scans described.
  std::string cache_key() {
    return fmt::format("train_on={};fingerprint={}", to_string(protocol_.train_on),
                       get().fingerprint());
  }

 private:
  const DatasetConfig& dataset_;
  const Protocol& protocol_;
  const ScanSequence& query_;
  const ScanSequence* database_;
  std::unique_ptr<ScanSequence> opened_;
};

// The scans' times, recorded beside cached values for readers outside radarpr.
std::vector<std::int64_t> timestamps_of(const ScanSequence& sequence) {
  std::vector<std::int64_t> times;
  times.reserve(sequence.size());
  for (const ScanRecord& record : sequence.records()) times.push_back(record.timestamp_ns);
  return times;
}

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

// Fills the missing sessions[d] of `sequence`: descriptors with external values read them
// (`dataset` and `role` locate their files); the others share one extraction pass (one decode
// per scan), each result checked and stored in the cache.
void extract_missing(const ScanSequence& sequence, const std::string& dataset,
                     const std::string& role, const std::vector<bool>& missing,
                     const DatasetValues& dataset_values, std::vector<SessionValues>& sessions,
                     const std::vector<DescriptorCacheKey>& keys, const DescriptorCache& cache,
                     int threads, bool show_progress, const RunPosition& position) {
  std::vector<std::size_t> indices;
  std::vector<DescriptorInstance> instances;
  for (std::size_t d = 0; d < missing.size(); ++d) {
    if (!missing[d]) continue;
    if (const ExternalValues* external =
            external_values_of(*dataset_values.instances[d].descriptor)) {
      try {
        sessions[d] = {external->values_for({dataset, role, sequence.name(), sequence.records()}),
                       0.0, false};
      } catch (const std::exception& error) {
        throw std::runtime_error(fmt::format("dataset '{}' ({}), descriptor {}: {}", dataset, role,
                                             dataset_values.instances[d].id, error.what()));
      }
      continue;
    }
    indices.push_back(d);
    instances.push_back(dataset_values.instances[d]);
  }
  if (indices.empty()) return;
  ExtractedDescriptors extracted =
      extract_descriptors(sequence, instances, threads,
                          "extracting " + sequence.name() + position.suffix(), show_progress);
  for (std::size_t k = 0; k < indices.size(); ++k) {
    const std::size_t d = indices[k];
    check_uniform_shape(instances[k].id, sequence.name(), extracted.values[k]);
    SessionValues& session = sessions[d];
    session.values = std::move(extracted.values[k]);
    session.mean_extract_ms = extracted.mean_extract_ms[k];
    session.from_cache = false;
    if (cache.enabled() && cacheable(instances[k])) {
      cache.store(keys[d], {session.values, session.mean_extract_ms, dataset_values.training[d],
                            timestamps_of(sequence)});
    }
  }
}

}  // namespace

bool cacheable(const DescriptorInstance& instance) {
  // External values are read from their files each time: no entry could go stale when the files
  // change.
  if (instance.descriptor && external_values_of(*instance.descriptor)) return false;
  // A function defined at run time has no identity to key an entry with.
  if (instance.descriptor && is_runtime_defined(*instance.descriptor)) return false;
  // A descriptor that saves its codebook must train in its run to write the file.
  if (instance.descriptor) {
    const LearntCodebook* codebook = learnt_codebook_of(*instance.descriptor);
    if (codebook != nullptr && !codebook->codebook_saved_to().empty()) return false;
  }
  const DescriptorRegistry& registry = DescriptorRegistry::global();
  if (!registry.contains(instance.name)) return false;
  return instance.id == canonical_descriptor_id(registry.info(instance.name), instance.parameters);
}

DatasetValues obtain_dataset_values(const ExperimentConfig& config, const DatasetConfig& dataset,
                                    const ScanSequence& query, const ScanSequence* database,
                                    const DescriptorCache& cache, bool show_progress,
                                    const RunPosition& position, bool map_single_session_l2) {
  const std::vector<DescriptorInstance>& descriptors = config.descriptors;
  const std::size_t count = descriptors.size();
  TrainingSequence training(dataset, config.protocol, query, database);

  std::vector<std::string> training_keys(count);
  for (std::size_t d = 0; d < count; ++d) {
    if (descriptors[d].descriptor->trainable()) {
      training_keys[d] = training.cache_key();
    } else {
      training_keys[d] = loaded_codebook_key(*descriptors[d].descriptor);
    }
  }
  std::vector<std::string> plugin_builds(count);
  for (std::size_t d = 0; d < count; ++d) {
    if (DescriptorRegistry::global().contains(descriptors[d].name)) {
      plugin_builds[d] = DescriptorRegistry::global().info(descriptors[d].name).plugin_build;
    }
  }
  auto keys_of = [&](const ScanSequence& sequence) {
    std::vector<DescriptorCacheKey> keys;
    const std::string fingerprint = sequence.fingerprint();
    for (std::size_t d = 0; d < count; ++d) {
      keys.push_back({descriptors[d].id, fingerprint, training_keys[d], plugin_builds[d]});
    }
    return keys;
  };

  DatasetValues result;
  result.instances = descriptors;
  result.query.resize(count);
  if (database) result.database.resize(count);
  result.training.resize(count);

  std::size_t stale = 0;
  // Reads what the cache holds for `sequence`; returns which descriptors are still missing.
  auto look_up = [&](const ScanSequence& sequence, const std::vector<DescriptorCacheKey>& keys,
                     std::vector<SessionValues>& sessions) {
    std::vector<bool> missing(count, true);
    std::vector<std::string> found;
    for (std::size_t d = 0; d < count; ++d) {
      if (!cache.enabled() || !cacheable(descriptors[d])) continue;
      CacheLookup outcome = CacheLookup::miss;
      if (map_single_session_l2 && database == nullptr &&
          descriptors[d].descriptor->retrieval_method() == RetrievalMethod::exhaustive_l2) {
        std::optional<MappedDescriptorValues> mapped =
            cache.map(keys[d], sequence.size(), &outcome);
        if (outcome == CacheLookup::stale) ++stale;
        if (!mapped) {
          // load() warns about a damaged entry (and finds it damaged again).
          if (outcome == CacheLookup::corrupt)
            static_cast<void>(cache.load(keys[d], sequence.size()));
          continue;
        }
        if (mapped->training() && !result.training[d]) result.training[d] = mapped->training();
        const double mean_extract_ms = mapped->mean_extract_ms();
        sessions[d].values.clear();
        sessions[d].mean_extract_ms = mean_extract_ms;
        sessions[d].from_cache = true;
        sessions[d].mapped = std::make_shared<const MappedDescriptorValues>(std::move(*mapped));
        missing[d] = false;
        found.push_back(descriptors[d].id);
        continue;
      }
      std::optional<CachedDescriptorValues> cached = cache.load(keys[d], sequence.size(), &outcome);
      if (outcome == CacheLookup::stale) ++stale;
      if (!cached) continue;
      sessions[d] = {std::move(cached->values), cached->mean_extract_ms, true};
      if (cached->training && !result.training[d]) result.training[d] = cached->training;
      missing[d] = false;
      found.push_back(descriptors[d].id);
    }
    if (show_progress && !found.empty()) {
      fmt::print(stderr, "  from the descriptor cache for {}: {}\n", sequence.name(),
                 fmt::join(found, ", "));
    }
    return missing;
  };
  const std::vector<DescriptorCacheKey> query_keys = keys_of(query);
  const std::vector<DescriptorCacheKey> database_keys =
      database ? keys_of(*database) : std::vector<DescriptorCacheKey>{};
  const std::vector<bool> query_missing = look_up(query, query_keys, result.query);
  std::vector<bool> database_missing =
      database ? look_up(*database, database_keys, result.database) : std::vector<bool>{};
  if (show_progress && stale > 0) {
    fmt::print(stderr,
               "  {} descriptor cache entries were written by another radarpr build or cache "
               "format: recomputing\n",
               stale);
  }

  // Trainable descriptors learn only when some of their values must be extracted.
  std::vector<DescriptorInstance> to_train;
  std::vector<std::size_t> trained_index;
  for (std::size_t d = 0; d < count; ++d) {
    const bool needed = query_missing[d] || (database && database_missing[d]);
    if (descriptors[d].descriptor->trainable() && needed) {
      to_train.push_back(descriptors[d]);
      trained_index.push_back(d);
    }
  }
  if (!to_train.empty()) {
    std::vector<std::string> positions;
    for (const std::size_t d : trained_index) positions.push_back(position.suffix(d + 1, count));
    TrainedDescriptors trained =
        train_descriptors(to_train, training.get(), show_progress, positions);
    for (std::size_t k = 0; k < trained_index.size(); ++k) {
      result.instances[trained_index[k]] = std::move(trained.instances[k]);
      result.training[trained_index[k]] = std::move(trained.training[k]);
    }
  }

  extract_missing(query, dataset.name, "query", query_missing, result, result.query, query_keys,
                  cache, config.threads, show_progress, position);
  if (database) {
    // The same scans on both sides (a session searched against itself as a multi session): the
    // values are already there.
    for (std::size_t d = 0; d < count; ++d) {
      if (database_missing[d] && database_keys[d].text() == query_keys[d].text()) {
        result.database[d] = result.query[d];
        database_missing[d] = false;
      }
    }
    extract_missing(*database, dataset.name, "database", database_missing, result, result.database,
                    database_keys, cache, config.threads, show_progress, position);
  }

  for (std::size_t d = 0; d < count; ++d) {
    const auto& query_values = result.query[d].values;
    if (query_values.empty()) continue;
    check_uniform_shape(descriptors[d].id, query.name(), query_values);
    if (!database) continue;
    const auto& database_values = result.database[d].values;
    check_uniform_shape(descriptors[d].id, database->name(), database_values);
    if (!database_values.empty() &&
        database_values.front().values.size() != query_values.front().values.size()) {
      throw std::runtime_error(fmt::format(
          "dataset '{}': descriptor {} has {} values on the query session but {} on the database "
          "session",
          dataset.name, descriptors[d].id, query_values.front().values.size(),
          database_values.front().values.size()));
    }
  }
  return result;
}

}  // namespace radarpr
