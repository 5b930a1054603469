#include "benchmarks/bench_runner.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <system_error>

#include <benchmark/benchmark.h>

#include "benchmarks/extraction_benchmarks.hpp"
#include "benchmarks/startup_benchmarks.hpp"
#include "evaluation/parallel.hpp"

namespace radarpr::bench {
namespace {

using Run = benchmark::BenchmarkReporter::Run;

// Google Benchmark 1.8 replaced Run::error_occurred by Run::skipped.
template <typename R>
bool run_failed(const R& run) {
  if constexpr (requires { run.error_occurred; }) {
    return run.error_occurred;
  } else {
    return static_cast<bool>(run.skipped);
  }
}

template <typename R>
std::string run_message(const R& run) {
  if constexpr (requires { run.error_message; }) {
    return run.error_message;
  } else {
    return run.skip_message;
  }
}

// The console table as usual, plus every repetition kept for the medians.
class CollectingReporter final : public benchmark::ConsoleReporter {
 public:
  // Colours only on a terminal (the default reporter's flags do not reach a custom one).
  CollectingReporter() : ConsoleReporter(::isatty(STDOUT_FILENO) ? OO_ColorTabular : OO_Tabular) {}

  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs) {
      if (run.run_type == Run::RT_Iteration) runs_[run.run_name.function_name].push_back(run);
    }
    ConsoleReporter::ReportRuns(runs);
  }

  const std::map<std::string, std::vector<Run>>& runs() const { return runs_; }

 private:
  std::map<std::string, std::vector<Run>> runs_;
};

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t middle = values.size() / 2;
  return values.size() % 2 == 1 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

Measurement measurement_of(const std::vector<Run>& runs) {
  Measurement measurement;
  std::vector<double> real;
  std::vector<double> cpu;
  for (const Run& run : runs) {
    if (run_failed(run)) {
      measurement.error = run_message(run);
      continue;
    }
    const auto iterations = static_cast<double>(std::max<std::int64_t>(1, run.iterations));
    real.push_back(run.real_accumulated_time / iterations);
    cpu.push_back(run.cpu_accumulated_time / iterations);
  }
  measurement.real_seconds = median(real);
  measurement.cpu_seconds = median(cpu);
  measurement.real_seconds_each = real;
  measurement.cpu_seconds_each = cpu;
  measurement.repetitions = real.size();
  if (!runs.empty()) {
    measurement.iterations = runs.front().iterations;
    for (const auto& [name, counter] : runs.front().counters) {
      measurement.counters[name] = counter.value;
    }
  }
  return measurement;
}

ScanSummary summary_of(const BenchScan& scan) {
  return {scan.label,
          scan.radar,
          scan.source,
          scan.real,
          scan.image.azimuth_count(),
          scan.image.range_bin_count(),
          scan.png_bytes};
}

}  // namespace

std::filesystem::path default_real_data_root() {
  if (const char* folder = std::getenv("RADARPR_BENCH_DATA"); folder != nullptr && *folder) {
    return folder;
  }
  return std::filesystem::path(RADARPR_SOURCE_DIR) / ".." / "shared" / "data" / "real";
}

ScratchFolder::ScratchFolder()
    : path_(std::filesystem::temp_directory_path() /
            ("radarpr-bench-" + std::to_string(::getpid()))) {}

ScratchFolder::~ScratchFolder() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

RunLength run_length(const BenchOptions& options) {
  RunLength length;
  length.min_seconds = options.quick ? 0.05 : 0.5;
  length.repetitions = options.repetitions > 0 ? options.repetitions : options.quick ? 1 : 3;
  length.cheap_repetitions = options.repetitions > 0 ? options.repetitions : options.quick ? 1 : 5;
  return length;
}

std::vector<BenchScan> register_benchmarks(BenchPlan& plan, const BenchOptions& options,
                                           const std::filesystem::path& scratch_folder) {
  std::vector<BenchScan> scans = prepare_bench_scans(options.real_data_root, scratch_folder);
  add_extraction_benchmarks(
      plan, scans,
      options.descriptor_ids.empty() ? registered_descriptor_ids() : options.descriptor_ids);
  add_startup_benchmarks(plan, scans, options.cli_program);
  RetrievalBenchOptions retrieval = options.retrieval;
  if (options.quick) {
    std::erase_if(retrieval.database_sizes, [](std::size_t n) { return n > 10'000; });
  }
  add_retrieval_benchmarks(plan, retrieval);
  return scans;
}

BenchRun run_benchmarks(const BenchOptions& options) {
  BenchRun run;
  run.machine = describe_this_machine();
  run.quick = options.quick;
  run.length = run_length(options);
  run.filter = options.filter;
  run.threads = default_thread_count();
  const ScratchFolder scratch;
  BenchPlan plan(options.filter, run.length);
  const std::vector<BenchScan> scans = register_benchmarks(plan, options, scratch.path());
  for (const BenchScan& scan : scans) run.scans.push_back(summary_of(scan));

  char program[] = "radarpr bench";
  char* argv[] = {program, nullptr};
  int argc = 1;
  benchmark::Initialize(&argc, argv);
  CollectingReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();

  for (const BenchCase& bench : plan.cases()) {
    const auto found = reporter.runs().find(bench.name);
    if (found == reporter.runs().end()) continue;
    run.results.push_back({bench, measurement_of(found->second)});
  }
  run.skipped = plan.skipped();
  return run;
}

}  // namespace radarpr::bench
