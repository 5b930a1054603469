#include <atomic>
#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "cli/common_options.hpp"
#include "cli/verb.hpp"
#include "datasets/synthetic/scan_export.hpp"
#include "datasets/synthetic/synthetic_sequence.hpp"
#include "evaluation/config/experiment_config.hpp"
#include "evaluation/parallel.hpp"

namespace radarpr::cli {
namespace {

constexpr const char* kSimulateDescription =
    R"(write the config's synthetic sequences as polar PNGs + poses.csv

Renders every synthetic sequence of CONFIG to disk, as a real dataset would be laid out, so the
same loaders and decoders read it back:
  DIR/<dataset>/<query|database|training>/scans/<t_us>.png
        Oxford-layout polar PNGs: per azimuth row the µs timestamp (8 bytes LE), the encoder
        count (2 bytes LE, 0..5599), the valid flag 255, then the range bins
  DIR/<dataset>/<role>/poses.csv
        timestamp,x,y,yaw (µs, metres, radians), one row per scan
Read them with {"type": "folder", "root": "DIR/<dataset>", "sequence": "<role>",
"range_resolution_m": <the printed resolution>}. Sequences of other types are skipped. The same
config always gives byte-identical files, whatever the thread count.)";

struct SimulateArguments {
  std::string config;
  std::string out;
  std::vector<std::string> overrides;
  std::optional<long long> threads;
  bool quiet = false;
};

// The folder loader reads every PNG in scans/, so scans left there by an earlier, longer or other
// simulation would silently join this sequence (and lack poses). Overwriting our own names is fine.
void refuse_foreign_scans(const SyntheticSequence& sequence, const std::filesystem::path& folder) {
  const std::filesystem::path scans = folder / "scans";
  if (!std::filesystem::is_directory(scans)) return;
  std::set<std::filesystem::path> own;
  for (const ScanRecord& record : sequence.records()) {
    own.insert(synthetic::scan_png_path(folder, record).filename());
  }
  for (const auto& entry : std::filesystem::directory_iterator(scans)) {
    if (entry.path().extension() == ".png" && !own.contains(entry.path().filename())) {
      throw std::runtime_error(fmt::format(
          "{}: holds {}, which is not a scan of this sequence (an earlier simulation?); the "
          "folder loader would read it too: empty the folder or choose another --out",
          scans.string(), entry.path().filename().string()));
    }
  }
}

// Renders one sequence (in parallel, each scan once) into `folder`.
void write_sequence(const SyntheticSequence& sequence, const std::filesystem::path& folder,
                    bool quiet) {
  std::filesystem::create_directories(folder / "scans");
  synthetic::write_folder_poses(folder, sequence.records());
  std::atomic<std::size_t> done{0};
  const std::size_t total = sequence.size();
  parallel_for(total, 0, [&](std::size_t i) {
    synthetic::write_oxford_png(synthetic::scan_png_path(folder, sequence.records()[i]),
                                sequence.load_image(i));
    const std::size_t finished = ++done;
    if (!quiet && (finished % 100 == 0 || finished == total)) {
      fmt::print(stderr, "\r  {}: {}/{} scans", folder.string(), finished, total);
      if (finished == total) fmt::print(stderr, "\n");
    }
  });
}

int simulate(const SimulateArguments& arguments) {
  const ExperimentConfig config = load_experiment_config(arguments.config, arguments.overrides);
  struct Target {
    std::string label;  // <dataset>/<role>
    std::filesystem::path folder;
    std::unique_ptr<SyntheticSequence> sequence;
  };
  std::vector<Target> targets;
  for (const DatasetConfig& dataset : config.datasets) {
    std::vector<std::pair<std::string, const SequenceConfig*>> roles = {{"query", &dataset.query}};
    if (dataset.database) roles.emplace_back("database", &*dataset.database);
    if (dataset.training) roles.emplace_back("training", &*dataset.training);
    for (const auto& [role, spec] : roles) {
      const std::string label = dataset.name + "/" + role;
      if (!spec->synthetic) {
        fmt::print("{}: a {} sequence, not synthetic: skipped\n", label, spec->type);
        continue;
      }
      targets.push_back({label, std::filesystem::path(arguments.out) / dataset.name / role,
                         std::make_unique<SyntheticSequence>(*spec->synthetic)});
    }
  }
  // Every folder is checked before anything is written.
  for (const Target& target : targets) refuse_foreign_scans(*target.sequence, target.folder);
  for (const Target& target : targets) {
    const SyntheticSequence& synthetic = *target.sequence;
    write_sequence(synthetic, target.folder, arguments.quiet);
    fmt::print("{}: {} scans of {} x {} at {} m/bin -> {}\n", target.label, synthetic.size(),
               synthetic.config().radar.azimuth_count, synthetic.config().radar.range_bin_count,
               synthetic.config().radar.range_resolution_m, target.folder.string());
  }
  if (targets.empty()) {
    fmt::print("{}: no synthetic sequence to write\n", arguments.config);
    return 1;
  }
  return 0;
}

// The arguments and options of `radarpr simulate`, and what it does with them.
VerbAction define_simulate(CLI::App& verb) {
  auto arguments = std::make_shared<SimulateArguments>();
  add_config_argument(verb, arguments->config)->required();
  verb.add_option("--out", arguments->out,
                  "where to write; existing scans of the same names are overwritten, "
                  "other PNGs in a scans/ folder stop the command before it writes "
                  "anything")
      ->type_name("DIR")
      ->required();
  add_set_option(verb, arguments->overrides);
  add_threads_option(verb, arguments->threads);
  verb.add_flag("--quiet", arguments->quiet, "no progress lines");
  return [arguments] { return simulate(*arguments); };
}

}  // namespace

Verb simulate_verb() {
  return {"simulate", kSimulateDescription, define_simulate};
}

}  // namespace radarpr::cli
