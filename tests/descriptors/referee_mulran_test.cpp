// ReFeree descriptors on real MulRan KAIST03 scans (../shared/data/real/referee_mulran_kaist03).
#include <filesystem>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "descriptors/features/cen2018.hpp"
#include "descriptors/referee/referee_a.hpp"
#include "descriptors/referee/referee_r.hpp"
#include "tests/descriptors/mulran_frames.hpp"

namespace radarpr {
namespace {

using testing::native_frame;
using testing::read_native;

// The journal release's settings: box kernel, z_q = 3.
Cen2018Params journal_cen() {
  Cen2018Params params;
  params.kernel = CenKernel::box;
  params.z_q = 3.0;
  return params;
}

TEST(RefereeOnMulran, CenMaskHoldsAboutThreeThousandSixHundredFeatures) {
  SKIP_WITHOUT_FRAMES("000000");
  const PolarImage scan = read_native("000000");
  ASSERT_EQ(scan.azimuth_count(), 400);
  ASSERT_EQ(scan.range_bin_count(), 3360);
  const PolarFeatures features = extract_cen2018_features(scan, journal_cen());
  // descriptors.md: "about 3,600" with box, z_q = 3, min 58 (about 9 per azimuth).
  EXPECT_GT(features.feature_count(), 3000u);
  EXPECT_LT(features.feature_count(), 4200u);
  for (int a = 0; a < features.azimuth_count(); ++a) {
    for (const int r : features.azimuth(a)) ASSERT_GT(r, 58);
  }
}

TEST(RefereeOnMulran, RefereeRIsCloserToTheNextFrameThanToTheTenth) {
  SKIP_WITHOUT_FRAMES("000000", "000001", "000010");
  RefereeRParams params;
  params.cen = journal_cen();
  const RefereeRDescriptor referee_r(params);
  const DescriptorValue first = referee_r.extract(read_native("000000"));
  const DescriptorValue next = referee_r.extract(read_native("000001"));
  const DescriptorValue tenth = referee_r.extract(read_native("000010"));
  ASSERT_EQ(first.rows, 42);  // floor(3360 / 80)
  // 0.25 s apart vs 2.25 s apart while driving: the scene changes more in the second pair.
  EXPECT_LT(referee_r.distance(first, next), referee_r.distance(first, tenth));
}

TEST(RefereeOnMulran, RefereeAEstimatesTheYawOfARotatedScan) {
  SKIP_WITHOUT_FRAMES("000000");
  const PolarImage scan = read_native("000000");
  // Query row a = database row a + 40: 40 azimuths = 5 blocks of 8 -> yaw = 2 pi * 5 / 50.
  PolarImage turned = scan;
  turned.power = ByteImage(scan.power.rows(), scan.power.cols());
  for (int a = 0; a < 400; ++a)
    std::copy_n(scan.power.row((a + 40) % 400), scan.power.cols(), turned.power.row(a));
  RefereeAParams params;
  params.cen = journal_cen();
  const RefereeADescriptor referee_a(params);
  const auto yaw = referee_a.estimate_yaw(referee_a.extract(turned), referee_a.extract(scan));
  ASSERT_TRUE(yaw.has_value());
  EXPECT_NEAR(*yaw, 2.0 * std::numbers::pi * 5.0 / 50.0, 1e-9);
}

}  // namespace
}  // namespace radarpr
