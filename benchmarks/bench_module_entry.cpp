// The benchmark module's entry point (bench_module.hpp): its build record and the run, which the
// program's `radarpr bench` finds by name. Compiled into the module only.
#include "benchmarks/bench_module.hpp"
#include "descriptors/plugins/plugin.hpp"

extern "C" RADARPR_PLUGIN_EXPORT const RadarprPluginAbi radarpr_bench_module_abi =
    radarpr::this_build_plugin_abi(RADARPR_VERSION_MINOR, RADARPR_PLUGIN_ABI);

extern "C" RADARPR_PLUGIN_EXPORT void radarpr_bench_module_run(
    const radarpr::bench::BenchRequest& request, radarpr::bench::BenchOutcome& outcome) {
  outcome = radarpr::bench::run_bench_request(request);
}
