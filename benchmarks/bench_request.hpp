#pragma once
// What `radarpr bench` asks of the benchmarks, and what it gets back: the verb's parsed command
// line (cli/bench_command.cpp) handed to run_bench_request(), which the benchmark module runs
// (bench_module.hpp).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace radarpr::bench {

struct BenchRequest {
  std::string out = "results/bench";
  std::string filter;
  bool quick = false;
  std::optional<long long> repetitions;
  std::vector<std::string> descriptors;
  std::vector<long long> sizes;
  std::string data;  // empty: default_real_data_root()
  bool force = false;
  // The radarpr program whose whole-process start-up the benchmarks time; empty: not timed.
  std::filesystem::path cli_program;
};

struct BenchOutcome {
  int exit_code = 0;
  // Set (with exit code 2) when the command line asked for nothing the benchmarks can run; the
  // program prints it as a usage error of `radarpr bench`.
  std::string usage_error;
};

// Runs the benchmarks, writes REQUEST.out/bench.{json,md} and prints the speed targets; refuses a
// build that is not optimised unless forced (printed, exit code 2). Other failures throw.
BenchOutcome run_bench_request(const BenchRequest& request);

}  // namespace radarpr::bench
