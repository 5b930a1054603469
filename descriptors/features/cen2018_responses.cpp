#include "descriptors/features/cen2018_responses.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <opencv2/core/hal/intrin.hpp>

namespace radarpr::cen2018_detail {
namespace {

// exp(x) = 2^n e^r with n = round(x log2 e) and r = x - n ln 2 (ln 2 split in two so that n ln 2
// is exact to float precision), |r| <= ln(2) / 2; e^r by its Taylor polynomial of degree 6, whose
// truncation error is below 1.3e-7 there.
constexpr float kLog2E = 1.44269504088896341f;
constexpr float kLn2High = 0.693359375f;  // 8 significant bits: n * kLn2High is exact
constexpr float kLn2Low = -2.12194440e-4f;
constexpr float kLowestArgument = -87.0f;  // 2^-126 <= exp(-87): the result stays normal
constexpr float kTaylor[] = {1.0f / 720, 1.0f / 120, 1.0f / 24, 1.0f / 6, 0.5f, 1.0f, 1.0f};

// The relative error the verdicts allow for the whole float evaluation of y: the exponential
// (below 1e-6) and a few roundings of 6e-8 each, with a margin of five.
constexpr float kRelativeMargin = 1e-5f;

}  // namespace

float approximate_exp(float x) {
  x = x >= kLowestArgument ? x : kLowestArgument;  // NaN too: its y is NaN anyway
  const float n = std::nearbyint(x * kLog2E);
  const float r = (x - n * kLn2High) - n * kLn2Low;
  float e = kTaylor[0];
  for (int i = 1; i < 7; ++i) e = e * r + kTaylor[i];
  std::uint32_t bits = static_cast<std::uint32_t>(static_cast<int>(n) + 127) << 23;
  float scale = 0.0f;
  std::memcpy(&scale, &bits, sizeof scale);
  return e * scale;
}

void classify_responses(const float* q, const float* p, std::size_t count, double sigma,
                        double threshold, double p_error, Verdict* verdicts) {
  const auto minus_inverse_two_sigma_squared = static_cast<float>(-1.0 / (2.0 * sigma * sigma));
  const auto threshold_f = static_cast<float>(threshold);
  const auto p_margin = static_cast<float>(2.0 * p_error);
  std::size_t i = 0;
#if CV_SIMD128
  const cv::v_float32x4 k = cv::v_setall_f32(minus_inverse_two_sigma_squared);
  const cv::v_float32x4 lowest = cv::v_setall_f32(kLowestArgument);
  const cv::v_float32x4 log2e = cv::v_setall_f32(kLog2E);
  const cv::v_float32x4 ln2_high = cv::v_setall_f32(kLn2High);
  const cv::v_float32x4 ln2_low = cv::v_setall_f32(kLn2Low);
  const cv::v_int32x4 bias = cv::v_setall_s32(127);
  const cv::v_float32x4 thr = cv::v_setall_f32(threshold_f);
  const cv::v_float32x4 relative = cv::v_setall_f32(kRelativeMargin);
  const cv::v_float32x4 absolute = cv::v_setall_f32(p_margin);
  auto exp_of = [&](cv::v_float32x4 x) {
    x = cv::v_max(x, lowest);
    const cv::v_int32x4 n = cv::v_round(x * log2e);
    const cv::v_float32x4 nf = cv::v_cvt_f32(n);
    const cv::v_float32x4 r = (x - nf * ln2_high) - nf * ln2_low;
    cv::v_float32x4 e = cv::v_setall_f32(kTaylor[0]);
    for (int t = 1; t < 7; ++t) e = e * r + cv::v_setall_f32(kTaylor[t]);
    return e * cv::v_reinterpret_as_f32(cv::v_shl<23>(n + bias));
  };
  for (; i + 4 <= count; i += 4) {
    const cv::v_float32x4 qv = cv::v_load(q + i);
    const cv::v_float32x4 pv = cv::v_load(p + i);
    const cv::v_float32x4 d = qv - pv;
    const cv::v_float32x4 y = qv - d * exp_of(d * d * k) - pv * exp_of(pv * pv * k);
    const cv::v_float32x4 margin =
        absolute + relative * (cv::v_abs(qv) + cv::v_abs(d) + cv::v_abs(pv) + thr);
    const int passes = cv::v_signmask(y > thr + margin);
    const int fails = cv::v_signmask(y < thr - margin);
    // fails = 0, passes = 1, undecided = 2; a bin never both passes and fails.
    for (int lane = 0; lane < 4; ++lane) {
      verdicts[i + lane] = static_cast<Verdict>(2 - (passes >> lane & 1) - 2 * (fails >> lane & 1));
    }
  }
#endif
  for (; i < count; ++i) {
    const float d = q[i] - p[i];
    const float y = q[i] - d * approximate_exp(d * d * minus_inverse_two_sigma_squared) -
                    p[i] * approximate_exp(p[i] * p[i] * minus_inverse_two_sigma_squared);
    const float margin =
        p_margin + kRelativeMargin * (std::abs(q[i]) + std::abs(d) + std::abs(p[i]) + threshold_f);
    verdicts[i] = y > threshold_f + margin   ? Verdict::passes
                  : y < threshold_f - margin ? Verdict::fails
                                             : Verdict::undecided;
  }
}

}  // namespace radarpr::cen2018_detail
