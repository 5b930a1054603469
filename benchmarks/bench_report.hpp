#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "benchmarks/bench_runner.hpp"

namespace radarpr::bench {

// One descriptor on one scan: where its extraction time goes, in seconds of one thread's CPU.
struct ExtractionRow {
  std::string descriptor;
  std::string scan;
  std::optional<double> png_decode;   // the scan's PNG (shared by every descriptor)
  std::optional<double> preparation;  // empty: the descriptor has no separate preparation
  std::optional<double> features;     // empty: no Cen 2018 features
  double descriptor_stage = 0.0;      // the rest of the extraction
  // descriptor_stage is the total minus the measured stages rather than timed on its own.
  bool descriptor_derived = false;
  std::string preparation_what;
  double total = 0.0;                    // the whole extraction, timed on its own
  std::optional<double> floor_multiple;  // total / the plain pass over the same scan
  double payload_bytes = 0.0;
  double paper_bytes = 0.0;
};

// One retrieval strategy on one synthetic database, in seconds of wall clock on every core.
struct RetrievalRow {
  std::string strategy;
  std::string descriptor;
  std::size_t dimension = 0;
  std::size_t database_size = 0;
  std::string session;
  std::optional<double> index_build;  // empty: the strategy builds no index
  double total = 0.0;                 // the whole search, all queries
  double per_query = 0.0;             // (total - index_build) / queries
  std::size_t queries_timed = 0;
  std::size_t queries_total = 0;
  bool extrapolated = false;  // total from a timed sample of the queries
  // exhaustive_l2: the timed search over a plain Eigen product of its shapes, per pair of values
  // (single session: the pairs of its queries' prefixes).
  std::optional<double> over_matrix_product;
  // Values memory-mapped from a file (over the memory budget): the process's peak resident
  // memory during the search, and the values' size.
  std::optional<double> peak_memory_bytes;
  std::optional<double> values_bytes;
};

// One whole radarpr process (startup_benchmarks.hpp), in seconds.
struct StartupRow {
  std::string command;     // as a user types it, e.g. "radarpr extract referee 400x3360.png"
  bool floor = false;      // the minimal program of startup_benchmarks.hpp, not radarpr
  std::string descriptor;  // the descriptor it extracts; empty for --version
  std::string scan;
  double wall = 0.0;         // start to exit, as the user waits
  double process_cpu = 0.0;  // the process's own CPU
  // The same work in a running process, one thread: the scan's PNG decode plus the extraction
  // (the minimal program: the PNG decode alone).
  std::optional<double> in_process;
  std::optional<double> over_in_process;  // wall / in_process
};

// A speed target (speed_targets.hpp) and how this run measured it.
struct TargetCheck {
  std::string part;  // "extraction", "retrieval" or "start-up"
  std::string target;
  std::string measured;     // empty when this run did not measure it
  std::optional<bool> met;  // empty: not measured, or not decidable from timings
};

std::vector<ExtractionRow> extraction_rows(const BenchRun& run);
std::vector<RetrievalRow> retrieval_rows(const BenchRun& run);
std::vector<StartupRow> startup_rows(const BenchRun& run);
std::vector<TargetCheck> check_targets(const BenchRun& run);

nlohmann::json report_json(const BenchRun& run);
std::string report_markdown(const BenchRun& run);

// Writes folder/bench.json and folder/bench.md (the folder is created). Throws
// std::runtime_error naming a file that cannot be written.
void write_report(const BenchRun& run, const std::filesystem::path& folder);

}  // namespace radarpr::bench
