// The example plugin (descriptors/examples/range_histogram), built in the tree as a MODULE and
// loaded like any plugin: values worked out by hand on small scans.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "descriptors/descriptor_registry.hpp"
#include "descriptors/opencv_image.hpp"
#include "descriptors/plugins/plugin_loader.hpp"
#include "tests/descriptors/mulran_frames.hpp"

namespace radarpr {
namespace {

DescriptorInstance range_histogram(const nlohmann::json& parameters) {
  load_descriptor_plugin(RANGE_HISTOGRAM_TEST_PLUGIN_PATH);
  return DescriptorRegistry::global().create("range_histogram", parameters);
}

PolarImage scan_of(const cv::Mat& power) {
  PolarImage scan;
  scan.power = to_byte_image(power);
  scan.azimuths_rad = uniform_azimuths(power.rows);
  return scan;
}

// 2 azimuths x 4 range bins, threshold 10, 2 bands (bins 0-1 and 2-3):
//   row 0: 0 20 20 0  -> cells above 10 at bins 1, 2
//   row 1: 20 0 0 0   -> bin 0
// band 0 counts 2, band 1 counts 1, of 3 in all: [2/3, 1/3].
const cv::Mat kScan = (cv::Mat_<std::uint8_t>(2, 4) << 0, 20, 20, 0, 20, 0, 0, 0);

TEST(RangeHistogramPlugin, CountsTheReturnsAboveTheThresholdPerBand) {
  const auto instance = range_histogram({{"bands", 2}, {"threshold", 10}});
  EXPECT_EQ(instance.id, "range_histogram:bands=2,threshold=10");
  const DescriptorValue value = instance.descriptor->extract(scan_of(kScan));
  EXPECT_EQ(value.rows, 1);
  EXPECT_EQ(value.cols, 2);
  ASSERT_EQ(value.values.size(), 2u);
  EXPECT_FLOAT_EQ(value.values[0], 2.0f / 3.0f);
  EXPECT_FLOAT_EQ(value.values[1], 1.0f / 3.0f);
  EXPECT_EQ(instance.descriptor->shape({400, 3360, 0.06}), (DescriptorShape{1, 2}));
  EXPECT_TRUE(instance.descriptor->rotation_invariant());
  EXPECT_EQ(instance.descriptor->retrieval_method(), RetrievalMethod::kdtree);
}

TEST(RangeHistogramPlugin, IsRotationInvariant) {
  // Rolling the azimuths (rows) is a rotation of the radar: the same value.
  const auto instance = range_histogram({{"bands", 2}, {"threshold", 10}});
  cv::Mat rolled;
  cv::vconcat(kScan.row(1), kScan.row(0), rolled);
  EXPECT_EQ(instance.descriptor->extract(scan_of(rolled)).values,
            instance.descriptor->extract(scan_of(kScan)).values);
}

TEST(RangeHistogramPlugin, DistancesL2AndL1) {
  // [2/3, 1/3] against [1/3, 2/3]: L2 = sqrt(2 * (1/3)^2) = sqrt(2)/3, L1 = 2/3.
  const DescriptorValue a{1, 2, {2.0f / 3.0f, 1.0f / 3.0f}};
  const DescriptorValue b{1, 2, {1.0f / 3.0f, 2.0f / 3.0f}};
  const auto l2 = range_histogram({{"bands", 2}});
  EXPECT_NEAR(l2.descriptor->distance(a, b), std::sqrt(2.0) / 3.0, 1e-7);
  const auto l1 = range_histogram({{"bands", 2}, {"distance", "l1"}});
  EXPECT_NEAR(l1.descriptor->distance(a, b), 2.0 / 3.0, 1e-7);
  EXPECT_EQ(l1.descriptor->retrieval_method(), RetrievalMethod::exhaustive);
  EXPECT_THROW(l1.descriptor->distance(a, DescriptorValue{1, 1, {1.0f}}), std::invalid_argument);
}

TEST(RangeHistogramPlugin, AnEmptyScanGivesZerosNotNaN) {
  // Nothing above the threshold: no division by a zero total.
  const auto instance = range_histogram({{"bands", 2}, {"threshold", 200}});
  const DescriptorValue value = instance.descriptor->extract(scan_of(kScan));
  EXPECT_EQ(value.values, (std::vector<float>{0.0f, 0.0f}));
}

TEST(RangeHistogramPlugin, RefusesBadScansAndParameters) {
  const auto instance = range_histogram({{"bands", 8}});
  // 8 bands on 4 range bins.
  EXPECT_THROW(instance.descriptor->extract(scan_of(kScan)), std::invalid_argument);
  EXPECT_THROW(instance.descriptor->extract(scan_of(cv::Mat())), std::invalid_argument);
  EXPECT_THROW(range_histogram({{"bands", 0}}), ParameterError);
  EXPECT_THROW(range_histogram({{"distance", "cosine"}}), ParameterError);
}

TEST(RangeHistogramPlugin, RealMulRanScans) {
  SKIP_WITHOUT_FRAMES("000000", "000001", "000010");
  const auto instance = range_histogram(nlohmann::json::object());
  const PolarImage first = testing::read_native("000000");
  const DescriptorValue value = instance.descriptor->extract(first);
  ASSERT_EQ(value.values.size(), 10u);
  double total = 0.0;
  for (const float share : value.values) {
    EXPECT_TRUE(share >= 0.0f && share <= 1.0f) << share;
    total += share;
  }
  EXPECT_NEAR(total, 1.0, 1e-5);  // L1-normalised: a real scan has returns above 15
  // Rotating the scan by a quarter turn (rolling 100 of its 400 azimuth rows) changes nothing.
  PolarImage rotated = first;
  std::rotate_copy(first.power.data(), first.power.row(100),
                   first.power.data() + first.power.size(), rotated.power.data());
  EXPECT_EQ(instance.descriptor->extract(rotated).values, value.values);
  // The next scan (0.25 s later, the same place) is nearer than one 2.5 s later.
  const DescriptorValue next = instance.descriptor->extract(testing::read_native("000001"));
  const DescriptorValue later = instance.descriptor->extract(testing::read_native("000010"));
  EXPECT_LT(instance.descriptor->distance(value, next),
            instance.descriptor->distance(value, later));
}

}  // namespace
}  // namespace radarpr
