// Which stages of an extraction the benchmarks time separately.
#include "benchmarks/descriptor_stages.hpp"

#include <gtest/gtest.h>

#include "benchmarks/bench_scans.hpp"
#include "descriptors/descriptor_registry.hpp"

namespace radarpr::bench {
namespace {

std::vector<Stage> stages_of(const std::string& id, const PolarImage& scan) {
  const DescriptorInstance instance = DescriptorRegistry::global().create_from_id(id);
  std::vector<Stage> stages;
  for (const TimedStage& stage : timed_stages(*instance.descriptor, scan)) {
    EXPECT_FALSE(stage.what.empty()) << id;
    EXPECT_NO_THROW(stage.run()) << id;
    stages.push_back(stage.stage);
  }
  return stages;
}

TEST(DescriptorStages, EachDescriptorExposesTheStagesItsCodeHas) {
  const PolarImage scan = synthetic_bench_image(1000, 0.0595238);
  const std::vector<Stage> features_then_descriptor{Stage::features, Stage::descriptor};
  EXPECT_EQ(stages_of("referee", scan), features_then_descriptor);
  EXPECT_EQ(stages_of("referee_a", scan), features_then_descriptor);
  EXPECT_EQ(stages_of("referee_r:kernel=box", scan), features_then_descriptor);
  EXPECT_EQ(stages_of("raplace", scan), std::vector<Stage>{Stage::preparation});
  // The spectra need no codebook, so an untrained open_radvlad times its preparation too.
  EXPECT_EQ(stages_of("open_radvlad", scan), std::vector<Stage>{Stage::preparation});
  EXPECT_TRUE(stages_of("radar_scan_context", scan).empty());
}

}  // namespace
}  // namespace radarpr::bench
