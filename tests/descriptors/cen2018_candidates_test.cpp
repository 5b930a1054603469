// The Cen 2018 row pass computes the smoothed row p and the response y only at candidate bins
// (q above a bound derived from y <= q + sigma / sqrt(e) for q >= 0), and reads uint8 rows through
// integer sums. These tests hold both shortcuts to the full computation.
#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "datasets/byte_image.hpp"
#include "descriptors/features/cen2018.hpp"
#include "tests/descriptors/mulran_frames.hpp"

namespace radarpr {
namespace {

// The bytes of `power` as float32 values, row after row.
std::vector<float> as_floats(const ByteImage& power) {
  return std::vector<float>(power.data(), power.data() + power.size());
}

// Speckle-like rows: a noise floor in [0, noise) with returns of random height and width.
std::vector<float> speckle_row(int bins, int noise, std::uint32_t seed) {
  auto next = [&seed] {
    seed = seed * 1664525u + 1013904223u;
    return seed >> 8;
  };
  std::vector<float> row;
  for (int r = 0; r < bins; ++r) row.push_back(static_cast<float>(next() % noise));
  for (int target = 0; target < 12; ++target) {
    const int start = static_cast<int>(next() % static_cast<std::uint32_t>(bins));
    const int width = 1 + static_cast<int>(next() % 6);
    const float height = static_cast<float>(noise + next() % 200);
    for (int r = start; r < std::min(bins, start + width); ++r) {
      row[static_cast<std::size_t>(r)] = height;
    }
  }
  return row;
}

// The features as the spec defines them: runs of bins with y > z_q sigma over EVERY bin (the
// trace computes p and y everywhere), each giving its middle bin if beyond min_range_bins.
std::vector<int> features_from_all_responses(const Cen2018RowTrace& trace,
                                             const Cen2018Params& params) {
  std::vector<int> features;
  if (!trace.noise_sigma) return features;
  const double threshold = params.z_q * *trace.noise_sigma;
  const int count = static_cast<int>(trace.response.size());
  for (int r = 0; r < count;) {
    if (!(trace.response[static_cast<std::size_t>(r)] > threshold)) {
      ++r;
      continue;
    }
    int end = r;
    while (end < count && trace.response[static_cast<std::size_t>(end)] > threshold) ++end;
    const int bin = r + (end - r) / 2;
    if (bin > params.min_range_bins) features.push_back(bin);
    r = end;
  }
  return features;
}

// z_q values around 2 / sqrt(e) = 1.213, where the bound switches from q + 2 sigma / sqrt(e)
// (negative bins may pass) to q + sigma / sqrt(e).
TEST(Cen2018Candidates, SkippingNonCandidateBinsLosesNoFeature) {
  int passing_below_threshold = 0;  // features whose q lies under the threshold itself
  for (const double z_q : {0.0, 0.5, 1.0, 1.2, 1.25, 2.0, 3.0, 6.0}) {
    for (const CenKernel kernel : {CenKernel::gaussian, CenKernel::box}) {
      for (std::uint32_t seed = 1; seed <= 8; ++seed) {
        Cen2018Params params;
        params.z_q = z_q;
        params.kernel = kernel;
        params.min_range_bins = 0;
        const std::vector<float> row = speckle_row(1500, 30 + static_cast<int>(seed), seed);
        const Cen2018RowTrace trace = cen2018_row_trace(row, params);
        ASSERT_TRUE(trace.noise_sigma.has_value());
        const std::vector<int> expected = features_from_all_responses(trace, params);
        EXPECT_EQ(trace.features, expected) << "z_q " << z_q << " seed " << seed;
        for (std::size_t r = 0; r < row.size(); ++r) {
          if (trace.response[r] > z_q * *trace.noise_sigma &&
              trace.detrended[r] <= z_q * *trace.noise_sigma) {
            ++passing_below_threshold;
          }
        }
      }
    }
  }
  // Bins pass with q under the threshold, so a shortcut "q > threshold" would lose features:
  // the test would catch a bound that is too tight.
  EXPECT_GT(passing_below_threshold, 0);
}

// Hand-made: background 0 with one bin of 10 in R = 100 bins, box kernel (17 taps of 1/17).
// mean = 0.1, so q = -0.1 on the 99 background bins (sigma_a = 0.1) and q = 9.9 at the peak; p at
// the peak = (9.9 - 16 * 0.1) / 17 = 0.488. With G(x) = exp(-x^2 / 0.02): G(9.9 - 0.488) = 0 and
// G(0.488) = exp(-11.9) = 7e-6, so y = 9.9 - 0.488 * 7e-6 = 9.9 - 3e-6, i.e. 98.99997 sigma.
// The background bins next to it (q = -0.1) stay negative. z_q = 98.9: one feature at bin 40;
// z_q = 99.1: none.
TEST(Cen2018Candidates, ThresholdJustUnderAndOverTheOnlyReturn) {
  std::vector<float> row(100, 0.0f);
  row[40] = 10.0f;
  Cen2018Params params;
  params.kernel = CenKernel::box;
  params.min_range_bins = 0;
  params.z_q = 98.9;
  const Cen2018RowTrace trace = cen2018_row_trace(row, params);
  ASSERT_TRUE(trace.noise_sigma.has_value());
  EXPECT_NEAR(*trace.noise_sigma, 0.1, 1e-6);
  EXPECT_NEAR(trace.smoothed[40], (9.9 - 16 * 0.1) / 17.0, 1e-6);
  EXPECT_NEAR(trace.response[40], 9.9, 1e-5);
  EXPECT_EQ(trace.features, std::vector<int>{40});
  params.z_q = 99.1;
  EXPECT_TRUE(cen2018_row_trace(row, params).features.empty());
}

// uint8 rows take integer sums for the mean and sigma_a; the same values as float32 take the
// generic path. Exact in q, within double rounding in sigma_a: the features agree.
TEST(Cen2018Candidates, Uint8RowsGiveTheFeaturesOfTheSameValuesAsFloat) {
  ByteImage power(40, 2000);
  for (int a = 0; a < power.rows(); ++a) {
    const std::vector<float> row =
        speckle_row(power.cols(), 40, 100u + static_cast<std::uint32_t>(a));
    for (int r = 0; r < power.cols(); ++r) {
      power(a, r) = static_cast<unsigned char>(std::min(255.0f, row[r]));
    }
  }
  const std::vector<float> as_float = as_floats(power);
  for (const double z_q : {1.0, 3.0, 6.0}) {
    Cen2018Params params;
    params.z_q = z_q;
    const PolarFeatures features = extract_cen2018_features(power, params);
    EXPECT_GT(features.feature_count(), 0u);
    EXPECT_EQ(extract_cen2018_features(as_float, power.cols(), params), features) << "z_q " << z_q;
  }
}

// Rows longer than the 32768 bytes the integer sums take per chunk, and of odd lengths.
TEST(Cen2018Candidates, LongAndOddRowsGiveTheSameFeaturesAsUint8AndAsFloat) {
  for (const int bins : {101, 70001}) {
    ByteImage power(2, bins);
    for (int a = 0; a < power.rows(); ++a) {
      const std::vector<float> row = speckle_row(bins, 50, 7u + static_cast<std::uint32_t>(a));
      for (int r = 0; r < bins; ++r) {
        power(a, r) = static_cast<unsigned char>(std::min(255.0f, row[r]));
      }
    }
    Cen2018Params params;
    params.z_q = 3.0;
    params.min_range_bins = 0;
    const PolarFeatures features = extract_cen2018_features(power, params);
    EXPECT_GT(features.feature_count(), 0u) << bins;
    EXPECT_EQ(extract_cen2018_features(as_floats(power), bins, params), features) << bins;
  }
}

// A 30-bin row under the 103-tap Gaussian: the reflected border wraps more than once
// (scipy 'reflect': the edge sample repeated, applied again beyond the first reflection).
TEST(Cen2018Candidates, RowsShorterThanTheKernelReflectRepeatedly) {
  std::vector<float> row;
  for (int r = 0; r < 30; ++r) row.push_back(static_cast<float>((r * 7) % 11));
  const Cen2018Params params;
  const Cen2018RowTrace trace = cen2018_row_trace(row, params);
  const std::vector<float> taps = cen2018_kernel(params);
  const int radius = static_cast<int>(taps.size() / 2);
  // Index i of the row reflected about its edges, repeatedly: period 60, 30..59 run backwards.
  const auto reflected = [](int i) {
    const int folded = ((i % 60) + 60) % 60;
    return folded < 30 ? folded : 59 - folded;
  };
  for (int r = 0; r < 30; ++r) {
    double expected = 0.0;
    for (int k = -radius; k <= radius; ++k) {
      const int source = reflected(r + k);
      expected += taps[static_cast<std::size_t>(k + radius)] *
                  trace.detrended[static_cast<std::size_t>(source)];
    }
    EXPECT_NEAR(trace.smoothed[static_cast<std::size_t>(r)], expected, 1e-5) << r;
  }
}

TEST(Cen2018Candidates, RealMulranScanGivesTheSameFeaturesAsUint8AndAsFloat) {
  SKIP_WITHOUT_FRAMES("000000");
  const PolarImage scan = testing::read_native("000000");
  const ByteImage& power = scan.power;
  const std::vector<float> as_float = as_floats(power);
  for (const CenKernel kernel : {CenKernel::gaussian, CenKernel::box}) {
    Cen2018Params params;
    params.kernel = kernel;
    const PolarFeatures features = extract_cen2018_features(power, params);
    EXPECT_EQ(extract_cen2018_features(scan, params), features);
    // 1170 features (Gaussian) when this was written: a guard against an empty mask.
    EXPECT_GT(features.feature_count(), 800u);
    EXPECT_EQ(extract_cen2018_features(as_float, power.cols(), params), features);
  }
}

}  // namespace
}  // namespace radarpr
