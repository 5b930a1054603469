// The Cen 2018 response test decides most candidate bins in float32 with a polynomial
// exponential and leaves the bins near the threshold to the exact computation. These tests hold
// the exponential to its stated error, the verdicts to the exact responses, and the features of
// whole scans (uint8, both kernels, several z_q) to the features of the full definition: p and y
// at every bin of every row (cen2018_row_trace), runs of y > z_q sigma - through every row path
// the processor can run (the baseline, and AVX-512 where it has it).
#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "datasets/byte_image.hpp"
#include "descriptors/features/cen2018.hpp"
#include "descriptors/features/cen2018_avx512.hpp"
#include "descriptors/features/cen2018_paths.hpp"
#include "descriptors/features/cen2018_responses.hpp"
#include "descriptors/features/cen2018_row_passes.hpp"
#include "tests/descriptors/mulran_frames.hpp"

namespace radarpr {
namespace {

using cen2018_detail::approximate_exp;
using cen2018_detail::classify_responses;
using cen2018_detail::Verdict;

TEST(Cen2018Responses, ApproximateExponentialIsWithinOneMillionthRelative) {
  double worst = 0.0;
  for (int i = 0; i <= 870000; ++i) {
    const float x = -0.0001f * static_cast<float>(i);
    const double exact = std::exp(static_cast<double>(x));
    worst = std::max(worst, std::abs(approximate_exp(x) - exact) / exact);
  }
  EXPECT_LT(worst, 1e-6);
  EXPECT_EQ(approximate_exp(-1000.0f), approximate_exp(-87.0f));  // clamped, still normal
  EXPECT_GT(approximate_exp(-1000.0f), 0.0f);
}

double exact_response(double q, double p, double sigma) {
  const double k = 1.0 / (2.0 * sigma * sigma);
  const double g_difference = std::exp(-(q - p) * (q - p) * k);
  const double g_smoothed = std::exp(-p * p * k);
  return q * (1.0 - g_difference) + p * (g_difference - g_smoothed);
}

// Random q, p around the threshold, including bins right at it: no verdict contradicts the exact
// response, most bins are decided, and p given with an error bound widens the undecided band.
TEST(Cen2018Responses, VerdictsNeverContradictTheExactResponse) {
  std::uint32_t seed = 12345;
  auto uniform = [&seed](double low, double high) {
    seed = seed * 1664525u + 1013904223u;
    return low + (high - low) * static_cast<double>(seed >> 8) / 16777216.0;
  };
  for (const double p_error : {0.0, 0.01}) {
    const double sigma = 7.5;
    const double threshold = 3.0 * sigma;
    std::vector<float> q;
    std::vector<float> p;
    for (int i = 0; i < 200003; ++i) {
      q.push_back(static_cast<float>(uniform(-20.0, 120.0)));
      p.push_back(static_cast<float>(uniform(-20.0, 60.0)));
    }
    // Bins whose exact y lies on the threshold to float precision.
    for (int i = 0; i < 1000; ++i) {
      const float pv = static_cast<float>(uniform(-10.0, 10.0));
      float qv = static_cast<float>(threshold);
      for (int step = 0; step < 30; ++step) {
        qv += static_cast<float>(threshold - exact_response(qv, pv, sigma));
      }
      q.push_back(qv);
      p.push_back(pv);
    }
    std::vector<Verdict> verdicts(q.size());
    classify_responses(q.data(), p.data(), q.size(), sigma, threshold, p_error, verdicts.data());
    std::size_t undecided = 0;
    for (std::size_t i = 0; i < q.size(); ++i) {
      const double y = exact_response(q[i], p[i], sigma);
      if (verdicts[i] == Verdict::undecided) {
        ++undecided;
        continue;
      }
      // With p off by up to p_error, y may move by 2 p_error: decided bins keep their side.
      for (const double shift : {-p_error, 0.0, p_error}) {
        const double shifted = exact_response(q[i], p[i] + shift, sigma);
        ASSERT_EQ(verdicts[i] == Verdict::passes, shifted > threshold)
            << "q " << q[i] << " p " << p[i] << " y " << y << " p error " << p_error;
      }
    }
    EXPECT_GE(undecided, 900u);                   // the bins on the threshold
    EXPECT_LT(undecided, q.size() / 100 + 1000);  // and few others
  }
}

// The batched fixed-point products (AVX2 where the processor has it) are the exact integer sums.
TEST(Cen2018Responses, WindowProductsAreExactIntegerSums) {
  std::uint32_t seed = 4242;
  auto next = [&seed] {
    seed = seed * 1664525u + 1013904223u;
    return seed >> 8;
  };
  std::vector<unsigned char> bytes(5000);
  for (auto& b : bytes) b = static_cast<unsigned char>(next() % 256);
  for (const std::size_t length : {16u, 32u, 112u}) {
    std::vector<std::int16_t> taps(length);
    for (auto& t : taps) t = static_cast<std::int16_t>(next() % 32768);
    std::vector<const unsigned char*> windows;
    for (int i = 0; i < 300; ++i) windows.push_back(bytes.data() + next() % (5000 - length));
    std::vector<std::int32_t> sums(windows.size());
    cen2018_detail::window_dot_products(taps.data(), length, windows.data(), windows.size(),
                                        sums.data());
    for (std::size_t i = 0; i < windows.size(); ++i) {
      std::int64_t expected = 0;
      for (std::size_t k = 0; k < length; ++k) expected += taps[k] * windows[i][k];
      ASSERT_EQ(sums[i], expected) << "length " << length << " window " << i;
      ASSERT_EQ(cen2018_detail::window_dot_product(taps.data(), windows[i], length), expected);
    }
  }
}

// The features as the definition gives them, row by row from every bin's response.
std::vector<int> defined_row_features(const ByteImage& power, int a, const Cen2018Params& params) {
  const std::vector<float> row(power.row(a), power.row(a) + power.cols());
  const Cen2018RowTrace trace = cen2018_row_trace(row, params);
  std::vector<int> features;
  if (!trace.noise_sigma) return features;
  const double threshold = params.z_q * *trace.noise_sigma;
  for (int r = 0; r < power.cols();) {
    if (!(trace.response[static_cast<std::size_t>(r)] > threshold)) {
      ++r;
      continue;
    }
    int end = r;
    while (end < power.cols() && trace.response[static_cast<std::size_t>(end)] > threshold) ++end;
    const int bin = r + (end - r) / 2;
    if (bin > params.min_range_bins) features.push_back(bin);
    r = end;
  }
  return features;
}

// The row paths this processor runs.
std::vector<cen2018_detail::RowPath> available_paths() {
  std::vector<cen2018_detail::RowPath> paths{cen2018_detail::RowPath::baseline};
  if (cen2018_detail::has_avx512()) paths.push_back(cen2018_detail::RowPath::avx512);
  return paths;
}

void expect_defined_features(const ByteImage& power, const std::string& what) {
  std::size_t total = 0;
  for (const double z_q : {1.0, 3.0, 6.0}) {
    for (const CenKernel kernel : {CenKernel::gaussian, CenKernel::box}) {
      Cen2018Params params;
      params.z_q = z_q;
      params.kernel = kernel;
      std::vector<std::vector<int>> defined;
      for (int a = 0; a < power.rows(); ++a)
        defined.push_back(defined_row_features(power, a, params));
      for (const cen2018_detail::RowPath path : available_paths()) {
        const PolarFeatures features = cen2018_detail::extract_features_with(power, params, path);
        for (int a = 0; a < power.rows(); ++a) {
          const auto bins = features.azimuth(a);
          ASSERT_EQ(std::vector<int>(bins.begin(), bins.end()),
                    defined[static_cast<std::size_t>(a)])
              << what << " row " << a << " z_q " << z_q << " kernel " << static_cast<int>(kernel)
              << " path " << static_cast<int>(path);
        }
        total += features.feature_count();
      }
    }
  }
  EXPECT_GT(total, 1000u) << what;
}

// Kernels whose fixed-point taps are not one of the unrolled lengths (box: 32, sigma 17: 112), a
// row shorter than the kernel and one of an odd length: each path against the definition.
TEST(Cen2018Responses, OtherKernelLengthsAndShortRowsGiveTheDefinedFeatures) {
  std::uint32_t seed = 7;
  auto next = [&seed] {
    seed = seed * 1664525u + 1013904223u;
    return seed >> 8;
  };
  std::size_t total = 0;
  for (const int bins : {37, 1001}) {
    ByteImage power(6, bins);
    for (int a = 0; a < power.rows(); ++a) {
      for (int r = 0; r < bins; ++r) {
        power(a, r) = static_cast<uint8_t>(next() % 30u);
      }
      for (int target = 0; target < 8; ++target) {
        const int start = static_cast<int>(next() % static_cast<unsigned>(bins));
        const auto height = static_cast<uint8_t>(40u + next() % 200u);
        for (int r = start; r < std::min(bins, start + 1 + static_cast<int>(next() % 9u)); ++r) {
          power(a, r) = height;
        }
      }
    }
    for (const double sigma : {2.0, 9.0, 17.0, 30.0}) {
      Cen2018Params params;
      params.sigma = sigma;
      params.z_q = 2.0;
      params.min_range_bins = 0;
      for (const cen2018_detail::RowPath path : available_paths()) {
        const PolarFeatures features = cen2018_detail::extract_features_with(power, params, path);
        for (int a = 0; a < power.rows(); ++a) {
          const auto found = features.azimuth(a);
          ASSERT_EQ(std::vector<int>(found.begin(), found.end()),
                    defined_row_features(power, a, params))
              << bins << " bins, sigma " << sigma << " row " << a << " path "
              << static_cast<int>(path);
        }
        total += features.feature_count();
      }
    }
  }
  EXPECT_GT(total, 100u);
}

TEST(Cen2018Responses, ScanFeaturesAreThoseOfEveryBinsResponse) {
  ByteImage power(48, 3360);
  std::uint32_t seed = 99;
  auto next = [&seed] {
    seed = seed * 1664525u + 1013904223u;
    return seed >> 8;
  };
  for (int a = 0; a < power.rows(); ++a) {
    const unsigned noise = 10u + static_cast<unsigned>(a);
    for (int r = 0; r < power.cols(); ++r) {
      power(a, r) = static_cast<uint8_t>(next() % noise);
    }
    for (int target = 0; target < 30; ++target) {
      const int start = static_cast<int>(next() % 3360u);
      const int width = 1 + static_cast<int>(next() % 20u);
      const auto height = static_cast<uint8_t>(std::min(255u, noise + next() % 200u));
      for (int r = start; r < std::min(3360, start + width); ++r) power(a, r) = height;
    }
  }
  expect_defined_features(power, "speckle");
}

TEST(Cen2018Responses, RealMulranScanFeaturesAreThoseOfEveryBinsResponse) {
  SKIP_WITHOUT_FRAMES("000001");
  const PolarImage scan = testing::read_native("000001");
  // Every fourth azimuth: the full definition costs a 103-tap product at every bin.
  const ByteImage& power = scan.power;
  ByteImage rows((power.rows() + 3) / 4, power.cols());
  for (int a = 0; a < power.rows(); a += 4) {
    std::copy(power.row(a), power.row(a) + power.cols(), rows.row(a / 4));
  }
  expect_defined_features(rows, "MulRan 000001");
}

}  // namespace
}  // namespace radarpr
