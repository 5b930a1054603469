// The benchmarks of `radarpr bench` as a plain Google Benchmark program: every Google Benchmark
// flag works (--benchmark_filter, --benchmark_repetitions, --benchmark_format=json, ...); it
// writes no report (`radarpr bench` does). Real scans come from $RADARPR_BENCH_DATA or the
// source tree's ../shared/data/real, synthetic ones otherwise.
// Run: build/benchmarks/radarpr_benchmarks --benchmark_filter='extract/referee/'
#include <exception>
#include <iostream>

#include <benchmark/benchmark.h>

#include "benchmarks/bench_runner.hpp"

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  try {
    radarpr::bench::BenchOptions options;
    options.real_data_root = radarpr::bench::default_real_data_root();
    // Length and repetitions from the flags; Google Benchmark filters at run time.
    radarpr::bench::BenchPlan plan("", radarpr::bench::RunLength{0.0, 0, 0});
    const radarpr::bench::ScratchFolder scratch;
    const auto scans = radarpr::bench::register_benchmarks(plan, options, scratch.path());
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
  } catch (const std::exception& error) {
    std::cerr << "radarpr_benchmarks: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
