#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace radarpr::bench {

// What one registered benchmark measures, so that the report can put its time in the right
// table cell without parsing benchmark names.
enum class CaseKind {
  floor,           // one plain pass summing the scan's bytes
  png_decode,      // read_polar_png of the scan's file
  extraction,      // Descriptor::extract, whole
  stage,           // one stage of an extraction (BenchCase::stage)
  index_build,     // the query-independent part of a retrieval strategy
  retrieval,       // retrieve_nearest with k = 1
  matrix_product,  // a plain Eigen float product of a retrieval's shapes
  startup,         // a whole radarpr process, started and waited for
  process_floor,   // a whole minimal program (png_decode_floor.cpp), started and waited for
};

// The stages of an extraction, in order: the "PNG decode" stage is CaseKind::png_decode.
enum class Stage {
  preparation,  // what a descriptor does to the polar image before its own work
  features,     // Cen 2018 point features
  descriptor,   // the rest
};

std::string_view to_string(CaseKind kind);
std::string_view to_string(Stage stage);

struct BenchCase {
  std::string name;  // the Google Benchmark name
  CaseKind kind = CaseKind::floor;
  std::string
      scan;  // floor, png_decode, extraction, stage, startup, process_floor: the scan's label
  std::string descriptor;  // extraction, stage, index_build, retrieval, startup: descriptor id
  Stage stage = Stage::descriptor;
  std::string what;      // stage: what it covers, for the report
  std::string strategy;  // index_build, retrieval, matrix_product: the RetrievalMethod
  // retrieval: "multi" (every query against the whole database) or "single" (query i against
  // its eligible prefix 0..i-E of the same sequence).
  std::string session;
  std::size_t database_size = 0;
  std::size_t dimension = 0;      // floats per value
  std::size_t queries_timed = 0;  // queries per timed call
  // Queries of the whole search. Larger than queries_timed when the timed call searches a
  // sample of them: the report then extrapolates the total.
  std::size_t queries_total = 0;
  // Eligible database values summed over the timed queries (single session: the prefixes).
  std::size_t pairs_timed = 0;
  // Eligible values summed over all queries of the whole search.
  std::size_t pairs_total = 0;
};

// One benchmark's outcome: medians over its repetitions.
struct Measurement {
  double real_seconds = 0.0;  // wall time per iteration
  double cpu_seconds = 0.0;   // CPU time of the benchmark thread per iteration
  // Every repetition's times, to show the spread on a shared machine.
  std::vector<double> real_seconds_each;
  std::vector<double> cpu_seconds_each;
  std::size_t repetitions = 0;
  std::int64_t iterations = 0;             // per repetition (of the first)
  std::map<std::string, double> counters;  // user counters (of the first repetition)
  std::string error;                       // non-empty when the benchmark skipped with an error
};

struct CaseResult {
  BenchCase bench;
  Measurement measurement;
};

}  // namespace radarpr::bench
