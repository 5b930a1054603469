// Which stages of an extraction the benchmarks time separately: what each descriptor declares
// next to its registration.
#include "benchmarks/descriptor_stages.hpp"

#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "benchmarks/bench_scans.hpp"
#include "descriptors/descriptor_registry.hpp"

namespace radarpr::bench {
namespace {

std::vector<Stage> stages_of(const std::string& id, const PolarImage& scan) {
  const DescriptorInstance instance = DescriptorRegistry::global().create_from_id(id);
  const DescriptorInfo& info = DescriptorRegistry::global().info(instance.name);
  std::vector<Stage> stages;
  for (const TimedStage& stage : timed_stages(info, *instance.descriptor, scan)) {
    EXPECT_FALSE(stage.what.empty()) << id;
    EXPECT_NO_THROW(stage.run()) << id;
    stages.push_back(stage.stage);
  }
  return stages;
}

TEST(DescriptorStages, EachDescriptorDeclaresTheStagesItsCodeHas) {
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

// A registration whose stages the report could not place is refused with its name, not timed
// under a wrong column.
TEST(DescriptorStages, UnknownOrOutOfOrderStagesAreRefusedNamingTheDescriptor) {
  const PolarImage scan = synthetic_bench_image(1000, 0.0595238);
  const DescriptorInstance instance = DescriptorRegistry::global().create_from_id("referee");
  DescriptorInfo info = DescriptorRegistry::global().info("referee");
  info.name = "made_up";
  const auto expect_refused = [&](std::vector<ExtractionStage> declared, const char* fragment) {
    info.stages = [declared](const Descriptor&, const PolarImage&) { return declared; };
    try {
      timed_stages(info, *instance.descriptor, scan);
      ADD_FAILURE() << "accepted: " << fragment;
    } catch (const std::invalid_argument& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find("descriptor 'made_up' (built-in)"), std::string::npos) << message;
      EXPECT_NE(message.find(fragment), std::string::npos) << message;
    }
  };
  const auto nothing = [] {};
  expect_refused({{"warm_up", "?", nothing}}, "a stage named 'warm_up'");
  expect_refused({{"descriptor", "?", nothing}, {"features", "?", nothing}},
                 "the stage 'features' after 'descriptor'");
  expect_refused({{"features", "?", {}}}, "the stage 'features' without a function");
}

}  // namespace
}  // namespace radarpr::bench
