// Extraction time per scan and descriptor size, for every descriptor in the registry at its
// defaults, on a synthetic scan of MulRan's geometry (400 azimuths x 3360 bins, 0.0595 m).
// Run: build/benchmarks/radarpr_extraction_benchmark [--benchmark_filter=referee_r]
#include <benchmark/benchmark.h>

#include "datasets/synthetic/synthetic_sequence.hpp"
#include "descriptors/descriptor_registry.hpp"
#include "descriptors/vector_training_scans.hpp"

namespace {

radarpr::SyntheticConfig mulran_sized_town(int scans) {
  radarpr::SyntheticConfig config;
  config.scan_count = scans;
  config.radar.range_bin_count = 3360;
  return config;
}

const radarpr::PolarImage& mulran_sized_scan() {
  static const radarpr::PolarImage image =
      radarpr::SyntheticSequence(mulran_sized_town(1)).load_image(0);
  return image;
}

// Trainable descriptors (a codebook) learn from 16 scans of the same synthetic town first; the
// benchmark times extraction only.
radarpr::DescriptorInstance ready_to_extract(radarpr::DescriptorInstance instance) {
  if (!instance.descriptor->trainable()) return instance;
  const radarpr::SyntheticSequence town(mulran_sized_town(16));
  std::vector<radarpr::PolarImage> scans;
  for (std::size_t i = 0; i < town.size(); ++i) scans.push_back(town.load_image(i));
  auto trained = instance.create_fresh();
  trained->train(radarpr::VectorTrainingScans(std::move(scans), town.name()));
  instance.descriptor = std::move(trained);
  return instance;
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
  const radarpr::DescriptorShape shape{value.rows, value.cols};
  state.counters["paper_bytes"] = static_cast<double>(shape.paper_bytes());
  state.SetItemsProcessed(state.iterations());
}

}  // namespace

int main(int argc, char** argv) {
  // One benchmark per registered descriptor, so a new descriptor is measured without edits here.
  for (const auto* info : radarpr::DescriptorRegistry::global().all()) {
    auto instance =
        ready_to_extract(radarpr::DescriptorRegistry::global().create_from_id(info->name));
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
