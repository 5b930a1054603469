#include <algorithm>
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
// The request alone: plain data, with or without the benchmarks.
#include "benchmarks/bench_request.hpp"

#ifdef RADARPR_WITH_BENCH
#include <dlfcn.h>

#include "benchmarks/bench_module.hpp"
#include "descriptors/plugins/plugin_compatibility.hpp"
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

// What `radarpr bench` asks of the benchmarks (the options bind to it directly), and the threads.
struct BenchArguments {
  bench::BenchRequest request;
  std::optional<long long> threads;  // applied when parsed (add_threads_option)
};

#ifdef RADARPR_WITH_BENCH
// This radarpr program, whose whole-process start-up the benchmarks time; empty (not timed) where
// the system cannot say.
std::filesystem::path this_program() {
  std::error_code unknown;
  std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", unknown);
  return unknown ? std::filesystem::path() : program;
}

[[noreturn]] void module_failure(const std::filesystem::path& path, const std::string& what) {
  throw std::runtime_error(
      fmt::format("radarpr bench needs radarpr's benchmark module {}, which {}; rebuild radarpr "
                  "(cmake --build) or reinstall it, so that the module matches the program",
                  path.string(), what));
}

std::string last_dl_error() {
  const char* error = ::dlerror();
  return error != nullptr ? error : "unknown error";
}

// The benchmark module (benchmarks/bench_module.hpp), loaded when the verb runs: next to the
// program (a build tree, build/radarpr) or in the installed package's library folder, never from a
// path the environment or the current directory chooses, as the OpenCV module is.
bench::BenchModuleRun load_bench_module(const std::filesystem::path& program) {
  if (program.empty()) {
    throw std::runtime_error(
        "radarpr bench cannot find its benchmark module: the program's own path (/proc/self/exe) "
        "is unreadable");
  }
  const std::filesystem::path folder = program.parent_path();
  const std::vector<std::filesystem::path> candidates = {
      folder / RADARPR_BENCH_MODULE_FILE,
      (folder / RADARPR_BENCH_MODULE_FROM_PROGRAM / RADARPR_BENCH_MODULE_FILE).lexically_normal()};
  const auto found = std::find_if(candidates.begin(), candidates.end(), [](const auto& path) {
    std::error_code error;
    return std::filesystem::is_regular_file(path, error);
  });
  if (found == candidates.end()) {
    throw std::runtime_error(fmt::format(
        "radarpr bench needs radarpr's benchmark module, which is missing: expected {} (a build "
        "tree) or {} (an installed radarpr); build it (cmake --build) or reinstall radarpr",
        candidates[0].string(), candidates[1].string()));
  }
  // RTLD_NOW: a function the program does not provide fails here, with its name. Never closed:
  // its code runs until the verb returns.
  void* library = ::dlopen(found->c_str(), RTLD_NOW | RTLD_LOCAL);
  if (library == nullptr) module_failure(*found, "cannot be loaded: " + last_dl_error());
  const auto* abi =
      static_cast<const RadarprPluginAbi*>(::dlsym(library, RADARPR_BENCH_MODULE_ABI_SYMBOL));
  const auto run =
      reinterpret_cast<bench::BenchModuleRun>(::dlsym(library, RADARPR_BENCH_MODULE_RUN_SYMBOL));
  if (abi == nullptr || run == nullptr) {
    module_failure(*found, fmt::format("exports no '{}': not radarpr's benchmark module",
                                       abi == nullptr ? RADARPR_BENCH_MODULE_ABI_SYMBOL
                                                      : RADARPR_BENCH_MODULE_RUN_SYMBOL));
  }
  const RadarprPluginAbi& host = host_plugin_abi();
  const auto reason = plugin_incompatibility(*abi, host);
  if (reason || abi->version_patch != host.version_patch) {
    module_failure(
        *found, "was built for another radarpr: " +
                    reason.value_or(fmt::format("{}, this program is {}", describe_plugin_abi(*abi),
                                                describe_plugin_abi(host))));
  }
  return run;
}

int bench(const BenchArguments& arguments) {
  bench::BenchRequest request = arguments.request;
  request.cli_program = this_program();
  const bench::BenchModuleRun run = load_bench_module(request.cli_program);
  bench::BenchOutcome outcome;
  run(request, outcome);
  if (!outcome.usage_error.empty()) throw UsageError(outcome.usage_error);
  return outcome.exit_code;
}
#else
int bench(const BenchArguments&) {
  throw std::runtime_error("built without benchmarks (RADARPR_BUILD_BENCHMARKS=OFF)");
}
#endif

// The arguments and options of `radarpr bench`, and what it does with them.
VerbAction define_bench(CLI::App& verb) {
  auto arguments = std::make_shared<BenchArguments>();
  verb.add_option("--out", arguments->request.out, "where the report goes")
      ->type_name("DIR")
      ->capture_default_str();
  verb.add_option("--filter", arguments->request.filter,
                  "only the benchmarks whose name matches, e.g. 'extract/referee' or "
                  "'/1000/'")
      ->type_name("REGEX");
  verb.add_flag("--quick", arguments->request.quick,
                "one short repetition each, databases up to 10^4 (a minute or two)");
  add_whole_number_option(verb, "--repetitions", arguments->request.repetitions, {1, 1000}, "N",
                          "repetitions per benchmark, the report takes the median")
      ->default_str("5 on one scan, 3 in retrieval");
  verb.add_option("--descriptor", arguments->request.descriptors,
                  "also benchmark the extraction of this configuration, e.g. "
                  "referee:kernel=box; for a plugin's descriptor, its retrieval too")
      ->type_name("ID")
      ->allow_extra_args(false);
  add_whole_numbers_option(verb, "--sizes", arguments->request.sizes, {1, 100'000'000}, "N",
                           "retrieval database sizes")
      ->default_str("1000,10000,100000");
  verb.add_option("--data", arguments->request.data, "the real-data folder")
      ->type_name("DIR")
      ->default_str("$RADARPR_BENCH_DATA, else the source tree's ../shared/data/real");
  verb.add_flag("--force", arguments->request.force,
                "run even in a non-optimised build (the report then says so in bold)");
  add_threads_option(verb, arguments->threads);
  return [arguments] { return bench(*arguments); };
}

}  // namespace

Verb bench_verb() {
  return {"bench", kBenchDescription, define_bench};
}

}  // namespace radarpr::cli
