#pragma once

#include <functional>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "benchmarks/bench_case.hpp"

namespace radarpr::bench {

// How long and how often each benchmark runs; 0 leaves it to Google Benchmark's flags.
struct RunLength {
  double min_seconds = 0.5;  // per repetition (Google Benchmark's MinTime)
  int repetitions = 3;       // the report takes the median
  // Cheap benchmarks (one scan) repeat more: a median of more repetitions spread over time is
  // less at the mercy of a burst of load on a shared machine.
  int cheap_repetitions = 5;
};

// A benchmark the plan left out, and why (e.g. its data would not fit in memory).
struct SkippedCase {
  std::string name;
  std::string reason;
};

// The benchmarks of one run: registers each with Google Benchmark, remembers what it measures
// (BenchCase), and skips those the filter excludes before any of their setup is paid for.
class BenchPlan {
 public:
  // `filter` is an ECMAScript regex searched in benchmark names; empty = everything. Throws
  // std::invalid_argument for a malformed regex.
  BenchPlan(const std::string& filter, RunLength length);

  bool wanted(const std::string& name) const;
  // Registers `body` under bench.name unless the filter excludes it. `wall_clock`: time by wall
  // clock (multi-threaded work) rather than the benchmark thread's CPU time. `cheap`: repeated
  // RunLength::cheap_repetitions times. `repetitions` > 0: that many instead (a benchmark whose
  // setup or call takes minutes).
  void add(BenchCase bench, std::function<void(benchmark::State&)> body, bool wall_clock,
           bool cheap = false, int repetitions = 0);

  // Records a benchmark left out on purpose (when the filter wants it), for the report.
  void skip(const std::string& name, std::string reason);

  const std::vector<BenchCase>& cases() const { return cases_; }
  const std::vector<SkippedCase>& skipped() const { return skipped_; }
  const RunLength& length() const { return length_; }

 private:
  std::optional<std::regex> filter_;
  RunLength length_;
  std::vector<BenchCase> cases_;
  std::vector<SkippedCase> skipped_;
};

}  // namespace radarpr::bench
