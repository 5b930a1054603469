// The example ReFeree variant (descriptors/examples/referee_nearest), built in the tree as a
// MODULE against radarpr_plugin_api and loaded like any plugin: the Cen 2018 extractor and the
// ReFeree helpers it reuses come from the program that loads it, and its values equal the
// variant's rule worked out here from the same features.
#include <cstdint>
#include <stdexcept>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "descriptors/descriptor_registry.hpp"
#include "descriptors/extraction_stages.hpp"
#include "descriptors/features/cen2018.hpp"
#include "descriptors/opencv_image.hpp"
#include "descriptors/plugins/plugin_loader.hpp"
#include "tests/descriptors/mulran_frames.hpp"

namespace radarpr {
namespace {

DescriptorInstance referee_nearest(const nlohmann::json& parameters) {
  load_descriptor_plugin(REFEREE_NEAREST_TEST_PLUGIN_PATH);
  return DescriptorRegistry::global().create("referee_nearest", parameters);
}

// 120 azimuths x 600 range bins of noise, with two bright returns per azimuth: a near one at a
// range that sweeps with the azimuth, and a far one at bin 500. Every seventh azimuth has none.
PolarImage swept_scan() {
  cv::Mat power(120, 600, CV_8UC1);
  cv::RNG noise(11);
  noise.fill(power, cv::RNG::UNIFORM, 0, 30);
  for (int a = 0; a < power.rows; ++a) {
    if (a % 7 == 0) continue;
    const int peak = 100 + 3 * a;
    for (int r = peak; r < peak + 8; ++r) power.at<std::uint8_t>(a, r) = 250;
    for (int r = 500; r < 508; ++r) power.at<std::uint8_t>(a, r) = 250;
  }
  PolarImage scan;
  scan.power = to_byte_image(power);
  scan.azimuths_rad = uniform_azimuths(power.rows);
  scan.range_resolution_m = 0.06;
  return scan;
}

// The variant's rule, written out: per block of azimuths (the first count % alpha blocks one
// longer), the mean over its azimuths of (bins before the nearest feature) / R.
std::vector<float> nearest_profile(const PolarFeatures& features, int alpha) {
  const int count = features.azimuth_count();
  const double bins = features.range_bin_count();
  std::vector<float> profile;
  int start = 0;
  for (int block = 0; block < alpha; ++block) {
    const int length = count / alpha + (block < count % alpha ? 1 : 0);
    double sum = 0.0;
    for (int a = start; a < start + length; ++a) {
      const auto nearest = features.azimuth(a);
      sum += nearest.empty() ? 0.0 : nearest.front();
    }
    profile.push_back(static_cast<float>(sum / (length * bins)));
    start += length;
  }
  return profile;
}

void expect_near_all(const std::vector<float>& actual, const std::vector<float>& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t i = 0; i < actual.size(); ++i) {
    EXPECT_NEAR(actual[i], expected[i], 1e-6) << "block " << i;
  }
}

TEST(RefereeNearestPlugin, IsTheNearestFeatureProfileOfRadarprsCenFeatures) {
  const auto instance = referee_nearest({{"alpha", 16}, {"z_q", 3}});
  EXPECT_EQ(instance.id, "referee_nearest:alpha=16,z_q=3");
  const PolarImage scan = swept_scan();
  Cen2018Params cen;
  cen.z_q = 3.0;
  const PolarFeatures features = extract_cen2018_features(scan, cen);
  ASSERT_GT(features.feature_count(), 0u);
  const DescriptorValue value = instance.descriptor->extract(scan);
  EXPECT_EQ(value.rows, 16);
  EXPECT_EQ(value.cols, 1);
  expect_near_all(value.values, nearest_profile(features, 16));
  EXPECT_EQ(instance.descriptor->shape({120, 600, 0.06}), (DescriptorShape{16, 1}));
  // Not the built-in ReFeree (farthest feature) on the same scan: the rule is its own.
  const auto referee =
      DescriptorRegistry::global().create("referee", nlohmann::json{{"alpha", 16}, {"z_q", 3}});
  EXPECT_NE(referee.descriptor->extract(scan).values, value.values);
}

TEST(RefereeNearestPlugin, SharesReFereesParametersAndStages) {
  const auto instance = referee_nearest(nlohmann::json::object());
  const DescriptorInfo& info = DescriptorRegistry::global().info("referee_nearest");
  const DescriptorInfo& referee = DescriptorRegistry::global().info("referee");
  ASSERT_EQ(info.parameters.size(), referee.parameters.size());
  for (std::size_t i = 0; i < info.parameters.size(); ++i) {
    EXPECT_EQ(info.parameters[i].name, referee.parameters[i].name);
  }
  // Two timed stages, as for referee: the features, then the profile.
  ASSERT_TRUE(info.stages);
  const PolarImage scan = swept_scan();
  const auto stages = info.stages(*instance.descriptor, scan);
  ASSERT_EQ(stages.size(), 2u);
  EXPECT_EQ(stages[0].name, kFeaturesStage);
  EXPECT_EQ(stages[1].name, kDescriptorStage);
  for (const auto& stage : stages) EXPECT_NO_THROW(stage.run());
  EXPECT_EQ(instance.descriptor->retrieval_method(), RetrievalMethod::kdtree);
  EXPECT_FALSE(instance.descriptor->rotation_invariant());
}

TEST(RefereeNearestPlugin, RefusesBadScansAndParameters) {
  const auto instance = referee_nearest(nlohmann::json::object());
  PolarImage empty;
  EXPECT_THROW(instance.descriptor->extract(empty), std::invalid_argument);
  EXPECT_THROW(referee_nearest({{"alpha", 0}}), ParameterError);
  EXPECT_THROW(referee_nearest({{"kernel", "triangle"}}), ParameterError);
  const DescriptorValue a{16, 1, std::vector<float>(16, 0.0f)};
  const DescriptorValue b{8, 1, std::vector<float>(8, 0.0f)};
  EXPECT_THROW(instance.descriptor->distance(a, b), std::invalid_argument);
}

TEST(RefereeNearestPlugin, RealMulRanScans) {
  SKIP_WITHOUT_FRAMES("000000", "000001", "000010");
  const auto instance = referee_nearest(nlohmann::json::object());
  const PolarImage first = testing::read_native("000000");
  const DescriptorValue value = instance.descriptor->extract(first);
  expect_near_all(value.values, nearest_profile(extract_cen2018_features(first, {}), 50));
  for (const float share : value.values) EXPECT_TRUE(share >= 0.0f && share <= 1.0f) << share;
}

}  // namespace
}  // namespace radarpr
