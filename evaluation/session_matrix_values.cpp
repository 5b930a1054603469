#include "evaluation/session_matrix_values.hpp"

#include <set>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "descriptors/precomputed/external_values.hpp"
#include "evaluation/descriptor_extraction.hpp"
#include "evaluation/descriptor_training.hpp"

namespace radarpr {
namespace {

std::string describe_job(const ExperimentConfig& config, const MatrixValueJob& job,
                         MatrixSequences& sequences) {
  std::string text = fmt::format("{} on {}", config.descriptors[job.descriptor].id,
                                 sequences.session(job.session).name());
  if (job.trained_on) {
    text += fmt::format(" (trained on {})", sequences.source(*job.trained_on).name());
  }
  return text;
}

}  // namespace

MappedDescriptorValues map_matrix_job_values(const ExperimentConfig& config,
                                             const MatrixValueJob& job, MatrixSequences& sequences,
                                             const DescriptorCache& cache) {
  const DescriptorCacheKey key = matrix_job_key(config, job, sequences);
  CacheLookup outcome = CacheLookup::miss;
  std::string problem;
  auto mapped = cache.map(key, sequences.session(job.session).size(), &outcome, &problem);
  if (mapped) return std::move(*mapped);
  if (outcome == CacheLookup::miss) {
    throw std::runtime_error(fmt::format(
        "the values of {} are not in the descriptor cache {}: run the extraction units first",
        describe_job(config, job, sequences), cache.entry_path(key).string()));
  }
  // The values unit that wrote the entry counts as done while its files exist: once one is
  // deleted, that unit is missing again and a rerun of the phase rewrites it.
  throw std::runtime_error(fmt::format(
      "the values of {} cannot be used: {}; delete {} and {} and run the values unit of the "
      "session again",
      describe_job(config, job, sequences), problem, cache.entry_path(key).string(),
      cache.values_path(key).string()));
}

const ScanSequence& MatrixSequences::session(std::size_t index) {
  auto& slot = opened_[index];
  if (!slot) {
    if (index == kMatrixTrainingSequence) {
      if (!matrix_.training) {
        throw std::logic_error(
            fmt::format("session matrix '{}' has no training sequence", matrix_.name));
      }
      slot = open_sequence(*matrix_.training);
    } else {
      slot = open_sequence(matrix_.sessions.at(index).sequence);
    }
    if (slot->size() == 0) {
      throw std::runtime_error(fmt::format("session matrix '{}': {} has no scans with a pose",
                                           matrix_.name, slot->name()));
    }
  }
  return *slot;
}

const ScanSequence& MatrixSequences::training() {
  return session(kMatrixTrainingSequence);
}

std::vector<MatrixValueJob> matrix_pair_jobs(const ExperimentConfig& config,
                                             const SessionMatrixConfig& matrix, std::size_t pair,
                                             std::size_t descriptor) {
  const auto [query, database] = matrix.pairs.at(pair);
  std::optional<std::size_t> trained_on;
  if (config.descriptors.at(descriptor).descriptor->trainable()) {
    trained_on = config.protocol.train_on == TrainingSource::training_sequence
                     ? kMatrixTrainingSequence
                     : database;
  }
  return {{descriptor, query, trained_on}, {descriptor, database, trained_on}};
}

DescriptorCacheKey matrix_job_key(const ExperimentConfig& config, const MatrixValueJob& job,
                                  MatrixSequences& sequences) {
  const DescriptorInstance& instance = config.descriptors.at(job.descriptor);
  DescriptorCacheKey key;
  key.descriptor_id = instance.id;
  key.sequence_fingerprint = sequences.session(job.session).fingerprint();
  if (job.trained_on) {
    // As an ordinary dataset of the pair names it (descriptor_values.cpp), so both share entries.
    key.training = fmt::format("train_on={};fingerprint={}", to_string(config.protocol.train_on),
                               sequences.source(*job.trained_on).fingerprint());
  } else {
    key.training = loaded_codebook_key(*instance.descriptor);
  }
  const DescriptorRegistry& registry = DescriptorRegistry::global();
  if (registry.contains(instance.name))
    key.plugin_build = registry.info(instance.name).plugin_build;
  return key;
}

std::map<MatrixValueJob, MatrixJobValues> obtain_matrix_values(
    const ExperimentConfig& config, const std::vector<MatrixValueJob>& jobs,
    MatrixSequences& sequences, const DescriptorCache& cache, bool show_progress, bool keep_values,
    const TrainedLookup& trained_elsewhere) {
  std::map<MatrixValueJob, MatrixJobValues> found;
  std::map<MatrixValueJob, DescriptorCacheKey> keys;
  std::set<MatrixValueJob> to_compute;
  for (const MatrixValueJob& job : jobs) {
    if (keys.count(job)) continue;
    const DescriptorCacheKey key = matrix_job_key(config, job, sequences);
    keys.emplace(job, key);
    const DescriptorInstance& instance = config.descriptors[job.descriptor];
    if (cache.enabled() && cacheable(instance)) {
      const std::size_t scans = sequences.session(job.session).size();
      if (!keep_values) {
        // Checked in place through a map, a block at a time: not read into memory to be dropped.
        if (auto mapped = cache.map(key, scans)) {
          found[job] = {{{}, mapped->mean_extract_ms(), true}, mapped->training()};
          continue;
        }
      }
      auto cached = cache.load(key, scans);
      if (cached) {
        if (!keep_values) cached->values.clear();
        found[job] = {{std::move(cached->values), cached->mean_extract_ms, true},
                      std::move(cached->training)};
        continue;
      }
    }
    to_compute.insert(job);
  }
  // Values read from files (`precomputed`): asked for each session, never extracted. In its paths
  // {dataset} is the matrix's name and {role} the session's.
  for (auto job = to_compute.begin(); job != to_compute.end();) {
    const ExternalValues* external =
        external_values_of(*config.descriptors[job->descriptor].descriptor);
    if (external == nullptr) {
      ++job;
      continue;
    }
    const ScanSequence& sequence = sequences.session(job->session);
    const std::string& session = sequences.matrix().sessions.at(job->session).name;
    try {
      std::vector<DescriptorValue> values = external->values_for(
          {sequences.matrix().name, session, sequence.name(), sequence.records()});
      found[*job] = {{keep_values ? std::move(values) : std::vector<DescriptorValue>{}, 0.0, false},
                     std::nullopt};
    } catch (const std::exception& error) {
      throw std::runtime_error(fmt::format("session matrix '{}' (session {}), descriptor {}: {}",
                                           sequences.matrix().name, session,
                                           config.descriptors[job->descriptor].id, error.what()));
    }
    job = to_compute.erase(job);
  }
  if (to_compute.empty()) return found;

  // Train each trainable descriptor once per training source that some missing job needs.
  std::map<std::pair<std::size_t, std::size_t>, DescriptorInstance> trained;  // (descriptor, on)
  std::map<std::pair<std::size_t, std::size_t>, TrainingRecord> records;
  for (const MatrixValueJob& job : to_compute) {
    if (!job.trained_on) continue;
    const auto source = std::make_pair(job.descriptor, *job.trained_on);
    if (trained.count(source)) continue;
    if (trained_elsewhere) {
      TrainedInstance loaded = trained_elsewhere(job.descriptor, *job.trained_on);
      trained.emplace(source, std::move(loaded.instance));
      records.emplace(source, std::move(loaded.record));
      continue;
    }
    TrainedDescriptors result = train_descriptors({config.descriptors[job.descriptor]},
                                                  sequences.source(*job.trained_on), show_progress);
    trained.emplace(source, std::move(result.instances.front()));
    records.emplace(source, *result.training.front());
  }

  // One decode of each session for all of its missing jobs.
  std::map<std::size_t, std::vector<MatrixValueJob>> by_session;
  for (const MatrixValueJob& job : to_compute) by_session[job.session].push_back(job);
  for (const auto& [session, session_jobs] : by_session) {
    const ScanSequence& sequence = sequences.session(session);
    std::vector<DescriptorInstance> instances;
    for (const MatrixValueJob& job : session_jobs) {
      instances.push_back(job.trained_on ? trained.at({job.descriptor, *job.trained_on})
                                         : config.descriptors[job.descriptor]);
    }
    ExtractedDescriptors extracted = extract_descriptors(
        sequence, instances, config.threads, "extracting " + sequence.name(), show_progress);
    for (std::size_t k = 0; k < session_jobs.size(); ++k) {
      const MatrixValueJob& job = session_jobs[k];
      auto& values = extracted.values[k];
      for (std::size_t i = 1; i < values.size(); ++i) {
        if (values[i].rows != values[0].rows || values[i].cols != values[0].cols ||
            values[i].values.size() != values[0].values.size()) {
          throw std::runtime_error(fmt::format(
              "{}: descriptor {} gave shape {}x{} on scan 0 but {}x{} on scan {}", sequence.name(),
              instances[k].id, values[0].rows, values[0].cols, values[i].rows, values[i].cols, i));
        }
      }
      MatrixJobValues entry;
      entry.values = {std::move(values), extracted.mean_extract_ms[k], false};
      if (job.trained_on) entry.training = records.at({job.descriptor, *job.trained_on});
      if (cache.enabled() && cacheable(config.descriptors[job.descriptor])) {
        std::vector<std::int64_t> times;
        times.reserve(sequence.size());
        for (const ScanRecord& record : sequence.records()) times.push_back(record.timestamp_ns);
        cache.store(keys.at(job), {entry.values.values, entry.values.mean_extract_ms,
                                   entry.training, std::move(times)});
      }
      if (!keep_values) entry.values.values = {};
      found[job] = std::move(entry);
    }
  }
  return found;
}

}  // namespace radarpr
