// Extraction time per scan and descriptor size, for every descriptor in the registry at its
// defaults, on a synthetic scan of MulRan's geometry (400 azimuths x 3360 bins, 0.0595 m).
// Run: build/benchmarks/radarpr_extraction_benchmark [--benchmark_filter=referee_r]
#include <benchmark/benchmark.h>

#include "datasets/synthetic/synthetic_sequence.hpp"
#include "descriptors/descriptor_registry.hpp"

namespace {

const radarpr::PolarImage& mulran_sized_scan() {
  static const radarpr::PolarImage image = [] {
    radarpr::SyntheticConfig config;
    config.scan_count = 1;
    config.radar.range_bin_count = 3360;
    return radarpr::SyntheticSequence(config).load_image(0);
  }();
  return image;
}

void extract(benchmark::State& state, const radarpr::DescriptorInstance& instance) {
  const radarpr::PolarImage& image = mulran_sized_scan();
  radarpr::DescriptorValue value;
  for (auto _ : state) {
    value = instance.descriptor->extract(image);
    benchmark::DoNotOptimize(value.values.data());
  }
  state.counters["elements"] = static_cast<double>(value.element_count());
  state.counters["payload_bytes"] = static_cast<double>(value.payload_bytes());
  state.counters["paper_bytes"] = static_cast<double>(value.element_count() * 8 + 128);
  state.SetItemsProcessed(state.iterations());
}

}  // namespace

int main(int argc, char** argv) {
  // One benchmark per registered descriptor, so a new descriptor is measured without edits here.
  for (const auto* info : radarpr::DescriptorRegistry::global().all()) {
    auto instance = radarpr::DescriptorRegistry::global().create_from_id(info->name);
    benchmark::RegisterBenchmark(("extract/" + instance.id).c_str(), [instance](
                                                                         benchmark::State& state) {
      extract(state, instance);
    })->Unit(benchmark::kMillisecond);
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
