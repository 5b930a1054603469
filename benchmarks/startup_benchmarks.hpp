#pragma once

#include <filesystem>
#include <vector>

#include "benchmarks/bench_plan.hpp"
#include "benchmarks/bench_scans.hpp"

namespace radarpr::bench {

// What a user waits for when radarpr runs once: the whole process of `program` (the radarpr
// command line) started, run and waited for, per iteration:
// - "startup/version": `radarpr --version`, loading the program and its libraries and no more;
// - "startup/extract/referee/SCAN": `radarpr extract referee SCAN.png`, one scan decoded and
//   described, printed to /dev/null;
// - "startup/floor/empty" and "startup/floor/png_decode/SCAN": the minimal program beside radarpr
//   (png_decode_floor.cpp) started with nothing to do, and decoding the same PNG: what any process
//   costs on this machine (left out, with the reason, where the program is not installed).
// Timed by wall clock; the counter process_cpu_seconds is the processes' own CPU per iteration.
// Nothing is registered when `program` is empty (a benchmark program without the command line).
void add_startup_benchmarks(BenchPlan& plan, const std::vector<BenchScan>& scans,
                            const std::filesystem::path& program);

}  // namespace radarpr::bench
