#include "evaluation/study/unit_runner.hpp"

#include <chrono>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <stdexcept>

#include <fmt/format.h>

#include "datasets/cache_directory.hpp"
#include "evaluation/descriptor_cache.hpp"
#include "evaluation/descriptor_training.hpp"
#include "evaluation/results/results_writer.hpp"
#include "evaluation/study/descriptor_run_json.hpp"
#include "evaluation/version.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

nlohmann::json read_json(const fs::path& path) {
  std::ifstream file(path);
  if (!file) throw std::runtime_error(fmt::format("{}: cannot open the file", path.string()));
  try {
    return nlohmann::json::parse(file);
  } catch (const nlohmann::json::exception& error) {
    throw std::runtime_error(fmt::format("{}: not valid JSON ({})", path.string(), error.what()));
  }
}

// The output file of `unit` when it exists, parses and carries `fingerprint`; nullopt otherwise.
std::optional<nlohmann::json> matching_output(const fs::path& path,
                                              const std::string& fingerprint) {
  std::error_code error;
  if (!fs::exists(path, error)) return std::nullopt;
  std::ifstream file(path);
  auto json = nlohmann::json::parse(file, nullptr, /*allow_exceptions=*/false);
  if (!json.is_object() || json.value("fingerprint", std::string()) != fingerprint) {
    return std::nullopt;
  }
  return json;
}

bool stamped_unit_done(const ExperimentConfig& config, const PlanFolder& folder,
                       const StudyUnit& unit) {
  const auto stamp = matching_output(folder.stamp(unit.id), unit_fingerprint(config, unit));
  if (!stamp || !stamp->contains("entries")) return false;
  for (const auto& entry : stamp->at("entries")) {
    std::error_code error;
    if (!entry.is_string() || !fs::exists(folder.root / entry.get<std::string>(), error)) {
      return false;
    }
  }
  return true;
}

// What the values one pass over a session computes may take in memory: a values unit of a study
// with many codebooks of large values (Open-RadVLAD: 128 KiB per scan and codebook) splits its
// jobs into passes of at most this much, decoding the session once per pass.
constexpr std::size_t kValuesPassBytes = std::size_t{4} << 30;

// `jobs` in passes whose values fit kValuesPassBytes (a job larger than that is a pass of its
// own), in order. The size of a value is the descriptor's shape at the default scan geometry, an
// estimate where the shape depends on the range bins.
std::vector<std::vector<MatrixValueJob>> passes_within_budget(
    const ExperimentConfig& config, const std::vector<MatrixValueJob>& jobs,
    MatrixSequences& sequences) {
  std::vector<std::vector<MatrixValueJob>> passes;
  std::size_t bytes = 0;
  for (const auto& job : jobs) {
    const std::size_t job_bytes =
        sequences.session(job.session).size() *
        config.descriptors.at(job.descriptor).descriptor->shape(ScanGeometry{}).payload_bytes();
    if (passes.empty() || (bytes + job_bytes > kValuesPassBytes && !passes.back().empty())) {
      passes.emplace_back();
      bytes = 0;
    }
    passes.back().push_back(job);
    bytes += job_bytes;
  }
  return passes;
}

// A descriptor as the train unit `id` trained it: a fresh instance loaded with what that unit
// saved, and the record of its training.
TrainedInstance load_trained(const ExperimentConfig& config, const PlanFolder& folder,
                             const std::string& id, std::size_t descriptor) {
  const fs::path stamp = folder.stamp(id);
  const fs::path state = folder.trained(id);
  std::error_code error;
  if (!fs::exists(stamp, error) || !fs::exists(state, error)) {
    throw std::runtime_error(
        fmt::format("{} is not done ({} or {} is missing): run the train "
                    "units first",
                    id, stamp.string(), state.string()));
  }
  const nlohmann::json done = read_json(stamp);
  TrainedInstance trained{config.descriptors.at(descriptor), {}};
  try {
    const nlohmann::json& record = done.at("training");
    trained.record = {record.at("sequence").get<std::string>(),
                      record.at("scans").get<std::size_t>(),
                      record.at("loaded").get<std::size_t>(),
                      record.at("seconds").get<double>(),
                      /*from_cache=*/false,
                      record.value("codebook_sha256", std::string())};
  } catch (const nlohmann::json::exception& bad) {
    throw std::runtime_error(
        fmt::format("{}: no training record ({})", stamp.string(), bad.what()));
  }
  std::ifstream file(state, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  if (!file.good() && !file.eof()) {
    throw std::runtime_error(fmt::format("{}: cannot read the file", state.string()));
  }
  std::unique_ptr<Descriptor> fresh = trained.instance.create_fresh();
  try {
    fresh->load_training(bytes);
  } catch (const std::exception& bad) {
    throw std::runtime_error(fmt::format("{}: {}", state.string(), bad.what()));
  }
  trained.instance.descriptor = std::move(fresh);
  return trained;
}

// A train unit of a descriptor that saves what it learnt: trains once, writes the state.
nlohmann::json run_train_unit(const ExperimentConfig& config, const PlanFolder& folder,
                              const StudyUnit& unit, bool show_progress) {
  MatrixSequences sequences(config.matrices.at(*unit.matrix));
  const TrainedDescriptors trained =
      train_descriptors({config.descriptors.at(*unit.descriptor)},
                        sequences.source(*unit.training_source), show_progress);
  const TrainingRecord& record = *trained.training.front();
  write_file_atomically(folder.trained(unit.id),
                        trained.instances.front().descriptor->save_training());
  return {{"entries", {fs::relative(folder.trained(unit.id), folder.root).string()}},
          {"training",
           {{"sequence", record.sequence},
            {"scans", record.scans},
            {"loaded", record.loaded},
            {"seconds", record.seconds},
            {"codebook_sha256", record.codebook_sha256}}}};
}

nlohmann::json run_values_unit(const ExperimentConfig& config, const PlanFolder& folder,
                               const StudyUnit& unit, bool show_progress) {
  const SessionMatrixConfig& matrix = config.matrices.at(*unit.matrix);
  MatrixSequences sequences(matrix);
  const DescriptorCache cache(folder.cache());
  // A values unit takes its codebooks from the train units; a train unit that encodes sessions
  // itself (its descriptor cannot save what it learnt) trains here.
  TrainedLookup trained;
  if (unit.phase == UnitPhase::values) {
    trained = [&](std::size_t descriptor, std::size_t source) {
      return load_trained(config, folder, train_unit_id(config, *unit.matrix, source, descriptor),
                          descriptor);
    };
  }
  // Values go to the cache only; a pass over the scans holds the values of its jobs until they
  // are stored, so jobs beyond the memory budget take another pass.
  for (const auto& pass : passes_within_budget(config, unit.jobs, sequences)) {
    obtain_matrix_values(config, pass, sequences, cache, show_progress,
                         /*keep_values=*/false, trained);
  }
  nlohmann::json entries = nlohmann::json::array();
  for (const auto& job : unit.jobs) {
    // The entry's sidecar and values: the unit is missing again once either is deleted.
    const DescriptorCacheKey key = matrix_job_key(config, job, sequences);
    for (const fs::path& entry : {cache.entry_path(key), cache.values_path(key)}) {
      std::error_code error;
      if (!fs::exists(entry, error)) {
        throw std::runtime_error(
            fmt::format("the descriptor cache entry {} was not written", entry.string()));
      }
      entries.push_back(fs::relative(entry, folder.root).string());
    }
  }
  return {{"entries", entries}};
}

nlohmann::json run_evaluate_unit(const ExperimentConfig& config, const StudyUnit& unit,
                                 const PlanFolder& folder, bool show_progress) {
  nlohmann::json descriptors = nlohmann::json::array();
  std::string dataset_name;
  if (unit.matrix) {
    const SessionMatrixConfig& matrix = config.matrices.at(*unit.matrix);
    MatrixSequences sequences(matrix);
    // Memory-mapped and read a block at a time: a unit holds two blocks of values, not the two
    // sessions' (Open-RadVLAD: 1 GiB per Oxford session).
    const DescriptorCache cache(folder.cache());
    const MappedDescriptorValues query =
        map_matrix_job_values(config, unit.jobs[0], sequences, cache);
    const MappedDescriptorValues database =
        map_matrix_job_values(config, unit.jobs[1], sequences, cache);
    const DatasetRun pair = describe_matrix_pair(config, matrix, *unit.pair, sequences);
    dataset_name = pair.name;
    const DescriptorRun run = evaluate_mapped_pair_descriptor(
        config, pair, config.descriptors.at(*unit.descriptor), query, database,
        database.training() ? database.training() : query.training(), show_progress);
    descriptors.push_back(descriptor_run_to_json(run));
  } else {
    ExperimentConfig single = config;
    single.datasets = {config.datasets.at(*unit.dataset)};
    single.matrices.clear();
    const ExperimentRun run = run_experiment(single, show_progress);
    dataset_name = run.datasets.front().name;
    for (const auto& descriptor : run.datasets.front().descriptors) {
      descriptors.push_back(descriptor_run_to_json(descriptor));
    }
  }
  return {{"dataset", dataset_name}, {"descriptors", descriptors}};
}

}  // namespace

std::vector<StudyUnit> write_plan(const ExperimentConfig& config, const fs::path& config_folder,
                                  const PlanFolder& folder) {
  std::error_code error;
  if (fs::exists(folder.root, error)) {
    if (!fs::is_directory(folder.root, error)) {
      throw std::runtime_error(fmt::format("{}: exists and is not a folder", folder.root.string()));
    }
    const bool empty = fs::is_empty(folder.root, error);
    if (!empty) {
      std::ifstream file(folder.manifest());
      const auto manifest = nlohmann::json::parse(file, nullptr, /*allow_exceptions=*/false);
      if (!manifest.is_object() || manifest.value("experiment", std::string()) != config.name) {
        throw std::runtime_error(
            fmt::format("{}: exists and holds no plan of experiment '{}'; choose another --out",
                        folder.root.string(), config.name));
      }
    }
  }
  const std::vector<StudyUnit> units = plan_units(config);
  fs::create_directories(folder.units());
  fs::create_directories(folder.cache());
  write_file_atomically(folder.config(), config.resolved.dump(2) + "\n");
  write_file_atomically(folder.manifest(),
                        plan_manifest(config, folder, units, config_folder).dump(2) + "\n");
  return units;
}

ExperimentConfig load_plan_config(const PlanFolder& folder) {
  const nlohmann::json manifest = read_json(folder.manifest());
  if (!manifest.is_object() || !manifest.contains("config_folder") ||
      !manifest["config_folder"].is_string()) {
    throw std::runtime_error(
        fmt::format("{}: not a radarpr plan (config_folder expected)", folder.manifest().string()));
  }
  const nlohmann::json config = read_json(folder.config());
  ExperimentConfig experiment;
  try {
    experiment = parse_experiment_config(config, manifest["config_folder"].get<std::string>());
  } catch (const ConfigError& error) {
    throw error.in_file(folder.config().string());
  }
  override_cache_directory(folder.cache());
  return experiment;
}

std::string unit_fingerprint(const ExperimentConfig& config, const StudyUnit& unit) {
  const std::string text =
      fmt::format("{}\n{}\n{}\n{}", radarpr_version(), descriptor_cache_build_identity(),
                  config.resolved.dump(), unit.id);
  return fmt::format("{:016x}", cache_checksum(text.data(), text.size()));
}

std::string_view to_string(UnitState state) {
  switch (state) {
    case UnitState::done:
      return "done";
    case UnitState::missing:
      return "missing";
    case UnitState::failed:
      return "failed";
  }
  return "?";
}

UnitState unit_state(const ExperimentConfig& config, const PlanFolder& folder,
                     const StudyUnit& unit) {
  const bool done =
      unit.phase != UnitPhase::evaluate
          ? stamped_unit_done(config, folder, unit)
          : matching_output(folder.result(unit.id), unit_fingerprint(config, unit)).has_value();
  if (done) return UnitState::done;
  std::error_code error;
  return fs::exists(folder.failure(unit.id), error) ? UnitState::failed : UnitState::missing;
}

UnitOutcome run_unit(const ExperimentConfig& config, const PlanFolder& folder,
                     const StudyUnit& unit, bool show_progress) {
  UnitOutcome outcome;
  if (unit_state(config, folder, unit) == UnitState::done) {
    outcome.skipped = true;
    return outcome;
  }
  const auto start = std::chrono::steady_clock::now();
  try {
    nlohmann::json output = unit.phase == UnitPhase::evaluate
                                ? run_evaluate_unit(config, unit, folder, show_progress)
                            : unit.phase == UnitPhase::train && unit.jobs.empty()
                                ? run_train_unit(config, folder, unit, show_progress)
                                : run_values_unit(config, folder, unit, show_progress);
    outcome.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    output["fingerprint"] = unit_fingerprint(config, unit);
    output["unit"] = unit.id;
    output["seconds"] = outcome.seconds;
    fs::create_directories(folder.units());
    write_file_atomically(
        unit.phase == UnitPhase::evaluate ? folder.result(unit.id) : folder.stamp(unit.id),
        output.dump() + "\n");
    std::error_code ignored;
    fs::remove(folder.failure(unit.id), ignored);
  } catch (const std::exception& error) {
    try {
      fs::create_directories(folder.units());
      write_file_atomically(folder.failure(unit.id), std::string(error.what()) + "\n");
    } catch (const std::exception&) {
      // The cause still reaches the caller, which prints it.
    }
    throw std::runtime_error(fmt::format("unit {} failed: {}", unit.id, error.what()));
  }
  return outcome;
}

ExperimentRun merge_units(const ExperimentConfig& config, const PlanFolder& folder,
                          const std::vector<StudyUnit>& units) {
  std::vector<std::string> not_done;
  for (const auto& unit : units) {
    if (unit_state(config, folder, unit) != UnitState::done) not_done.push_back(unit.id);
  }
  if (!not_done.empty()) {
    throw std::runtime_error(
        fmt::format("{}: {} of {} units are not done ({}{}); run them first (radarpr status {})",
                    folder.root.string(), not_done.size(), units.size(),
                    fmt::join(not_done.begin(),
                              not_done.begin() + std::min<std::size_t>(not_done.size(), 5), ", "),
                    not_done.size() > 5 ? ", ..." : "", folder.root.string()));
  }
  std::map<std::string, const StudyUnit*> by_id;
  for (const auto& unit : units) by_id[unit.id] = &unit;
  ExperimentRun run;
  auto read_unit = [&](const std::string& id) {
    const nlohmann::json output = read_json(folder.result(id));
    run.seconds += output.value("seconds", 0.0);
    std::vector<DescriptorRun> descriptors;
    try {
      for (const auto& descriptor : output.at("descriptors")) {
        descriptors.push_back(descriptor_run_from_json(descriptor));
      }
    } catch (const std::exception& error) {
      throw std::runtime_error(fmt::format("{}: {}", folder.result(id).string(), error.what()));
    }
    return descriptors;
  };
  for (const auto& unit : units) {
    if (unit.phase != UnitPhase::evaluate) {
      run.seconds += read_json(folder.stamp(unit.id)).value("seconds", 0.0);
    }
  }
  std::map<std::size_t, std::unique_ptr<MatrixSequences>> sequences;
  for (std::size_t i = 0; i < config.datasets.size(); ++i) {
    const DatasetConfig& dataset = config.datasets[i];
    if (dataset.matrix_pair) {
      const std::size_t m = dataset.matrix_pair->matrix;
      auto& matrix_sequences = sequences[m];
      if (!matrix_sequences) {
        matrix_sequences = std::make_unique<MatrixSequences>(config.matrices[m]);
      }
      const SessionMatrixConfig& matrix = config.matrices[m];
      DatasetRun pair =
          describe_matrix_pair(config, matrix, i - matrix.first_dataset, *matrix_sequences);
      for (const auto& instance : config.descriptors) {
        for (auto& descriptor : read_unit(fmt::format("evaluate.{}.{}", dataset.name,
                                                      descriptor_folder_name(instance.id)))) {
          pair.descriptors.push_back(std::move(descriptor));
        }
      }
      run.datasets.push_back(std::move(pair));
    } else {
      const auto query = open_sequence(dataset.query);
      const auto database = dataset.database ? open_sequence(*dataset.database) : nullptr;
      DatasetRun plain = describe_dataset(dataset.name, *query, database.get());
      plain.descriptors = read_unit("dataset." + dataset.name);
      run.datasets.push_back(std::move(plain));
    }
  }
  return run;
}

}  // namespace radarpr
