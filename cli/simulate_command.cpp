#include <atomic>
#include <filesystem>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "datasets/synthetic/scan_export.hpp"
#include "datasets/synthetic/synthetic_sequence.hpp"
#include "evaluation/config/experiment_config.hpp"
#include "evaluation/parallel.hpp"

namespace radarpr::cli {

const char* const kSimulateHelp =
    R"(usage: radarpr simulate CONFIG --out DIR [--set key.path=value ...] [--threads N] [--quiet]

Renders every synthetic sequence of CONFIG to disk, as a real dataset would be laid out, so the
same loaders and decoders read it back:
  DIR/<dataset>/<query|database|training>/scans/<t_us>.png
        Oxford-layout polar PNGs: per azimuth row the µs timestamp (8 bytes LE), the encoder
        count (2 bytes LE, 0..5599), the valid flag 255, then the range bins
  DIR/<dataset>/<role>/poses.csv
        timestamp,x,y,yaw (µs, metres, radians), one row per scan
Read them with {"type": "folder", "root": "DIR/<dataset>", "sequence": "<role>",
"range_resolution_m": <the printed resolution>}. Sequences of other types are skipped. The
same config always gives byte-identical files.

  --out DIR       where to write (required); existing scans of the same names are overwritten,
                  other PNGs in a scans/ folder stop the command before it writes anything
  --set key.path=value
                  change a config value first, as for run
  --threads N     render with N threads (default: one per core)
  --quiet         no progress lines
)";

namespace {

struct SimulateArgs {
  std::string config;
  std::string out;
  std::vector<std::string> overrides;
  int threads = 0;
  bool quiet = false;
};

SimulateArgs parse_args(const std::vector<std::string>& args) {
  SimulateArgs parsed;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size()) throw UsageError(fmt::format("{} needs a value", arg));
      return args[++i];
    };
    if (arg == "--out") {
      parsed.out = value();
    } else if (arg == "--set") {
      parsed.overrides.push_back(value());
    } else if (arg == "--threads") {
      const std::string& text = value();
      try {
        parsed.threads = std::stoi(text);
      } catch (const std::exception&) {
        throw UsageError(fmt::format("--threads expects a number, got '{}'", text));
      }
      if (parsed.threads < 0) throw UsageError("--threads must be >= 0");
    } else if (arg == "--quiet") {
      parsed.quiet = true;
    } else if (arg.starts_with("-")) {
      throw UsageError(fmt::format("unknown option '{}'", arg));
    } else if (parsed.config.empty()) {
      parsed.config = arg;
    } else {
      throw UsageError(fmt::format("one CONFIG expected, got '{}' and '{}'", parsed.config, arg));
    }
  }
  if (parsed.config.empty()) throw UsageError("simulate needs a CONFIG file");
  if (parsed.out.empty()) throw UsageError("simulate needs --out DIR");
  return parsed;
}

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
                    int threads, bool quiet) {
  std::filesystem::create_directories(folder / "scans");
  synthetic::write_folder_poses(folder, sequence.records());
  std::atomic<std::size_t> done{0};
  const std::size_t total = sequence.size();
  parallel_for(total, threads, [&](std::size_t i) {
    synthetic::write_oxford_png(synthetic::scan_png_path(folder, sequence.records()[i]),
                                sequence.load_image(i));
    const std::size_t finished = ++done;
    if (!quiet && (finished % 100 == 0 || finished == total)) {
      fmt::print(stderr, "\r  {}: {}/{} scans", folder.string(), finished, total);
      if (finished == total) fmt::print(stderr, "\n");
    }
  });
}

}  // namespace

int simulate_command(const std::vector<std::string>& args) {
  for (const auto& arg : args) {
    if (arg == "--help" || arg == "-h") {
      fmt::print("{}", kSimulateHelp);
      return 0;
    }
  }
  const SimulateArgs parsed = parse_args(args);
  const ExperimentConfig config = load_experiment_config(parsed.config, parsed.overrides);
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
      targets.push_back({label, std::filesystem::path(parsed.out) / dataset.name / role,
                         std::make_unique<SyntheticSequence>(*spec->synthetic)});
    }
  }
  // Every folder is checked before anything is written.
  for (const Target& target : targets) refuse_foreign_scans(*target.sequence, target.folder);
  for (const Target& target : targets) {
    const SyntheticSequence& synthetic = *target.sequence;
    write_sequence(synthetic, target.folder, parsed.threads, parsed.quiet);
    fmt::print("{}: {} scans of {} x {} at {} m/bin -> {}\n", target.label, synthetic.size(),
               synthetic.config().radar.azimuth_count, synthetic.config().radar.range_bin_count,
               synthetic.config().radar.range_resolution_m, target.folder.string());
  }
  const std::size_t written = targets.size();
  if (written == 0) {
    fmt::print("{}: no synthetic sequence to write\n", parsed.config);
    return 1;
  }
  return 0;
}

}  // namespace radarpr::cli
