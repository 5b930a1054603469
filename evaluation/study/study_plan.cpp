#include "evaluation/study/study_plan.hpp"

#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include <stdexcept>

#include <unistd.h>

#include <fmt/format.h>

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
constexpr double kSecondsPerComparison = 2e-8;

std::string descriptor_part(const ExperimentConfig& config, std::size_t descriptor) {
  return descriptor_folder_name(config.descriptors[descriptor].id);
}

}  // namespace

std::string_view to_string(UnitPhase phase) {
  return phase == UnitPhase::values ? "values" : "evaluate";
}

std::vector<StudyUnit> plan_units(const ExperimentConfig& config, UnitCosts costs) {
  const bool estimate = costs == UnitCosts::estimate;
  std::vector<StudyUnit> values_units;
  std::vector<StudyUnit> evaluate_units;
  for (std::size_t m = 0; m < config.matrices.size(); ++m) {
    const SessionMatrixConfig& matrix = config.matrices[m];
    MatrixSequences sequences(matrix);
    std::vector<std::size_t> scans(matrix.sessions.size());
    for (std::size_t s = 0; estimate && s < scans.size(); ++s) {
      scans[s] = sequences.session(s).size();
    }
    // Which sessions each descriptor needs, under which codebook: the union of the pairs' jobs.
    for (std::size_t d = 0; d < config.descriptors.size(); ++d) {
      std::map<std::optional<std::size_t>, std::set<std::size_t>> by_source;
      for (std::size_t p = 0; p < matrix.pairs.size(); ++p) {
        for (const auto& job : matrix_pair_jobs(config, matrix, p, d)) {
          by_source[job.trained_on].insert(job.session);
        }
      }
      for (const auto& [source, sessions] : by_source) {
        if (!source) {
          // Not trainable: one unit per session.
          for (std::size_t s : sessions) {
            StudyUnit unit;
            unit.id = fmt::format("values.{}.{}.{}", matrix.name, matrix.sessions[s].name,
                                  descriptor_part(config, d));
            unit.matrix = m;
            unit.descriptor = d;
            unit.jobs = {{d, s, std::nullopt}};
            unit.scans_described = scans[s];
            values_units.push_back(std::move(unit));
          }
          continue;
        }
        // Trainable: one unit per codebook, which encodes every session it is used on.
        StudyUnit unit;
        const bool own_training = *source == kMatrixTrainingSequence;
        unit.id =
            fmt::format("train.{}.{}.{}", matrix.name,
                        own_training ? std::string("training") : matrix.sessions[*source].name,
                        descriptor_part(config, d));
        unit.matrix = m;
        unit.descriptor = d;
        for (std::size_t s : sessions) {
          unit.jobs.push_back({d, s, source});
          unit.scans_described += scans[s];
        }
        if (estimate) {
          unit.scans_trained = own_training ? sequences.training().size() : scans[*source];
        }
        values_units.push_back(std::move(unit));
      }
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
    unit.comparisons = (dataset.database ? query * database : query * query / 2) * descriptors;
    evaluate_units.push_back(std::move(unit));
  }
  std::vector<StudyUnit> units = std::move(values_units);
  for (auto& unit : evaluate_units) units.push_back(std::move(unit));
  for (auto& unit : units) {
    unit.estimated_cpu_seconds =
        static_cast<double>(unit.scans_described) * kExtractSecondsPerScan +
        static_cast<double>(unit.scans_trained) * kTrainSecondsPerScan +
        static_cast<double>(unit.comparisons) * kSecondsPerComparison;
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
  for (UnitPhase phase : {UnitPhase::values, UnitPhase::evaluate}) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& unit : units) {
      if (unit.phase != phase) continue;
      nlohmann::json inputs = nlohmann::json::array();
      nlohmann::json outputs = nlohmann::json::array();
      if (unit.phase == UnitPhase::values) {
        const SessionMatrixConfig& matrix = config.matrices[*unit.matrix];
        std::set<std::string> sources;
        for (const auto& job : unit.jobs) {
          inputs.push_back(fmt::format("session {} of matrix {}", matrix.sessions[job.session].name,
                                       matrix.name));
          if (job.trained_on && sources.insert("t").second) {
            inputs.push_back(*job.trained_on == kMatrixTrainingSequence
                                 ? fmt::format("the training sequence of matrix {}", matrix.name)
                                 : fmt::format("session {} of matrix {} (training)",
                                               matrix.sessions[*job.trained_on].name, matrix.name));
          }
          outputs.push_back(fmt::format("cache/: {} on session {}",
                                        config.descriptors[job.descriptor].id,
                                        matrix.sessions[job.session].name));
        }
        outputs.push_back(fs::relative(folder.stamp(unit.id), folder.root).string());
      } else {
        if (unit.matrix) {
          // The values units that compute what this one reads.
          for (const auto& other : units) {
            if (other.phase != UnitPhase::values || other.matrix != unit.matrix ||
                other.descriptor != unit.descriptor) {
              continue;
            }
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
           fmt::format("{} s per scan described, {} s per training scan, {} s per distance: "
                       "defaults, not measurements",
                       kExtractSecondsPerScan, kTrainSecondsPerScan, kSecondsPerComparison)},
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
