#include "benchmarks/descriptor_stages.hpp"

#include <stdexcept>
#include <utility>

#include <benchmark/benchmark.h>

#include "descriptors/extraction_stages.hpp"

namespace radarpr::bench {
namespace {

std::invalid_argument bad_stage(const DescriptorInfo& info, const std::string& problem) {
  return std::invalid_argument("descriptor '" + info.name + "' (" + origin_of(info) +
                               ") declares " + problem + "; expected stages named '" +
                               std::string(kPreparationStage) + "', '" +
                               std::string(kFeaturesStage) + "', '" +
                               std::string(kDescriptorStage) + "', in that order, each once");
}

Stage stage_named(const DescriptorInfo& info, const std::string& name) {
  for (const Stage stage : {Stage::preparation, Stage::features, Stage::descriptor}) {
    if (name == to_string(stage)) return stage;
  }
  throw bad_stage(info, "a stage named '" + name + "'");
}

}  // namespace

std::vector<TimedStage> timed_stages(const DescriptorInfo& info, const Descriptor& descriptor,
                                     const PolarImage& scan) {
  if (!info.stages) return {};
  std::vector<TimedStage> timed;
  for (ExtractionStage& stage : info.stages(descriptor, scan)) {
    const Stage kind = stage_named(info, stage.name);
    if (!timed.empty() && kind <= timed.back().stage) {
      throw bad_stage(info, "the stage '" + stage.name + "' after '" +
                                std::string(to_string(timed.back().stage)) + "'");
    }
    if (!stage.run) throw bad_stage(info, "the stage '" + stage.name + "' without a function");
    // The stage's result is discarded inside run(); what it computes cannot be optimised away
    // because the work happens behind a call the compiler cannot see through.
    timed.push_back({kind, std::move(stage.what), [run = std::move(stage.run)] {
                       run();
                       benchmark::ClobberMemory();
                     }});
  }
  return timed;
}

}  // namespace radarpr::bench
