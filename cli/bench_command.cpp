#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "cli/common_options.hpp"
#include "cli/number_options.hpp"
#include "cli/verb.hpp"

#ifdef RADARPR_WITH_BENCH
#include "benchmarks/bench_report.hpp"
#include "benchmarks/bench_runner.hpp"
#include "benchmarks/extraction_benchmarks.hpp"
#include "benchmarks/retrieval_benchmarks.hpp"
#endif

namespace radarpr::cli {
namespace {

constexpr const char* kBenchDescription =
    R"(microbenchmarks: extraction and retrieval times, written to results/bench/bench.{json,md}

Runs the microbenchmarks in this process and writes DIR/bench.json (every measurement, the
machine: CPU, cores, memory, OS, compiler, build type, radarpr version, date, threads) and
DIR/bench.md (the tables and the speed targets, met or not):
- extraction of every registered descriptor at its defaults on a 400 x 3360 and a 400 x 3768 scan
  (the real MulRan and Oxford samples of the shared data folder when present, synthetic scans
  otherwise), split into PNG decode, preparation, Cen 2018 features and descriptor, with payload
  and paper bytes and the multiple of a plain pass over the same scan; one thread;
- retrieval per strategy over synthetic drives of 10^3, 10^4 and 10^5 values: index build, search
  time per query, multi-session and single-session (query i against frames 0..i-50); every
  thread --threads allows;
- start-up: this radarpr as a whole process, `radarpr --version` and `radarpr extract referee` on
  the 400 x 3360 scan, against the same decode and extraction in a running process.
A plugin's descriptors (--plugin) are measured with the built-ins: their extraction always, their
retrieval when named with --descriptor. The default run takes about five minutes on two cores.)";

struct BenchArguments {
  std::string out = "results/bench";
  std::string filter;
  bool quick = false;
  std::optional<long long> repetitions;
  std::vector<std::string> descriptors;
  std::vector<long long> sizes;
  std::string data;
  bool force = false;
  std::optional<long long> threads;
};

#ifdef RADARPR_WITH_BENCH
// This radarpr program, whose whole-process start-up the benchmarks time; empty (not timed) where
// the system cannot say.
std::filesystem::path this_program() {
  std::error_code unknown;
  std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", unknown);
  return unknown ? std::filesystem::path() : program;
}

int bench(const BenchArguments& arguments) {
  bench::BenchOptions options;
  options.real_data_root = arguments.data.empty() ? bench::default_real_data_root()
                                                  : std::filesystem::path(arguments.data);
  options.filter = arguments.filter;
  options.quick = arguments.quick;
  if (arguments.repetitions) options.repetitions = static_cast<int>(*arguments.repetitions);
  options.descriptor_ids = arguments.descriptors;
  options.cli_program = this_program();
  if (!arguments.sizes.empty()) {
    options.retrieval.database_sizes.assign(arguments.sizes.begin(), arguments.sizes.end());
  }
  if (!bench::optimised_build() && !arguments.force) {
    fmt::print(stderr,
               "radarpr bench: this radarpr is not an optimised build, so its timings would not "
               "describe radarpr. Rebuild with -DCMAKE_BUILD_TYPE=Release, or pass --force to "
               "measure anyway (the report then carries a warning).\n");
    return 2;
  }
  if (!options.descriptor_ids.empty()) {
    options.retrieval.descriptor_ids = bench::retrieval_descriptor_ids(options.descriptor_ids);
    // --descriptor adds to the registered descriptors rather than replacing them.
    std::vector<std::string> ids = bench::registered_descriptor_ids();
    ids.insert(ids.end(), options.descriptor_ids.begin(), options.descriptor_ids.end());
    options.descriptor_ids = ids;
  }
  const bench::BenchRun run = bench::run_benchmarks(options);
  if (run.results.empty()) {
    throw UsageError(fmt::format("no benchmark matches the filter '{}'", options.filter));
  }
  bench::write_report(run, arguments.out);
  fmt::print("\nwrote {0}/bench.json and {0}/bench.md\n", arguments.out);
  for (const bench::TargetCheck& target : bench::check_targets(run)) {
    if (target.measured.empty()) continue;
    fmt::print("  [{}] {}: {}{}\n", target.part, target.target, target.measured,
               target.met ? (*target.met ? " - met" : " - NOT MET") : "");
  }
  return 0;
}
#else
int bench(const BenchArguments&) {
  throw std::runtime_error("built without benchmarks (RADARPR_BUILD_BENCHMARKS=OFF)");
}
#endif

// The arguments and options of `radarpr bench`, and what it does with them.
VerbAction define_bench(CLI::App& verb) {
  auto arguments = std::make_shared<BenchArguments>();
  verb.add_option("--out", arguments->out, "where the report goes")
      ->type_name("DIR")
      ->capture_default_str();
  verb.add_option("--filter", arguments->filter,
                  "only the benchmarks whose name matches, e.g. 'extract/referee' or "
                  "'/1000/'")
      ->type_name("REGEX");
  verb.add_flag("--quick", arguments->quick,
                "one short repetition each, databases up to 10^4 (a minute or two)");
  add_whole_number_option(verb, "--repetitions", arguments->repetitions, {1, 1000}, "N",
                          "repetitions per benchmark, the report takes the median")
      ->default_str("5 on one scan, 3 in retrieval");
  verb.add_option("--descriptor", arguments->descriptors,
                  "also benchmark the extraction of this configuration, e.g. "
                  "referee:kernel=box; for a plugin's descriptor, its retrieval too")
      ->type_name("ID")
      ->allow_extra_args(false);
  add_whole_numbers_option(verb, "--sizes", arguments->sizes, {1, 100'000'000}, "N",
                           "retrieval database sizes")
      ->default_str("1000,10000,100000");
  verb.add_option("--data", arguments->data, "the real-data folder")
      ->type_name("DIR")
      ->default_str("$RADARPR_BENCH_DATA, else the source tree's ../shared/data/real");
  verb.add_flag("--force", arguments->force,
                "run even in a non-optimised build (the report then says so in bold)");
  add_threads_option(verb, arguments->threads);
  return [arguments] { return bench(*arguments); };
}

}  // namespace

Verb bench_verb() {
  return {"bench", kBenchDescription, define_bench};
}

}  // namespace radarpr::cli
