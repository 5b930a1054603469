#include "descriptors/referee/referee_r.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "tests/descriptors/feature_masks.hpp"

namespace radarpr {
namespace {

using test::features_from_rows;

// A = 4, R = 13. Features per bin: 0 -> 2 (rows 0, 3), 1 -> 1, 5 -> 2, 6 -> 1, 9 -> 1, 12 -> 1.
// Z_r = 4 - features: r = 0..12 -> 2 3 4 4 4 | 2 3 4 4 3 | 4 4 3.
PolarFeatures four_by_thirteen() {
  return features_from_rows(13, {{0, 5, 12}, {5, 6}, {}, {0, 1, 9}});
}

RefereeRParams with(int window, RefereeRBinning binning, bool normalize) {
  RefereeRParams params;
  params.window = window;
  params.binning = binning;
  params.normalize = normalize;
  return params;
}

TEST(RefereeRChunks, NearEqualChunksAndTheCppQuirk) {
  // chunks: n = floor(13 / 4) = 3, lengths 5, 4, 4.
  EXPECT_EQ(referee_r_chunks(13, 4, RefereeRBinning::chunks),
            (std::vector<RangeChunk>{{0, 5}, {5, 4}, {9, 4}}));
  // cpp_quirk, window 5: closes at r = 0, 5, 10 -> {0}, {1..5}, {6..10}; 11, 12 dropped.
  EXPECT_EQ(referee_r_chunks(13, 5, RefereeRBinning::cpp_quirk),
            (std::vector<RangeChunk>{{0, 1}, {1, 5}, {6, 5}}));

  // MulRan R = 3360: 42 chunks of 80 either way; the quirk's are {0}, then 41 of 80 ending at
  // 3280, so bins 3281..3359 (79) are dropped.
  const auto mulran = referee_r_chunks(3360, 80, RefereeRBinning::chunks);
  ASSERT_EQ(mulran.size(), 42u);
  EXPECT_EQ(mulran.back(), (RangeChunk{3280, 80}));
  const auto quirk = referee_r_chunks(3360, 80, RefereeRBinning::cpp_quirk);
  ASSERT_EQ(quirk.size(), 42u);
  EXPECT_EQ(quirk.front(), (RangeChunk{0, 1}));
  EXPECT_EQ(quirk.back(), (RangeChunk{3201, 80}));
  // Oxford R = 3768 = 47 * 80 + 8: 47 chunks, the first 8 of 81 bins; quirk 1 + 3767 / 80 = 48.
  const auto oxford = referee_r_chunks(3768, 80, RefereeRBinning::chunks);
  ASSERT_EQ(oxford.size(), 47u);
  EXPECT_EQ(oxford[7], (RangeChunk{7 * 81, 81}));
  EXPECT_EQ(oxford[8], (RangeChunk{8 * 81, 80}));
  EXPECT_EQ(referee_r_chunks(3768, 80, RefereeRBinning::cpp_quirk).size(), 48u);

  EXPECT_THROW(referee_r_chunks(79, 80, RefereeRBinning::chunks), std::invalid_argument);
  EXPECT_THROW(referee_r_chunks(100, 0, RefereeRBinning::cpp_quirk), std::invalid_argument);
}

TEST(RefereeRFromFeatures, RawCountsPerChunk) {
  // Chunks 0..4, 5..8, 9..12: 2+3+4+4+4 = 17, 2+3+4+4 = 13, 3+4+4+3 = 14.
  const DescriptorValue value =
      referee_r_from_features(four_by_thirteen(), with(4, RefereeRBinning::chunks, false));
  EXPECT_EQ(value.rows, 3);
  EXPECT_EQ(value.cols, 1);
  EXPECT_EQ(value.values, (std::vector<float>{17.0f, 13.0f, 14.0f}));
}

TEST(RefereeRFromFeatures, NormalisedCountsDivideByAzimuthsTimesChunkLength) {
  // 17 / (4 * 5) = 0.85, 13 / (4 * 4) = 0.8125, 14 / 16 = 0.875.
  const DescriptorValue value =
      referee_r_from_features(four_by_thirteen(), with(4, RefereeRBinning::chunks, true));
  ASSERT_EQ(value.values.size(), 3u);
  EXPECT_FLOAT_EQ(value.values[0], 0.85f);
  EXPECT_FLOAT_EQ(value.values[1], 0.8125f);
  EXPECT_FLOAT_EQ(value.values[2], 0.875f);
}

TEST(RefereeRFromFeatures, CppQuirkBinning) {
  // Window 5: {0} -> 2; {1..5} -> 3+4+4+4+2 = 17; {6..10} -> 3+4+4+3+4 = 18; 11, 12 dropped.
  EXPECT_EQ(referee_r_from_features(four_by_thirteen(), with(5, RefereeRBinning::cpp_quirk, false))
                .values,
            (std::vector<float>{2.0f, 17.0f, 18.0f}));
  // Normalised: 2 / (4 * 1) = 0.5, 17 / (4 * 5) = 0.85, 18 / 20 = 0.9.
  const DescriptorValue normalised =
      referee_r_from_features(four_by_thirteen(), with(5, RefereeRBinning::cpp_quirk, true));
  ASSERT_EQ(normalised.values.size(), 3u);
  EXPECT_FLOAT_EQ(normalised.values[0], 0.5f);
  EXPECT_FLOAT_EQ(normalised.values[1], 0.85f);
  EXPECT_FLOAT_EQ(normalised.values[2], 0.9f);
  // The same window with near-equal chunks: n = 2, lengths 7 and 6:
  // 2+3+4+4+4+2+3 = 22 and 4+4+3+4+4+3 = 22.
  EXPECT_EQ(
      referee_r_from_features(four_by_thirteen(), with(5, RefereeRBinning::chunks, false)).values,
      (std::vector<float>{22.0f, 22.0f}));
}

TEST(RefereeRFromFeatures, IgnoresTheAzimuthOrder) {
  const PolarFeatures turned = features_from_rows(13, {{0, 1, 9}, {0, 5, 12}, {5, 6}, {}});
  const RefereeRParams params = with(4, RefereeRBinning::chunks, false);
  EXPECT_EQ(referee_r_from_features(turned, params).values,
            referee_r_from_features(four_by_thirteen(), params).values);
}

TEST(RefereeRDescriptor, L2DistanceAndMetadata) {
  const RefereeRDescriptor descriptor(RefereeRParams{});
  EXPECT_TRUE(descriptor.rotation_invariant());
  const DescriptorValue a{2, 1, {3.0f, 4.0f}};
  const DescriptorValue zero{2, 1, {0.0f, 0.0f}};
  EXPECT_DOUBLE_EQ(descriptor.distance(a, zero), 5.0);
  EXPECT_EQ(descriptor.search_key(a), a.values);
  EXPECT_THROW(descriptor.distance(a, DescriptorValue{1, 1, {1.0f}}), std::invalid_argument);

  // 400 x 3360 scan without features: 42 chunks of 80 bins * 400 azimuths = 32000 free cells.
  PolarImage scan;
  scan.power = ByteImage(400, 3360, 9);
  const DescriptorValue value = descriptor.extract(scan);
  EXPECT_EQ(value.rows, 42);
  EXPECT_EQ(value.cols, 1);
  EXPECT_EQ(value.values, std::vector<float>(42, 32000.0f));
}

TEST(RefereeRDescriptor, CosineDistanceAndUnitSearchKeys) {
  RefereeRParams params;
  params.metric = RefereeRMetric::cosine;
  const RefereeRDescriptor descriptor(params);
  const DescriptorValue a{2, 1, {3.0f, 4.0f}};
  const DescriptorValue b{2, 1, {4.0f, 3.0f}};
  const DescriptorValue a_scaled{2, 1, {30.0f, 40.0f}};
  const DescriptorValue zero{2, 1, {0.0f, 0.0f}};
  // cos(a, b) = (12 + 12) / (5 * 5) = 0.96 -> 0.04; a and 10 a are parallel -> 0.
  EXPECT_NEAR(descriptor.distance(a, b), 0.04, 1e-12);
  EXPECT_NEAR(descriptor.distance(a, a_scaled), 0.0, 1e-12);
  // Keys a / |a| = (0.6, 0.8), b / |b| = (0.8, 0.6): 0.5 * |ka - kb|^2 = 0.5 * 0.08 = 0.04.
  const std::vector<float> key_a = descriptor.search_key(a);
  const std::vector<float> key_b = descriptor.search_key(b);
  EXPECT_FLOAT_EQ(key_a[0], 0.6f);
  EXPECT_FLOAT_EQ(key_a[1], 0.8f);
  EXPECT_FLOAT_EQ(key_b[0], 0.8f);
  // A zero vector keeps a zero key; distances stay finite and follow the key geometry:
  // 0.5 * |0 - ka|^2 = 0.5, and 0 between two zero vectors.
  EXPECT_EQ(descriptor.search_key(zero), (std::vector<float>{0.0f, 0.0f}));
  EXPECT_DOUBLE_EQ(descriptor.distance(zero, a), 0.5);
  EXPECT_DOUBLE_EQ(descriptor.distance(zero, zero), 0.0);
  EXPECT_THROW(descriptor.distance(a, DescriptorValue{3, 1, {1.0f, 1.0f, 1.0f}}),
               std::invalid_argument);
}

TEST(RefereeRDescriptor, RejectsScansShorterThanTheWindow) {
  const RefereeRDescriptor descriptor(RefereeRParams{});
  PolarImage scan;
  scan.power = ByteImage(400, 79, 0);  // 79 bins < window 80
  EXPECT_THROW(descriptor.extract(scan), std::invalid_argument);
  EXPECT_THROW(descriptor.extract(PolarImage{}), std::invalid_argument);
}

}  // namespace
}  // namespace radarpr
