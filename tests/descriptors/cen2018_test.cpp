#include "descriptors/features/cen2018.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "datasets/byte_image.hpp"

namespace radarpr {
namespace {

// A row of `bins` at `background` with the inclusive runs [first, last] raised to `height`.
std::vector<float> row_with_runs(int bins, float background,
                                 const std::vector<std::pair<int, int>>& runs, float height) {
  std::vector<float> row(static_cast<std::size_t>(bins), background);
  for (const auto& [first, last] : runs) {
    for (int r = first; r <= last; ++r) row[static_cast<std::size_t>(r)] = height;
  }
  return row;
}

// Deterministic speckle-like row: uniform noise in [0, 40) plus a few strong returns.
std::vector<float> noisy_row(int bins, std::uint32_t seed) {
  std::vector<float> row;
  for (int r = 0; r < bins; ++r) {
    seed = seed * 1664525u + 1013904223u;
    row.push_back(static_cast<float>((seed >> 8) % 40));
  }
  for (const int r : {90, 91, 92, 150, 300, 301, 600, 777, 778, 779, 780}) {
    if (r < bins) row[static_cast<std::size_t>(r)] = 200.0f;
  }
  return row;
}

// Background 10 with 9 bins at 250 in R = 400: mean = 10 + 240 * 9 / 400 = 15.4, so every
// background bin has q = -5.4 (sigma_a = 5.4, threshold 6 * 5.4 = 32.4) and every raised bin
// q = 234.6. Raised bins: p stays far below q (at most 4 taps of ~0.0235 on the raised level),
// so G(q - p) ~ 0 and y ~ q - p G(p) ~ 234 > 32.4. Background bins: q < 0 and, when p >= 0,
// G(q - p) <= G(p), so both terms of y are <= 0: never candidates.
TEST(Cen2018Row, OneFeatureAtTheMiddleOfEveryRunBeyondTheMinimumRange) {
  const auto row =
      row_with_runs(400, 10.0f, {{58, 58}, {150, 150}, {200, 203}, {300, 302}}, 250.0f);
  // [58] -> 58, not > 58: dropped. [150] -> 150. [200, 203]: L = 4 -> 200 + 2 = 202.
  // [300, 302]: L = 3 -> 300 + 1 = 301.
  EXPECT_EQ(cen2018_row_features(row, Cen2018Params{}), (std::vector<int>{150, 202, 301}));

  const Cen2018RowTrace trace = cen2018_row_trace(row, Cen2018Params{});
  ASSERT_TRUE(trace.noise_sigma.has_value());
  EXPECT_NEAR(*trace.noise_sigma, 5.4, 1e-4);
  EXPECT_NEAR(trace.detrended[0], -5.4, 1e-4);
  EXPECT_NEAR(trace.detrended[150], 234.6, 1e-4);
  EXPECT_EQ(trace.features, (std::vector<int>{150, 202, 301}));
}

TEST(Cen2018Row, MinimumRangeCutAppliesToTheFeaturePositionNotTheRun) {
  const Cen2018Params params;  // min_range_bins = 58
  // A lone bin at 59 > 58 is kept.
  EXPECT_EQ(cen2018_row_features(row_with_runs(400, 10.0f, {{59, 59}}, 250.0f), params),
            std::vector<int>{59});
  // Run [56, 61]: L = 6 -> 56 + 3 = 59 > 58, kept although the run starts before the cut.
  EXPECT_EQ(cen2018_row_features(row_with_runs(400, 10.0f, {{56, 61}}, 250.0f), params),
            std::vector<int>{59});
  // Run [54, 59]: L = 6 -> 54 + 3 = 57 <= 58, dropped although the run reaches past the cut.
  EXPECT_TRUE(cen2018_row_features(row_with_runs(400, 10.0f, {{54, 59}}, 250.0f), params).empty());
  // With min_range_bins = 56 the same run's feature 57 survives.
  Cen2018Params near = params;
  near.min_range_bins = 56;
  EXPECT_EQ(cen2018_row_features(row_with_runs(400, 10.0f, {{54, 59}}, 250.0f), near),
            std::vector<int>{57});
}

TEST(Cen2018Row, EvenRunsTakeTheUpperMiddleBin) {
  // L = 2 -> r0 + 1; L = 8 -> r0 + 4.
  const auto row = row_with_runs(400, 10.0f, {{100, 101}, {250, 257}}, 250.0f);
  EXPECT_EQ(cen2018_row_features(row, Cen2018Params{}), (std::vector<int>{101, 254}));
}

TEST(Cen2018Row, ConstantRowHasNoNegativeBinSoNoFeatureAndNoNan) {
  const std::vector<float> row(400, 37.0f);  // mean 37 -> q = 0 everywhere, sigma_a undefined
  for (const CenKernel kernel : {CenKernel::gaussian, CenKernel::box}) {
    Cen2018Params params;
    params.kernel = kernel;
    params.z_q = 0.0;  // even a zero threshold finds nothing
    const Cen2018RowTrace trace = cen2018_row_trace(row, params);
    EXPECT_FALSE(trace.noise_sigma.has_value());
    EXPECT_TRUE(trace.features.empty());
    for (std::size_t r = 0; r < row.size(); ++r) {
      ASSERT_TRUE(std::isfinite(trace.smoothed[r]) && std::isfinite(trace.response[r])) << r;
      EXPECT_EQ(trace.response[r], 0.0);
    }
    EXPECT_TRUE(cen2018_row_features(row, params).empty());
  }
}

// Scale invariance on one row: 0..255 values and the same values /255 (the uint8 image path is
// checked by Cen2018Image below).
TEST(Cen2018Row, SameFeaturesForByteRangeAndUnitScaledValues) {
  const std::vector<float> row = noisy_row(1000, 7u);
  std::vector<float> scaled;
  for (const float v : row) scaled.push_back(v / 255.0f);
  for (const CenKernel kernel : {CenKernel::gaussian, CenKernel::box}) {
    Cen2018Params params;
    params.kernel = kernel;
    params.z_q = 3.0;
    const std::vector<int> features = cen2018_row_features(row, params);
    ASSERT_FALSE(features.empty());  // the strong returns are found
    EXPECT_EQ(cen2018_row_features(scaled, params), features);
  }
}

TEST(Cen2018Image, Uint8AndScaledFloatImagesGiveTheSameFeatures) {
  ByteImage power(6, 1000);
  for (int a = 0; a < power.rows(); ++a) {
    const std::vector<float> row = noisy_row(1000, 100u + static_cast<std::uint32_t>(a));
    for (int r = 0; r < power.cols(); ++r) power(a, r) = static_cast<unsigned char>(row[r]);
  }
  std::vector<float> scaled;
  for (std::size_t i = 0; i < power.size(); ++i) {
    scaled.push_back(static_cast<float>(power.data()[i] * (1.0 / 255.0)));
  }
  Cen2018Params params;
  params.z_q = 3.0;
  const PolarFeatures features = extract_cen2018_features(power, params);
  EXPECT_GT(features.feature_count(), 0u);
  EXPECT_EQ(extract_cen2018_features(scaled, power.cols(), params), features);
  // The scan version works row by row: every row alone gives the same bins.
  for (int a = 0; a < power.rows(); ++a) {
    const std::vector<float> row(power.row(a), power.row(a) + power.cols());
    const auto bins = features.azimuth(a);
    EXPECT_EQ(cen2018_row_features(row, params), std::vector<int>(bins.begin(), bins.end())) << a;
  }
}

// One bin at 250 in 400 bins of 10: mean 10.6, background q = -0.6 (sigma_a = 0.6), peak
// q = 239.4. The smoothed peak p ~ 0.0235 * 240 - 0.6 ~ 5.0, so G(q - p) and G(p) vanish and
// y ~ 239.4 for both conventions. negative_rms: candidate while z_q * 0.6 < 239.4 (z_q < 399);
// negative_rms_x2: sigma_a = 0.6 * sqrt(2) = 0.8485, candidate while z_q < 239.4 / 0.8485 = 282.
TEST(Cen2018Row, SigmaConventionScalesTheThresholdBySqrtTwo) {
  const auto row = row_with_runs(400, 10.0f, {{200, 200}}, 250.0f);
  Cen2018Params rms;
  Cen2018Params rms_x2;
  rms_x2.sigma_convention = CenSigmaConvention::negative_rms_x2;

  EXPECT_NEAR(*cen2018_row_trace(row, rms).noise_sigma, 0.6, 1e-5);
  EXPECT_NEAR(*cen2018_row_trace(row, rms_x2).noise_sigma, 0.6 * std::sqrt(2.0), 1e-5);

  rms.z_q = rms_x2.z_q = 250.0;  // below both limits
  EXPECT_EQ(cen2018_row_features(row, rms), std::vector<int>{200});
  EXPECT_EQ(cen2018_row_features(row, rms_x2), std::vector<int>{200});
  rms.z_q = rms_x2.z_q = 300.0;  // between 282 and 399
  EXPECT_EQ(cen2018_row_features(row, rms), std::vector<int>{200});
  EXPECT_TRUE(cen2018_row_features(row, rms_x2).empty());
  rms.z_q = rms_x2.z_q = 450.0;  // above both
  EXPECT_TRUE(cen2018_row_features(row, rms).empty());
  EXPECT_TRUE(cen2018_row_features(row, rms_x2).empty());
}

// A weak 20-bin plateau [200, 219] at 18 on a background alternating 8 (even r) / 12 (odd r):
// mean = (190 * 8 + 190 * 12 + 20 * 18) / 400 = 10.4; negative bins are the 8s (q = -2.4), so
// sigma_a = 2.4 and with z_q = 2.5 the threshold is 6.0; on the plateau q = 7.6.
// Box (17 taps): at r = 210 the window 202..218 lies on the plateau, p = q = 7.6, G(0) = 1 and
// y = 7.6 * (1 - exp(-7.6^2 / (2 * 2.4^2))) = 7.6 * (1 - 0.0066) = 7.55 > 6: a feature. The
// candidate run is symmetric about 209.5, so its even length puts the feature at 210.
// Gaussian (sigma 17): only 44% of the kernel's mass lies on the plateau, p(210) ~ 3.16,
// y = 7.6 (1 - G(4.44)) + 3.16 (G(4.44) - G(3.16)) = 7.6 * 0.819 + 3.16 * (0.181 - 0.420) = 5.47
// < 6: the broad kernel dilutes the plateau and nothing is found.
TEST(Cen2018Row, BoxKernelKeepsABroadWeakPlateauThatTheGaussianDilutes) {
  std::vector<float> row;
  for (int r = 0; r < 400; ++r) row.push_back(r % 2 == 0 ? 8.0f : 12.0f);
  for (int r = 200; r < 220; ++r) row[static_cast<std::size_t>(r)] = 18.0f;
  Cen2018Params box;
  box.kernel = CenKernel::box;
  box.z_q = 2.5;
  Cen2018Params gaussian = box;
  gaussian.kernel = CenKernel::gaussian;

  const Cen2018RowTrace box_trace = cen2018_row_trace(row, box);
  EXPECT_NEAR(*box_trace.noise_sigma, 2.4, 1e-5);
  EXPECT_NEAR(box_trace.smoothed[210], 7.6, 1e-4);
  EXPECT_NEAR(box_trace.response[210], 7.55, 0.01);
  EXPECT_EQ(box_trace.features, std::vector<int>{210});

  const Cen2018RowTrace gaussian_trace = cen2018_row_trace(row, gaussian);
  EXPECT_NEAR(gaussian_trace.smoothed[210], 3.16, 0.01);
  EXPECT_NEAR(gaussian_trace.response[210], 5.47, 0.01);
  EXPECT_TRUE(gaussian_trace.features.empty());
}

// Ramp x[r] = r, R = 40, mean 19.5. Box at r = 0 with BORDER_REFLECT (edge repeated, scipy
// 'reflect'): x[-k] = x[k - 1], window sum = (7 + 6 + ... + 0) + (0 + 1 + ... + 8) = 28 + 36 = 64,
// p[0] = 64 / 17 - 19.5 = -15.735. (REFLECT_101 would give (36 + 36) / 17 - 19.5 = -15.265.)
TEST(Cen2018Row, SmoothingReflectsWithTheEdgeSampleRepeated) {
  std::vector<float> ramp;
  for (int r = 0; r < 40; ++r) ramp.push_back(static_cast<float>(r));
  Cen2018Params box;
  box.kernel = CenKernel::box;
  const Cen2018RowTrace trace = cen2018_row_trace(ramp, box);
  EXPECT_NEAR(trace.smoothed[0], 64.0 / 17.0 - 19.5, 1e-4);
  // Last bin mirrors the first: window 31..39 and 39..32 -> (315 + 284) / 17 - 19.5.
  EXPECT_NEAR(trace.smoothed[39], (315.0 + 284.0) / 17.0 - 19.5, 1e-4);
  // Inside, a symmetric kernel leaves a ramp unchanged: p = q = r - 19.5.
  EXPECT_NEAR(trace.smoothed[20], 0.5, 1e-4);
}

TEST(Cen2018Kernel, GaussianIsTruncatedAtThreeSigmaAndNormalised) {
  const std::vector<float> gaussian = cen2018_kernel(Cen2018Params{});
  ASSERT_EQ(gaussian.size(), 103u);  // radius floor(3 * 17 + 0.5) = 51
  double sum = 0.0;
  for (const float tap : gaussian) sum += tap;
  EXPECT_NEAR(sum, 1.0, 1e-6);
  // Edge over centre: exp(-51^2 / (2 * 17^2)) = exp(-4.5) = 0.011109.
  EXPECT_NEAR(gaussian.front() / gaussian[51], std::exp(-4.5), 1e-6);
  EXPECT_EQ(gaussian.front(), gaussian.back());

  Cen2018Params box;
  box.kernel = CenKernel::box;
  EXPECT_EQ(cen2018_kernel(box), std::vector<float>(17, 1.0f / 17.0f));

  Cen2018Params narrow;
  narrow.sigma = 2.0;
  EXPECT_EQ(cen2018_kernel(narrow).size(), 13u);  // radius floor(6.5) = 6
}

// Ramp x[r] = r over 400 bins, window [r - 100, r + 99] (200 bins), reflected at the ends.
// r = 200: bins 100..299, middle values 199 and 200 -> median 199.5, q = 0.5.
// r = 0: bins -100..99 -> {0..99} twice; sorted positions 99 and 100 hold 49 and 50 -> q = -49.5.
// r = 399: bins 299..498, 400..498 reflect to 399..301 -> {299, 300} + {301..399} twice; sorted
// position 2k + 1 holds 300 + k, so positions 99, 100 hold 349, 350 -> median 349.5, q = 49.5.
TEST(Cen2018Row, MedianDetrendSubtractsARunningMedianOfWidth200) {
  std::vector<float> ramp;
  for (int r = 0; r < 400; ++r) ramp.push_back(static_cast<float>(r));
  Cen2018Params params;
  params.detrend = CenDetrend::median;
  const Cen2018RowTrace trace = cen2018_row_trace(ramp, params);
  EXPECT_NEAR(trace.detrended[200], 0.5, 1e-4);
  EXPECT_NEAR(trace.detrended[0], -49.5, 1e-4);
  EXPECT_NEAR(trace.detrended[399], 49.5, 1e-4);
}

// The sliding sorted window against a median taken from scratch at a few bins of a noisy row.
TEST(Cen2018Row, MedianDetrendMatchesAMedianTakenFromScratch) {
  const std::vector<float> row = noisy_row(1000, 11u);
  Cen2018Params params;
  params.detrend = CenDetrend::median;
  const Cen2018RowTrace trace = cen2018_row_trace(row, params);
  auto reflect = [](int i) { return i < 0 ? -i - 1 : (i >= 1000 ? 1999 - i : i); };
  for (const int r : {0, 1, 99, 100, 101, 450, 899, 900, 998, 999}) {
    std::vector<float> window;
    for (int i = r - 100; i < r + 100; ++i)
      window.push_back(row[static_cast<std::size_t>(reflect(i))]);
    std::sort(window.begin(), window.end());
    const double median = 0.5 * (window[99] + window[100]);
    EXPECT_NEAR(trace.detrended[static_cast<std::size_t>(r)],
                row[static_cast<std::size_t>(r)] - median, 1e-4)
        << r;
  }
}

TEST(Cen2018, RejectsBadInput) {
  EXPECT_THROW(extract_cen2018_features(ByteImage(), Cen2018Params{}), std::invalid_argument);
  EXPECT_THROW(extract_cen2018_features(ByteImage(0, 10), Cen2018Params{}), std::invalid_argument);
  // Float rows: none, or not a whole number of rows.
  EXPECT_THROW(extract_cen2018_features(std::vector<float>{}, 10, Cen2018Params{}),
               std::invalid_argument);
  EXPECT_THROW(extract_cen2018_features(std::vector<float>(25, 1.0f), 10, Cen2018Params{}),
               std::invalid_argument);
  EXPECT_THROW(extract_cen2018_features(std::vector<float>(20, 1.0f), 0, Cen2018Params{}),
               std::invalid_argument);
  EXPECT_THROW(cen2018_row_features(std::vector<float>{}, Cen2018Params{}), std::invalid_argument);
  Cen2018Params zero_sigma;
  zero_sigma.sigma = 0.0;
  EXPECT_THROW(cen2018_kernel(zero_sigma), std::invalid_argument);
  EXPECT_THROW(extract_cen2018_features(ByteImage(4, 10, 1), zero_sigma), std::invalid_argument);
}

// min_range_bins beyond the scan kept no feature at all: ReFeree gave every scan the same
// all-zero value, without a word. Refused, naming the largest value that fits.
TEST(Cen2018, RefusesAMinimumRangeBeyondTheScan) {
  Cen2018Params params;
  params.min_range_bins = 60;
  try {
    extract_cen2018_features(ByteImage(8, 50, 1), params);
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(),
                 "cen2018: min_range_bins = 60 leaves no range bin of a scan with 50 (at most 48 "
                 "for these scans)");
  }
  params.min_range_bins = 48;
  EXPECT_NO_THROW(extract_cen2018_features(ByteImage(8, 50, 1), params));
}

}  // namespace
}  // namespace radarpr
