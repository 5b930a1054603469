#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "benchmarks/bench_case.hpp"
#include "benchmarks/bench_plan.hpp"
#include "benchmarks/bench_scans.hpp"
#include "benchmarks/machine_description.hpp"
#include "benchmarks/retrieval_benchmarks.hpp"

namespace radarpr::bench {

struct BenchOptions {
  // The shared real-data folder; scans missing from it are synthesised (prepare_bench_scans).
  std::filesystem::path real_data_root;
  std::string filter;  // regex over benchmark names; empty = all
  // Shorter runs: one repetition of 0.05 s, databases up to 10^4.
  bool quick = false;
  int repetitions = 0;                      // 0 = 3 (quick: 1)
  std::vector<std::string> descriptor_ids;  // extraction; empty = registered_descriptor_ids()
  RetrievalBenchOptions retrieval;
  // The radarpr command line whose whole-process start-up is timed (startup_benchmarks.hpp);
  // empty: not timed.
  std::filesystem::path cli_program;
};

// What a scan was, for the report (BenchScan without its pixels).
struct ScanSummary {
  std::string label;
  std::string radar;
  std::string source;
  bool real = false;
  int azimuths = 0;
  int range_bins = 0;
  std::uintmax_t png_bytes = 0;
};

// Everything a report needs from one run.
struct BenchRun {
  MachineDescription machine;
  bool quick = false;
  RunLength length;
  std::string filter;
  int threads = 0;  // retrieval's threads (default_thread_count(): --threads, else the processors)
  std::vector<ScanSummary> scans;
  std::vector<CaseResult> results;  // in run order
  std::vector<SkippedCase> skipped;
};

// The shared real-data folder: $RADARPR_BENCH_DATA when set, else ../shared/data/real next to
// the source tree this program was built from.
std::filesystem::path default_real_data_root();

// A fresh folder under the system's temporary folder, removed with everything in it on
// destruction: the synthetic scans' PNGs live there.
class ScratchFolder {
 public:
  ScratchFolder();
  ~ScratchFolder();
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// Registers the benchmarks `options` select (extraction, then retrieval) on `plan`, returning the
// scans the extraction benchmarks use (they must outlive the run).
std::vector<BenchScan> register_benchmarks(BenchPlan& plan, const BenchOptions& options,
                                           const std::filesystem::path& scratch_folder);

// Runs them in this process (progress on stdout, Google Benchmark's console table) and collects
// the medians. Call at most once per process: Google Benchmark's registry is global.
BenchRun run_benchmarks(const BenchOptions& options);

// The run length `options` ask for: quick 1 x 0.05 s, else 0.5 s repeated 5 times (one scan)
// or 3 times (retrieval), unless repetitions is set.
RunLength run_length(const BenchOptions& options);

}  // namespace radarpr::bench
