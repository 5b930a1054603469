// The synthetic descriptor values of the retrieval benchmarks: a drive, not noise.
#include "benchmarks/drive_values.hpp"

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

namespace radarpr::bench {
namespace {

double distance(const DescriptorValue& a, const DescriptorValue& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.values.size(); ++i) {
    const double d = static_cast<double>(a.values[i]) - b.values[i];
    sum += d * d;
  }
  return std::sqrt(sum);
}

TEST(DriveValues, ShapeAndDeterminism) {
  DriveValuesSpec spec;
  spec.count = 200;
  spec.rows = 20;
  spec.cols = 18;
  const std::vector<DescriptorValue> values = drive_values(spec);
  ASSERT_EQ(values.size(), 200u);
  for (const DescriptorValue& value : values) {
    EXPECT_EQ(value.rows, 20);
    EXPECT_EQ(value.cols, 18);
    ASSERT_EQ(value.values.size(), 360u);
    for (const float v : value.values) ASSERT_TRUE(std::isfinite(v));
  }
  const std::vector<DescriptorValue> again = drive_values(spec);
  for (std::size_t i = 0; i < values.size(); ++i) EXPECT_EQ(values[i].values, again[i].values);
}

// 4 laps of 1000 scans: scan i and i + 250 are the same place one lap apart.
TEST(DriveValues, RevisitsComeBackNearTheFirstVisit) {
  DriveValuesSpec spec;
  spec.count = 1000;
  const std::vector<DescriptorValue> values = drive_values(spec);
  int revisit_nearer = 0;
  for (std::size_t i = 0; i < 250; i += 10) {
    const double revisit = distance(values[i], values[i + 250]);
    const double elsewhere = distance(values[i], values[i + 125]);  // half a lap away
    if (revisit < elsewhere) ++revisit_nearer;
    // Consecutive scans are close: the path is smooth.
    EXPECT_LT(distance(values[i], values[i + 1]), elsewhere) << i;
  }
  EXPECT_EQ(revisit_nearer, 25);
}

TEST(DriveValues, SessionsShareTheRouteButNotTheNoise) {
  DriveValuesSpec spec;
  spec.count = 400;
  const std::vector<DescriptorValue> first = drive_values(spec);
  spec.session = 1;
  const std::vector<DescriptorValue> second = drive_values(spec);
  EXPECT_NE(first[10].values, second[10].values);
  EXPECT_LT(distance(first[10], second[10]), distance(first[10], second[60]));
}

TEST(DriveValues, RejectsAnEmptySpec) {
  DriveValuesSpec spec;
  spec.count = 0;
  EXPECT_THROW(drive_values(spec), std::invalid_argument);
  spec.count = 10;
  spec.laps = 0;
  EXPECT_THROW(drive_values(spec), std::invalid_argument);
}

}  // namespace
}  // namespace radarpr::bench
