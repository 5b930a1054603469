// The speed targets are data: each names a configuration the benchmarks measure under that very
// name, or the report would say "not measured" forever.
#include "benchmarks/speed_targets.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "benchmarks/extraction_benchmarks.hpp"
#include "descriptors/descriptor_registry.hpp"

namespace radarpr::bench {
namespace {

TEST(SpeedTargets, NameCanonicalIdsOfRegisteredDescriptors) {
  const DescriptorRegistry& registry = DescriptorRegistry::global();
  for (const SpeedTarget& target : speed_targets()) {
    EXPECT_TRUE(target.part == "extraction" || target.part == "retrieval" ||
                target.part == "start-up")
        << target.wording;
    std::string id(target.descriptor);
    if (id.empty() && target.part == "start-up") continue;  // `radarpr --version`
    if (id.ends_with('*')) {
      id.pop_back();
      EXPECT_TRUE(registry.contains(id)) << target.wording;
      continue;
    }
    EXPECT_EQ(registry.create_from_id(id).id, id) << target.wording;
    if (target.part == "retrieval") {
      EXPECT_TRUE(target.where == "single" || target.where == "multi") << target.wording;
    }
  }
}

TEST(SpeedTargets, TheDefaultExtractionRunMeasuresEveryConfigurationTheyName) {
  const std::vector<std::string> measured = registered_descriptor_ids();
  for (const std::string& id : extraction_target_descriptor_ids()) {
    EXPECT_NE(std::find(measured.begin(), measured.end(), id), measured.end()) << id;
  }
}

}  // namespace
}  // namespace radarpr::bench
