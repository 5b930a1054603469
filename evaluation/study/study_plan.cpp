#include "evaluation/study/study_plan.hpp"

#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include <stdexcept>

#include <unistd.h>

#include <fmt/format.h>

#include "descriptors/precomputed/external_values.hpp"
#include "descriptors/runtime_defined.hpp"
#include "evaluation/results/results_writer.hpp"
#include "evaluation/version.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

// Cost model of the estimate, stated in the manifest. Per scan and descriptor, decoding and
// extraction; per scan a codebook learns from; per descriptor distance a search computes. Rough
// defaults of the order measured on the synthetic scans (radarpr bench); the real figure depends
// on the descriptor and the scan size, so the manifest lists the work itself too.
constexpr double kExtractSecondsPerScan = 0.02;
constexpr double kTrainSecondsPerScan = 0.05;
// Per query-database pair a search compares: a KD-tree search (ReFeree's 50 floats) about 2e-8 s;
// an exhaustive search in proportion to the values' floats, 2.0 us for Open-RadVLAD's 32,768
// (benchmarks/cluster/cost_rates.sh, CPU on one thread).
constexpr double kSecondsPerComparison = 2e-8;
constexpr double kSecondsPerComparedFloat = 6.1e-11;

double seconds_per_comparison(const DescriptorInstance& instance) {
  const Descriptor& descriptor = *instance.descriptor;
  switch (descriptor.retrieval_method()) {
    case RetrievalMethod::kdtree:
    case RetrievalMethod::key_then_rerank:
      return kSecondsPerComparison;
    case RetrievalMethod::exhaustive:
    case RetrievalMethod::exhaustive_l2:
      break;
  }
  const double floats = static_cast<double>(descriptor.shape(ScanGeometry{}).element_count());
  return std::max(kSecondsPerComparison, floats * kSecondsPerComparedFloat);
}

std::string descriptor_part(const ExperimentConfig& config, std::size_t descriptor) {
  return descriptor_folder_name(config.descriptors[descriptor].id);
}

}  // namespace

std::string_view to_string(UnitPhase phase) {
  switch (phase) {
    case UnitPhase::train:
      return "train";
    case UnitPhase::values:
      return "values";
    case UnitPhase::evaluate:
      return "evaluate";
  }
  return "?";
}

std::string train_unit_id(const ExperimentConfig& config, std::size_t matrix,
                          std::size_t training_source, std::size_t descriptor) {
  const SessionMatrixConfig& sessions = config.matrices.at(matrix);
  return fmt::format("train.{}.{}.{}", sessions.name,
                     training_source == kMatrixTrainingSequence
                         ? std::string("training")
                         : sessions.sessions.at(training_source).name,
                     descriptor_part(config, descriptor));
}

std::vector<StudyUnit> plan_units(const ExperimentConfig& config, UnitCosts costs) {
  // A study's units hand values on through the descriptor cache, which never holds values read
  // from files or computed by a function defined at run time.
  for (const DescriptorInstance& instance : config.descriptors) {
    if (external_values_of(*instance.descriptor) || is_runtime_defined(*instance.descriptor)) {
      throw std::runtime_error(fmt::format(
          "descriptor {} cannot be split into a study's units: its values are not kept in the "
          "descriptor cache that units share; run the config in one process (radarpr run)",
          instance.id));
    }
  }
  const bool estimate = costs == UnitCosts::estimate;
  std::vector<StudyUnit> train_units;
  std::vector<StudyUnit> values_units;
  std::vector<StudyUnit> evaluate_units;
  for (std::size_t m = 0; m < config.matrices.size(); ++m) {
    const SessionMatrixConfig& matrix = config.matrices[m];
    MatrixSequences sequences(matrix);
    std::vector<std::size_t> scans(matrix.sessions.size());
    for (std::size_t s = 0; estimate && s < scans.size(); ++s) {
      scans[s] = sequences.session(s).size();
    }
    // Per session, every value it needs: one values unit decodes its scans once for all of them.
    std::vector<std::vector<MatrixValueJob>> session_jobs(matrix.sessions.size());
    for (std::size_t d = 0; d < config.descriptors.size(); ++d) {
      // Which sessions the descriptor needs, under which codebook: the union of the pairs' jobs.
      std::map<std::optional<std::size_t>, std::set<std::size_t>> by_source;
      for (std::size_t p = 0; p < matrix.pairs.size(); ++p) {
        for (const auto& job : matrix_pair_jobs(config, matrix, p, d)) {
          by_source[job.trained_on].insert(job.session);
        }
      }
      const bool hands_on_training = config.descriptors[d].descriptor->saves_training();
      for (const auto& [source, sessions] : by_source) {
        if (source) {
          // Trainable: one unit per training source. What it learnt goes to the values units;
          // a descriptor that cannot save it encodes every session here instead.
          StudyUnit unit;
          unit.id = train_unit_id(config, m, *source, d);
          unit.phase = UnitPhase::train;
          unit.matrix = m;
          unit.descriptor = d;
          unit.training_source = source;
          if (estimate) {
            unit.scans_trained =
                *source == kMatrixTrainingSequence ? sequences.training().size() : scans[*source];
          }
          if (!hands_on_training) {
            for (std::size_t s : sessions) {
              unit.jobs.push_back({d, s, source});
              unit.scans_described += scans[s];
            }
          }
          train_units.push_back(std::move(unit));
          if (!hands_on_training) continue;
        }
        for (std::size_t s : sessions) session_jobs[s].push_back({d, s, source});
      }
    }
    for (std::size_t s = 0; s < session_jobs.size(); ++s) {
      if (session_jobs[s].empty()) continue;
      StudyUnit unit;
      unit.id = fmt::format("values.{}.{}", matrix.name, matrix.sessions[s].name);
      unit.matrix = m;
      unit.scans_described = scans[s] * session_jobs[s].size();
      unit.jobs = std::move(session_jobs[s]);
      values_units.push_back(std::move(unit));
    }
    for (std::size_t p = 0; p < matrix.pairs.size(); ++p) {
      for (std::size_t d = 0; d < config.descriptors.size(); ++d) {
        StudyUnit unit;
        unit.id = fmt::format("evaluate.{}.{}", config.datasets[matrix.first_dataset + p].name,
                              descriptor_part(config, d));
        unit.phase = UnitPhase::evaluate;
        unit.matrix = m;
        unit.pair = p;
        unit.descriptor = d;
        unit.jobs = matrix_pair_jobs(config, matrix, p, d);
        unit.comparisons = scans[matrix.pairs[p].first] * scans[matrix.pairs[p].second];
        unit.estimated_cpu_seconds =
            static_cast<double>(unit.comparisons) * seconds_per_comparison(config.descriptors[d]);
        evaluate_units.push_back(std::move(unit));
      }
    }
  }
  for (std::size_t i = 0; i < config.datasets.size(); ++i) {
    const DatasetConfig& dataset = config.datasets[i];
    if (dataset.matrix_pair) continue;
    // An ordinary dataset is one unit: it extracts, trains and evaluates like `radarpr run`.
    StudyUnit unit;
    unit.id = "dataset." + dataset.name;
    unit.phase = UnitPhase::evaluate;
    unit.dataset = i;
    if (!estimate) {
      evaluate_units.push_back(std::move(unit));
      continue;
    }
    const std::size_t query = open_sequence(dataset.query)->size();
    const std::size_t database = dataset.database ? open_sequence(*dataset.database)->size() : 0;
    const std::size_t descriptors = config.descriptors.size();
    unit.scans_described = (query + database) * descriptors;
    const std::size_t pairs = dataset.database ? query * database : query * query / 2;
    unit.comparisons = pairs * descriptors;
    for (const auto& instance : config.descriptors) {
      unit.estimated_cpu_seconds += static_cast<double>(pairs) * seconds_per_comparison(instance);
    }
    evaluate_units.push_back(std::move(unit));
  }
  std::vector<StudyUnit> units = std::move(train_units);
  for (auto& unit : values_units) units.push_back(std::move(unit));
  for (auto& unit : evaluate_units) units.push_back(std::move(unit));
  for (auto& unit : units) {
    // The search's share was set with the unit (it depends on the descriptor).
    unit.estimated_cpu_seconds +=
        static_cast<double>(unit.scans_described) * kExtractSecondsPerScan +
        static_cast<double>(unit.scans_trained) * kTrainSecondsPerScan;
  }
  std::set<std::string> ids;
  for (const auto& unit : units) {
    if (!ids.insert(unit.id).second) {
      throw std::runtime_error(fmt::format("two units of the plan are named {}", unit.id));
    }
  }
  return units;
}

nlohmann::json plan_manifest(const ExperimentConfig& config, const PlanFolder& folder,
                             const std::vector<StudyUnit>& units, const fs::path& config_folder) {
  nlohmann::json phases = nlohmann::json::array();
  double total = 0.0;
  for (UnitPhase phase : kUnitPhases) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& unit : units) {
      if (unit.phase != phase) continue;
      nlohmann::json inputs = nlohmann::json::array();
      nlohmann::json outputs = nlohmann::json::array();
      if (unit.phase != UnitPhase::evaluate) {
        const SessionMatrixConfig& matrix = config.matrices[*unit.matrix];
        const auto session_name = [&](std::size_t session) {
          return session == kMatrixTrainingSequence
                     ? fmt::format("the training sequence of matrix {}", matrix.name)
                     : fmt::format("session {} of matrix {}", matrix.sessions[session].name,
                                   matrix.name);
        };
        if (unit.training_source) {
          inputs.push_back(session_name(*unit.training_source) + " (training)");
          if (unit.jobs.empty()) {
            outputs.push_back(fs::relative(folder.trained(unit.id), folder.root).string());
          }
        }
        std::set<std::string> named;
        for (const auto& job : unit.jobs) {
          if (named.insert(session_name(job.session)).second) {
            inputs.push_back(session_name(job.session));
          }
          if (job.trained_on && unit.phase == UnitPhase::values) {
            const std::string trainer =
                train_unit_id(config, *unit.matrix, *job.trained_on, job.descriptor);
            if (named.insert(trainer).second) inputs.push_back(trainer);
          }
          std::string what =
              fmt::format("cache/: {} on session {}", config.descriptors[job.descriptor].id,
                          matrix.sessions[job.session].name);
          if (job.trained_on) {
            what += fmt::format(" (trained on {})", *job.trained_on == kMatrixTrainingSequence
                                                        ? std::string("the training sequence")
                                                        : matrix.sessions[*job.trained_on].name);
          }
          outputs.push_back(what);
        }
        outputs.push_back(fs::relative(folder.stamp(unit.id), folder.root).string());
      } else {
        if (unit.matrix) {
          // The units that compute the values this one reads.
          for (const auto& other : units) {
            if (other.phase == UnitPhase::evaluate || other.matrix != unit.matrix) continue;
            for (const auto& job : other.jobs) {
              if (std::find(unit.jobs.begin(), unit.jobs.end(), job) != unit.jobs.end()) {
                inputs.push_back(other.id);
                break;
              }
            }
          }
        } else {
          inputs.push_back(fmt::format("dataset {}", config.datasets[*unit.dataset].name));
        }
        outputs.push_back(fs::relative(folder.result(unit.id), folder.root).string());
      }
      total += unit.estimated_cpu_seconds;
      nlohmann::json entry{{"id", unit.id},
                           {"inputs", inputs},
                           {"outputs", outputs},
                           {"scans_described", unit.scans_described},
                           {"scans_trained", unit.scans_trained},
                           {"comparisons", unit.comparisons},
                           {"estimated_cpu_seconds", unit.estimated_cpu_seconds}};
      list.push_back(entry);
    }
    phases.push_back({{"phase", to_string(phase)}, {"units", list}});
  }
  return {{"radarpr_version", radarpr_version()},
          {"experiment", config.name},
          {"config", "config.json"},
          {"config_folder", fs::absolute(config_folder).lexically_normal().string()},
          {"cache", "cache"},
          {"estimate",
           fmt::format("{} s per scan described, {} s per training scan, per query-database "
                       "pair searched {} s (KD-tree) or {} s per float of the values, at least "
                       "{} s (exhaustive): rough defaults, not measurements of this study",
                       kExtractSecondsPerScan, kTrainSecondsPerScan, kSecondsPerComparison,
                       kSecondsPerComparedFloat, kSecondsPerComparison)},
          {"units", units.size()},
          {"estimated_cpu_seconds", total},
          {"phases", phases}};
}

void write_file_atomically(const fs::path& path, const std::string& bytes) {
  static std::size_t counter = 0;
  const fs::path temporary =
      path.parent_path() /
      fmt::format(".{}.tmp.{}.{}", path.filename().string(), ::getpid(), counter++);
  {
    std::ofstream file(temporary, std::ios::binary);
    file << bytes;
    file.close();
    if (!file) {
      std::error_code ignored;
      fs::remove(temporary, ignored);
      throw std::runtime_error(fmt::format("{}: cannot write the file", path.string()));
    }
  }
  std::error_code error;
  fs::rename(temporary, path, error);
  if (error) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw std::runtime_error(
        fmt::format("{}: cannot move the file into place ({})", path.string(), error.message()));
  }
}

}  // namespace radarpr
