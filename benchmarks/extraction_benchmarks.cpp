#include "benchmarks/extraction_benchmarks.hpp"

#include <algorithm>
#include <cstdint>
#include <memory>

#include "benchmarks/descriptor_stages.hpp"
#include "benchmarks/speed_targets.hpp"
#include "datasets/synthetic/synthetic_sequence.hpp"
#include "descriptors/descriptor_registry.hpp"
#include "descriptors/precomputed/external_values.hpp"
#include "descriptors/vector_training_scans.hpp"

namespace radarpr::bench {
namespace {

// A trainable descriptor (a codebook) learns from 16 scans of the synthetic town first, as an
// experiment would from its database session; the benchmarks time extraction only.
DescriptorInstance ready_to_extract(DescriptorInstance instance) {
  if (!instance.descriptor->trainable()) return instance;
  SyntheticConfig config;
  config.scan_count = 16;
  config.radar.range_bin_count = 3360;
  const SyntheticSequence town(config);
  std::vector<PolarImage> scans;
  for (std::size_t i = 0; i < town.size(); ++i) scans.push_back(town.load_image(i));
  auto trained = instance.create_fresh();
  trained->train(VectorTrainingScans(std::move(scans), town.name()));
  instance.descriptor = std::move(trained);
  return instance;
}

// The floor: one plain pass over the scan's bytes, the least any extraction must do.
void sum_bytes(benchmark::State& state, const ByteImage& power) {
  std::uint64_t sum = 0;
  for (auto _ : state) {
    std::uint64_t total = 0;
    for (int a = 0; a < power.rows(); ++a) {
      const unsigned char* row = power.row(a);
      for (int r = 0; r < power.cols(); ++r) total += row[r];
    }
    sum += total;
    benchmark::DoNotOptimize(sum);
  }
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(power.size()));
}

void extract(benchmark::State& state, const Descriptor& descriptor, const PolarImage& scan) {
  DescriptorValue value;
  for (auto _ : state) {
    value = descriptor.extract(scan);
    benchmark::DoNotOptimize(value.values.data());
  }
  const DescriptorShape shape = descriptor.shape(geometry_of(scan));
  state.counters["elements"] = static_cast<double>(value.element_count());
  state.counters["payload_bytes"] = static_cast<double>(value.payload_bytes());
  state.counters["paper_bytes"] = static_cast<double>(shape.paper_bytes());
  state.SetItemsProcessed(state.iterations());
}

BenchCase scan_case(std::string name, CaseKind kind, const BenchScan& scan) {
  BenchCase bench;
  bench.name = std::move(name);
  bench.kind = kind;
  bench.scan = scan.label;
  return bench;
}

std::string stage_name(const std::string& prefix, const BenchScan& scan, Stage stage) {
  return "stage/" + prefix + scan.label + "/" + std::string(to_string(stage));
}

}  // namespace

std::vector<std::string> registered_descriptor_ids() {
  std::vector<std::string> ids;
  const DescriptorRegistry& registry = DescriptorRegistry::global();
  for (const DescriptorInfo* info : registry.all()) {
    // Values read from files (precomputed) have no extraction to time.
    if (external_values_of(*registry.create_from_id(info->name).descriptor)) continue;
    ids.push_back(info->name);
  }
  // The configurations the speed targets name (parity presets), unless already listed.
  for (const std::string& id : extraction_target_descriptor_ids()) {
    const std::string name = id.substr(0, id.find(':'));
    if (registry.contains(name) && std::find(ids.begin(), ids.end(), id) == ids.end()) {
      ids.push_back(id);
    }
  }
  return ids;
}

void add_extraction_benchmarks(BenchPlan& plan, const std::vector<BenchScan>& scans,
                               const std::vector<std::string>& descriptor_ids) {
  for (const BenchScan& scan : scans) {
    plan.add(
        scan_case("floor/" + scan.label, CaseKind::floor, scan),
        [&scan](benchmark::State& state) { sum_bytes(state, scan.image.power); }, false, true);
    plan.add(
        scan_case("png_decode/" + scan.label, CaseKind::png_decode, scan),
        [&scan](benchmark::State& state) {
          for (auto _ : state) {
            DecodedPolarPng decoded = read_polar_png(scan.png, scan.options);
            benchmark::DoNotOptimize(decoded.image.power.data());
          }
          state.SetItemsProcessed(state.iterations());
        },
        false, true);
  }
  std::vector<std::string> added;  // canonical ids: one configuration named twice is timed once
  for (const std::string& id : descriptor_ids) {
    DescriptorInstance instance = DescriptorRegistry::global().create_from_id(id);
    if (std::find(added.begin(), added.end(), instance.id) != added.end()) continue;
    added.push_back(instance.id);
    const DescriptorInfo& info = DescriptorRegistry::global().info(instance.name);
    const std::string prefix = instance.id + "/";
    bool any_wanted = false;
    for (const BenchScan& scan : scans) {
      any_wanted = any_wanted || plan.wanted("extract/" + prefix + scan.label);
      for (const Stage stage : {Stage::preparation, Stage::features, Stage::descriptor}) {
        any_wanted = any_wanted || plan.wanted(stage_name(prefix, scan, stage));
      }
    }
    if (!any_wanted) continue;  // spares the training of a filtered-out trainable descriptor
    std::shared_ptr<const Descriptor> descriptor = ready_to_extract(instance).descriptor;
    for (const BenchScan& scan : scans) {
      BenchCase whole = scan_case("extract/" + prefix + scan.label, CaseKind::extraction, scan);
      whole.descriptor = instance.id;
      plan.add(
          whole,
          [descriptor, &scan](benchmark::State& state) { extract(state, *descriptor, scan.image); },
          false, true);
      for (TimedStage& stage : timed_stages(info, *descriptor, scan.image)) {
        BenchCase part = scan_case(stage_name(prefix, scan, stage.stage), CaseKind::stage, scan);
        part.descriptor = instance.id;
        part.stage = stage.stage;
        part.what = stage.what;
        plan.add(
            part,
            [descriptor, run = std::move(stage.run)](benchmark::State& state) {
              for (auto _ : state) run();
            },
            false, true);
      }
    }
  }
}

}  // namespace radarpr::bench
