#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "descriptors/descriptor_registry.hpp"
#include "descriptors/referee/referee.hpp"
#include "descriptors/referee/referee_a.hpp"
#include "descriptors/referee/referee_r.hpp"

namespace radarpr {
namespace {

std::vector<std::string> names(const DescriptorInfo& info) {
  std::vector<std::string> result;
  for (const ParameterSpec& spec : info.parameters) result.push_back(spec.name);
  std::sort(result.begin(), result.end());  // the registry may keep its own order
  return result;
}

const std::vector<std::string> kCenNames = {"detrend",          "kernel", "sigma",
                                            "sigma_convention", "z_q",    "min_range_bins"};

std::vector<std::string> concat(std::vector<std::string> own) {
  own.insert(own.end(), kCenNames.begin(), kCenNames.end());
  std::sort(own.begin(), own.end());
  return own;
}

// Also the proof that registration survives static linking: this program links the descriptors
// library statically and references none of the three directly.
TEST(RefereeRegistration, AllThreeAreRegisteredWithTheSharedCenParameters) {
  const DescriptorRegistry& registry = DescriptorRegistry::global();
  EXPECT_EQ(names(registry.info("referee")), concat({"alpha"}));
  EXPECT_EQ(names(registry.info("referee_a")), concat({"alpha"}));
  EXPECT_EQ(names(registry.info("referee_r")),
            concat({"window", "normalize", "binning", "metric"}));
}

TEST(RefereeRegistration, DefaultsFollowTheSpecification) {
  const DescriptorInstance referee =
      DescriptorRegistry::global().create("referee", nlohmann::json::object());
  EXPECT_EQ(referee.id, "referee");
  EXPECT_EQ(referee.parameters.integer("alpha"), 50);
  EXPECT_EQ(referee.parameters.choice("detrend"), "row_mean");
  EXPECT_EQ(referee.parameters.choice("kernel"), "gaussian");
  EXPECT_EQ(referee.parameters.number("sigma"), 17.0);
  EXPECT_EQ(referee.parameters.choice("sigma_convention"), "negative_rms");
  EXPECT_EQ(referee.parameters.number("z_q"), 6.0);
  EXPECT_EQ(referee.parameters.integer("min_range_bins"), 58);
  EXPECT_FALSE(referee.descriptor->rotation_invariant());

  const DescriptorInstance referee_r =
      DescriptorRegistry::global().create("referee_r", nlohmann::json::object());
  EXPECT_EQ(referee_r.parameters.integer("window"), 80);
  EXPECT_FALSE(referee_r.parameters.boolean("normalize"));
  EXPECT_EQ(referee_r.parameters.choice("binning"), "chunks");
  EXPECT_EQ(referee_r.parameters.choice("metric"), "l2");
  EXPECT_TRUE(referee_r.descriptor->rotation_invariant());

  EXPECT_FALSE(DescriptorRegistry::global()
                   .create("referee_a", nlohmann::json::object())
                   .descriptor->rotation_invariant());
}

TEST(RefereeRegistration, ParametersReachTheDescriptor) {
  const DescriptorInstance instance = DescriptorRegistry::global().create(
      "referee_r", nlohmann::json{{"metric", "cosine"}, {"kernel", "box"}, {"z_q", 3}});
  EXPECT_EQ(instance.id, "referee_r:kernel=box,metric=cosine,z_q=3");
  const auto* referee_r = dynamic_cast<const RefereeRDescriptor*>(instance.descriptor.get());
  ASSERT_NE(referee_r, nullptr);
  EXPECT_EQ(referee_r->params().metric, RefereeRMetric::cosine);
  EXPECT_EQ(referee_r->params().cen.kernel, CenKernel::box);
  EXPECT_EQ(referee_r->params().cen.z_q, 3.0);
  // Cosine: (3, 4) vs (4, 3) -> 1 - 24 / 25 = 0.04.
  EXPECT_NEAR(instance.descriptor->distance(DescriptorValue{2, 1, {3.0f, 4.0f}},
                                            DescriptorValue{2, 1, {4.0f, 3.0f}}),
              0.04, 1e-12);

  const DescriptorInstance referee = DescriptorRegistry::global().create_from_id(
      "referee:alpha=25,sigma_convention=negative_rms_x2,detrend=median,min_range_bins=10");
  const auto* typed = dynamic_cast<const RefereeDescriptor*>(referee.descriptor.get());
  ASSERT_NE(typed, nullptr);
  EXPECT_EQ(typed->params().alpha, 25);
  EXPECT_EQ(typed->params().cen.sigma_convention, CenSigmaConvention::negative_rms_x2);
  EXPECT_EQ(typed->params().cen.detrend, CenDetrend::median);
  EXPECT_EQ(typed->params().cen.min_range_bins, 10);

  EXPECT_THROW(DescriptorRegistry::global().create("referee", nlohmann::json{{"kernel", "tri"}}),
               ParameterError);
  EXPECT_THROW(DescriptorRegistry::global().create("referee_a", nlohmann::json{{"alpha", 0}}),
               ParameterError);
}

}  // namespace
}  // namespace radarpr
