#pragma once

#include <string>
#include <vector>

#include "benchmarks/bench_plan.hpp"
#include "benchmarks/bench_scans.hpp"

namespace radarpr::bench {

// Every registered descriptor name (at its defaults), sorted, then the configurations the
// extraction speed targets name (speed_targets.hpp) whose descriptor is registered.
std::vector<std::string> registered_descriptor_ids();

// Per scan: the floor (a plain pass summing the bytes) and the PNG decode. Per descriptor id and
// scan: the whole extraction (counters: payload_bytes, paper_bytes, elements; scans per second as
// items_per_second) and each stage its registration declares (DescriptorInfo::stages). Trainable
// descriptors are trained first on 16 synthetic scans. `scans` must outlive the run.
void add_extraction_benchmarks(BenchPlan& plan, const std::vector<BenchScan>& scans,
                               const std::vector<std::string>& descriptor_ids);

}  // namespace radarpr::bench
