#pragma once
// The benchmark module: the benchmarks and Google Benchmark as a shared library, which the
// `radarpr` program loads only when `radarpr bench` runs (cli/bench_command.cpp), so that no other
// radarpr process loads and relocates libbenchmark at its start. Built next to build/radarpr and
// installed under lib/radarpr/, like the OpenCV module
// (descriptors/opencv_module/opencv_module.hpp).
//
// Like the OpenCV module, it leaves radarpr's functions undefined and resolves them from the
// program (one registry, so a --plugin's descriptors are benchmarked too), and carries the plugin
// ABI record of its build: the program loads only a module of its own version, to the patch.
//
// Its two symbols (extern "C": unmangled, found by dlsym):
//   const RadarprPluginAbi radarpr_bench_module_abi;
//   void radarpr_bench_module_run(const BenchRequest&, BenchOutcome&);  // may throw
#include "benchmarks/bench_request.hpp"

#define RADARPR_BENCH_MODULE_ABI_SYMBOL "radarpr_bench_module_abi"
#define RADARPR_BENCH_MODULE_RUN_SYMBOL "radarpr_bench_module_run"

namespace radarpr::bench {

using BenchModuleRun = void (*)(const BenchRequest& request, BenchOutcome& outcome);

}  // namespace radarpr::bench
