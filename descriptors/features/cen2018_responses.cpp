#include "descriptors/features/cen2018_responses.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "datasets/cpu_features.hpp"
#include "descriptors/features/cen2018_float_test.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace radarpr::cen2018_detail {
namespace {

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define RADARPR_CEN2018_RESPONSES_AVX2 1

bool has_avx2() {
  static const bool available = cpu_features().avx2;
  return available;
}

// exp of eight floats, the same operations as the four-lane version below.
__attribute__((target("avx2"))) __m256 exp_of_eight(__m256 x) {
  x = _mm256_max_ps(x, _mm256_set1_ps(kLowestArgument));  // NaN gives the lowest argument
  const __m256i n = _mm256_cvtps_epi32(_mm256_mul_ps(x, _mm256_set1_ps(kLog2E)));
  const __m256 nf = _mm256_cvtepi32_ps(n);
  const __m256 r = _mm256_sub_ps(_mm256_sub_ps(x, _mm256_mul_ps(nf, _mm256_set1_ps(kLn2High))),
                                 _mm256_mul_ps(nf, _mm256_set1_ps(kLn2Low)));
  __m256 e = _mm256_set1_ps(kTaylor[0]);
  for (int t = 1; t < 7; ++t) {
    e = _mm256_add_ps(_mm256_mul_ps(e, r), _mm256_set1_ps(kTaylor[t]));
  }
  const __m256i bits = _mm256_slli_epi32(_mm256_add_epi32(n, _mm256_set1_epi32(127)), 23);
  return _mm256_mul_ps(e, _mm256_castsi256_ps(bits));
}

// classify_responses eight bins at a time; returns how many bins it decided (a multiple of 8).
__attribute__((target("avx2"))) std::size_t classify_eight_at_a_time(const float* q, const float* p,
                                                                     std::size_t count, float k,
                                                                     float threshold,
                                                                     float p_margin,
                                                                     Verdict* verdicts) {
  const __m256 scale = _mm256_set1_ps(k);
  const __m256 thr = _mm256_set1_ps(threshold);
  const __m256 relative = _mm256_set1_ps(kRelativeMargin);
  const __m256 absolute = _mm256_set1_ps(p_margin);
  const __m256 sign = _mm256_set1_ps(-0.0f);
  std::size_t i = 0;
  for (; i + 8 <= count; i += 8) {
    const __m256 qv = _mm256_loadu_ps(q + i);
    const __m256 pv = _mm256_loadu_ps(p + i);
    const __m256 d = _mm256_sub_ps(qv, pv);
    const __m256 y = _mm256_sub_ps(
        _mm256_sub_ps(qv,
                      _mm256_mul_ps(d, exp_of_eight(_mm256_mul_ps(_mm256_mul_ps(d, d), scale)))),
        _mm256_mul_ps(pv, exp_of_eight(_mm256_mul_ps(_mm256_mul_ps(pv, pv), scale))));
    const __m256 magnitudes = _mm256_add_ps(
        _mm256_add_ps(_mm256_add_ps(_mm256_andnot_ps(sign, qv), _mm256_andnot_ps(sign, d)),
                      _mm256_andnot_ps(sign, pv)),
        thr);
    const __m256 margin = _mm256_add_ps(absolute, _mm256_mul_ps(relative, magnitudes));
    const int passes = _mm256_movemask_ps(_mm256_cmp_ps(y, _mm256_add_ps(thr, margin), _CMP_GT_OQ));
    const int fails = _mm256_movemask_ps(_mm256_cmp_ps(y, _mm256_sub_ps(thr, margin), _CMP_LT_OQ));
    for (int lane = 0; lane < 8; ++lane) {
      verdicts[i + lane] = static_cast<Verdict>(2 - (passes >> lane & 1) - 2 * (fails >> lane & 1));
    }
  }
  return i;
}
#endif

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
#if defined(RADARPR_CEN2018_RESPONSES_AVX2)
  if (has_avx2()) {
    i = classify_eight_at_a_time(q, p, count, minus_inverse_two_sigma_squared, threshold_f,
                                 p_margin, verdicts);
  }
#endif
#if defined(__SSE2__)
  // The operations of approximate_exp and of the scalar loop below, four bins at a time.
  const __m128 k = _mm_set1_ps(minus_inverse_two_sigma_squared);
  const __m128 lowest = _mm_set1_ps(kLowestArgument);
  const __m128 log2e = _mm_set1_ps(kLog2E);
  const __m128 ln2_high = _mm_set1_ps(kLn2High);
  const __m128 ln2_low = _mm_set1_ps(kLn2Low);
  const __m128i bias = _mm_set1_epi32(127);
  const __m128 thr = _mm_set1_ps(threshold_f);
  const __m128 relative = _mm_set1_ps(kRelativeMargin);
  const __m128 absolute = _mm_set1_ps(p_margin);
  const __m128 magnitude_bits = _mm_castsi128_ps(_mm_set1_epi32(0x7fffffff));
  const auto exp_of = [&](__m128 x) {
    x = _mm_max_ps(x, lowest);                                // NaN gives the lowest argument
    const __m128i n = _mm_cvtps_epi32(_mm_mul_ps(x, log2e));  // rounded to nearest, even
    const __m128 nf = _mm_cvtepi32_ps(n);
    const __m128 r = _mm_sub_ps(_mm_sub_ps(x, _mm_mul_ps(nf, ln2_high)), _mm_mul_ps(nf, ln2_low));
    __m128 e = _mm_set1_ps(kTaylor[0]);
    for (int t = 1; t < 7; ++t) e = _mm_add_ps(_mm_mul_ps(e, r), _mm_set1_ps(kTaylor[t]));
    return _mm_mul_ps(e, _mm_castsi128_ps(_mm_slli_epi32(_mm_add_epi32(n, bias), 23)));
  };
  for (; i + 4 <= count; i += 4) {
    const __m128 qv = _mm_loadu_ps(q + i);
    const __m128 pv = _mm_loadu_ps(p + i);
    const __m128 d = _mm_sub_ps(qv, pv);
    const __m128 y =
        _mm_sub_ps(_mm_sub_ps(qv, _mm_mul_ps(d, exp_of(_mm_mul_ps(_mm_mul_ps(d, d), k)))),
                   _mm_mul_ps(pv, exp_of(_mm_mul_ps(_mm_mul_ps(pv, pv), k))));
    const __m128 magnitudes = _mm_add_ps(
        _mm_add_ps(_mm_add_ps(_mm_and_ps(qv, magnitude_bits), _mm_and_ps(d, magnitude_bits)),
                   _mm_and_ps(pv, magnitude_bits)),
        thr);
    const __m128 margin = _mm_add_ps(absolute, _mm_mul_ps(relative, magnitudes));
    const int passes = _mm_movemask_ps(_mm_cmpgt_ps(y, _mm_add_ps(thr, margin)));
    const int fails = _mm_movemask_ps(_mm_cmplt_ps(y, _mm_sub_ps(thr, margin)));
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
