// Loading a plugin must not change what the default retrieval benchmarks measure: they pick one
// descriptor per retrieval method by name, and plugin names sort among the built-ins.
#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "benchmarks/retrieval_benchmarks.hpp"
#include "descriptors/descriptor_registry.hpp"
#include "descriptors/plugins/plugin_loader.hpp"

namespace radarpr {
namespace {

bool contains(const std::vector<std::string>& ids, const std::string& id) {
  return std::find(ids.begin(), ids.end(), id) != ids.end();
}

TEST(PluginBenchmarks, DefaultRetrievalDescriptorsAreBuiltInsOnly) {
  // plugin_probe and range_histogram are kdtree descriptors whose names sort before referee,
  // the built-in that stands for kdtree: picked by name, they would replace it.
  load_descriptor_plugin(PROBE_PLUGIN_PATH);
  load_descriptor_plugin(RANGE_HISTOGRAM_TEST_PLUGIN_PATH);
  const std::vector<std::string> ids = bench::default_retrieval_descriptor_ids();
  EXPECT_TRUE(contains(ids, "referee"));
  for (const std::string& id : ids) {
    const DescriptorInstance instance = DescriptorRegistry::global().create_from_id(id);
    EXPECT_EQ(origin_of(DescriptorRegistry::global().info(instance.name)), "built-in") << id;
  }
}

TEST(PluginBenchmarks, APluginDescriptorNamedWithDescriptorIsBenchmarkedInRetrieval) {
  load_descriptor_plugin(PROBE_PLUGIN_PATH);
  const std::vector<std::string> ids =
      bench::retrieval_descriptor_ids({"plugin_probe", "referee:kernel=box"});
  // The defaults, then the plugin's descriptor; a built-in configuration adds nothing (its
  // method is covered by the defaults).
  EXPECT_EQ(std::vector<std::string>(ids.begin(), ids.end() - 1),
            bench::default_retrieval_descriptor_ids());
  EXPECT_EQ(ids.back(), "plugin_probe");

  // The probe keeps the default retrieval: exhaustive, correct for its own distance.
  bench::BenchPlan plan("^retrieval/exhaustive/plugin_probe/1000/", {});
  bench::RetrievalBenchOptions options;
  options.descriptor_ids = ids;
  options.database_sizes = {1000};
  bench::add_retrieval_benchmarks(plan, options);
  std::vector<std::string> names;
  for (const auto& bench : plan.cases()) names.push_back(bench.name);
  EXPECT_EQ(names, (std::vector<std::string>{"retrieval/exhaustive/plugin_probe/1000/multi",
                                             "retrieval/exhaustive/plugin_probe/1000/single"}));
}

}  // namespace
}  // namespace radarpr
