#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "benchmarks/bench_report.hpp"
#include "benchmarks/bench_runner.hpp"
#include "benchmarks/extraction_benchmarks.hpp"
#include "benchmarks/retrieval_benchmarks.hpp"
#include "cli/commands.hpp"

namespace radarpr::cli {

const char* const kBenchHelp =
    R"(usage: radarpr bench [--out DIR] [--filter REGEX] [--quick] [--repetitions N]
                     [--descriptor ID ...] [--sizes N,N,...] [--data DIR] [--force]

Runs the microbenchmarks in this process and writes DIR/bench.json (every measurement, the
machine: CPU, cores, memory, OS, compiler, build type, radarpr version, date) and DIR/bench.md
(the tables and the issue's speed targets, met or not):
- extraction of every registered descriptor at its defaults on a 400 x 3360 and a 400 x 3768 scan
  (the real MulRan and Oxford samples of the shared data folder when present, synthetic scans
  otherwise), split into PNG decode, preparation, Cen 2018 features and descriptor, with payload
  and paper bytes and the multiple of a plain pass over the same scan; one thread;
- retrieval per strategy over synthetic drives of 10^3, 10^4 and 10^5 values: index build, search
  time per query, multi-session and single-session (query i against frames 0..i-50); every core.
The default run takes about ten minutes on two cores.

  --out DIR          where the report goes (default results/bench)
  --filter REGEX     only the benchmarks whose name matches, e.g. 'extract/referee' or '/1000/'
  --quick            one short repetition each, databases up to 10^4 (a minute or two)
  --repetitions N    repetitions per benchmark, the report takes the median (default 5 on one
                     scan, 3 in retrieval)
  --descriptor ID    also benchmark the extraction of this configuration (repeatable), e.g.
                     referee:kernel=box; for a plugin's descriptor, its retrieval too
  --sizes N,N,...    retrieval database sizes (default 1000,10000,100000)
  --data DIR         the real-data folder (default $RADARPR_BENCH_DATA, else the source tree's
                     ../shared/data/real)
  --force            run even in a non-optimised build (the report then says so in bold)
  --plugin PATH      load a descriptor plugin first (repeatable; $RADARPR_PLUGINS too): its
                     descriptors' extraction is measured with the built-ins'; retrieval only
                     for a plugin descriptor named with --descriptor
)";

namespace {

std::string option_value(const std::vector<std::string>& args, std::size_t& i) {
  if (i + 1 >= args.size()) throw UsageError(fmt::format("{} needs a value", args[i]));
  return args[++i];
}

std::size_t positive_count(const std::string& text, const std::string& option) {
  std::size_t used = 0;
  unsigned long long value = 0;
  try {
    value = std::stoull(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || value == 0 || text.starts_with("-")) {
    throw UsageError(fmt::format("{}: '{}' is not a positive whole number", option, text));
  }
  return static_cast<std::size_t>(value);
}

std::vector<std::size_t> sizes_from(const std::string& text) {
  std::vector<std::size_t> sizes;
  std::size_t begin = 0;
  while (begin <= text.size()) {
    const std::size_t comma = std::min(text.find(',', begin), text.size());
    sizes.push_back(positive_count(text.substr(begin, comma - begin), "--sizes"));
    begin = comma + 1;
  }
  return sizes;
}

}  // namespace

int bench_command(const std::vector<std::string>& args) {
  bench::BenchOptions options;
  options.real_data_root = bench::default_real_data_root();
  std::string out = "results/bench";
  bool force = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg == "--help" || arg == "-h") {
      fmt::print("{}", kBenchHelp);
      return 0;
    } else if (arg == "--out") {
      out = option_value(args, i);
    } else if (arg == "--filter") {
      options.filter = option_value(args, i);
    } else if (arg == "--quick") {
      options.quick = true;
    } else if (arg == "--repetitions") {
      options.repetitions = static_cast<int>(positive_count(option_value(args, i), arg));
    } else if (arg == "--descriptor") {
      options.descriptor_ids.push_back(option_value(args, i));
    } else if (arg == "--sizes") {
      options.retrieval.database_sizes = sizes_from(option_value(args, i));
    } else if (arg == "--data") {
      options.real_data_root = option_value(args, i);
    } else if (arg == "--force") {
      force = true;
    } else {
      throw UsageError(fmt::format("unknown argument '{}'", arg));
    }
  }
  if (!bench::optimised_build() && !force) {
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
  bench::write_report(run, out);
  fmt::print("\nwrote {0}/bench.json and {0}/bench.md\n", out);
  for (const bench::TargetCheck& target : bench::check_targets(run)) {
    if (target.measured.empty()) continue;
    fmt::print("  [{}] {}: {}{}\n", target.part, target.target, target.measured,
               target.met ? (*target.met ? " - met" : " - NOT MET") : "");
  }
  return 0;
}

}  // namespace radarpr::cli
