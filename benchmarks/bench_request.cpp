#include "benchmarks/bench_request.hpp"

#include <fmt/format.h>

#include "benchmarks/bench_report.hpp"
#include "benchmarks/bench_runner.hpp"
#include "benchmarks/extraction_benchmarks.hpp"
#include "benchmarks/machine_description.hpp"
#include "benchmarks/retrieval_benchmarks.hpp"

namespace radarpr::bench {

BenchOutcome run_bench_request(const BenchRequest& request) {
  BenchOptions options;
  options.real_data_root =
      request.data.empty() ? default_real_data_root() : std::filesystem::path(request.data);
  options.filter = request.filter;
  options.quick = request.quick;
  if (request.repetitions) options.repetitions = static_cast<int>(*request.repetitions);
  options.descriptor_ids = request.descriptors;
  options.cli_program = request.cli_program;
  if (!request.sizes.empty()) {
    options.retrieval.database_sizes.assign(request.sizes.begin(), request.sizes.end());
  }
  if (!optimised_build() && !request.force) {
    fmt::print(stderr,
               "radarpr bench: this radarpr is not an optimised build, so its timings would not "
               "describe radarpr. Rebuild with -DCMAKE_BUILD_TYPE=Release, or pass --force to "
               "measure anyway (the report then carries a warning).\n");
    return {2, ""};
  }
  if (!options.descriptor_ids.empty()) {
    options.retrieval.descriptor_ids = retrieval_descriptor_ids(options.descriptor_ids);
    // --descriptor adds to the registered descriptors rather than replacing them.
    std::vector<std::string> ids = registered_descriptor_ids();
    ids.insert(ids.end(), options.descriptor_ids.begin(), options.descriptor_ids.end());
    options.descriptor_ids = ids;
  }
  const BenchRun run = run_benchmarks(options);
  if (run.results.empty()) {
    return {2, fmt::format("no benchmark matches the filter '{}'", options.filter)};
  }
  write_report(run, request.out);
  fmt::print("\nwrote {0}/bench.json and {0}/bench.md\n", request.out);
  for (const TargetCheck& target : check_targets(run)) {
    if (target.measured.empty()) continue;
    fmt::print("  [{}] {}: {}{}\n", target.part, target.target, target.measured,
               target.met ? (*target.met ? " - met" : " - NOT MET") : "");
  }
  return {};
}

}  // namespace radarpr::bench
