// The radarpr command line: one verb per job (run, report, compare, inspect, list, extract,
// simulate, bench).
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "evaluation/version.hpp"

namespace {

constexpr const char* kMainHelp = R"(radarpr - benchmark radar place-recognition descriptors

usage:
  radarpr run CONFIG [--out DIR] [--set key.path=value ...] [--quiet]
                           run an experiment: extract, evaluate, write results/<experiment>/
                           with its figures, tables and index.html
  radarpr report RESULTS_DIR [--missed]
                           redraw a results folder's figures, tables and index.html
  radarpr compare RESULTS_DIR... [--out DIR]
                           merge runs into one table and overlaid curves
  radarpr inspect CONFIG | --dataset TYPE ROOT [key=value ...]
                           what the datasets hold, revisit counts and problems, before a run
  radarpr list [--json]    the descriptors with their parameters and defaults
  radarpr extract DESCRIPTOR_ID FILE.png ...
                           print each polar PNG's descriptor as JSON
  radarpr simulate CONFIG --out DIR
                           write the config's synthetic sequences as polar PNGs + poses.csv
  radarpr bench [--out DIR] [--filter REGEX] [--quick]
                           microbenchmarks: extraction and retrieval times, written to
                           results/bench/bench.{json,md}
  radarpr --version

Every command also takes --plugin PATH (repeatable): load a descriptor plugin, a shared library
built against this radarpr (README "Write your own descriptor"), before anything else. The paths in
$RADARPR_PLUGINS (colon-separated) are loaded too, and a config may list its own under "plugins".

`radarpr COMMAND --help` explains a command.
)";

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args;
  try {
    args = radarpr::cli::load_plugins_and_strip_options({argv + 1, argv + argc});
  } catch (const radarpr::cli::UsageError& error) {
    fmt::print(stderr, "radarpr: {} (see radarpr --help)\n", error.what());
    return 2;
  } catch (const std::exception& error) {
    fmt::print(stderr, "radarpr: error: {}\n", error.what());
    return 1;
  }
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    fmt::print("{}", kMainHelp);
    return args.empty() ? 2 : 0;
  }
  if (args[0] == "--version") {
    fmt::print("radarpr {}\n", radarpr::radarpr_version());
    return 0;
  }
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  try {
    if (args[0] == "run") return radarpr::cli::run_command(rest);
    if (args[0] == "list") return radarpr::cli::list_command(rest);
    if (args[0] == "extract") return radarpr::cli::extract_command(rest);
    if (args[0] == "inspect") return radarpr::cli::inspect_command(rest);
    if (args[0] == "simulate") return radarpr::cli::simulate_command(rest);
    if (args[0] == "report") return radarpr::cli::report_command(rest);
    if (args[0] == "compare") return radarpr::cli::compare_command(rest);
#ifdef RADARPR_WITH_BENCH
    if (args[0] == "bench") return radarpr::cli::bench_command(rest);
#else
    if (args[0] == "bench")
      throw std::runtime_error("built without benchmarks (RADARPR_BUILD_BENCHMARKS=OFF)");
#endif
    throw radarpr::cli::UsageError(fmt::format("unknown command '{}'", args[0]));
  } catch (const radarpr::cli::UsageError& error) {
    fmt::print(stderr, "radarpr: {} (see radarpr {}--help)\n", error.what(),
               args[0] == "run" || args[0] == "list" || args[0] == "extract" ||
                       args[0] == "inspect" || args[0] == "simulate" || args[0] == "bench" ||
                       args[0] == "report" || args[0] == "compare"
                   ? args[0] + " "
                   : "");
    return 2;
  } catch (const std::exception& error) {
    fmt::print(stderr, "radarpr: error: {}\n", error.what());
    return 1;
  }
}
