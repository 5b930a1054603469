#include "descriptors/features/cen2018_avx512.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "datasets/cpu_features.hpp"
#include "descriptors/features/cen2018_float_test.hpp"

#if defined(__GNUC__) && !defined(__clang__)
// GCC 12's AVX-512 intrinsics fill their unused operands with a deliberately uninitialised
// vector (_mm512_undefined_*), which its own warnings flag where they are inlined.
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define RADARPR_CEN2018_AVX512 1
#define RADARPR_AVX512_TARGET \
  __attribute__((target("avx512f,avx512bw,avx512vl,avx512vnni,popcnt,bmi,bmi2")))
#endif

namespace radarpr::cen2018_detail {

#if defined(RADARPR_CEN2018_AVX512)

bool has_avx512() {
  static const bool available = cpu_features().avx512f && cpu_features().avx512bw &&
                                cpu_features().avx512vl && cpu_features().avx512vnni &&
                                cpu_features().popcnt;
  return available;
}

namespace {

// The bytes r .. r + 63 of a row of `count` that exist, as a load mask (masked-off bytes are not
// read, so a row's last step never reads past it).
inline std::uint64_t lanes_from(int r, int count) {
  const int left = count - r;
  return left >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << left) - 1;
}

RADARPR_AVX512_TARGET std::uint64_t sum_of_lanes(__m512i v) {
  return static_cast<std::uint64_t>(_mm512_reduce_add_epi64(v));
}

// The smallest and the largest of 64 bytes, by halving: 512 -> 256 -> 128 bits, then shifts
// within 128 bits.
RADARPR_AVX512_TARGET inline unsigned char smallest_byte(__m512i v) {
  const __m256i half = _mm256_min_epu8(_mm512_castsi512_si256(v), _mm512_extracti64x4_epi64(v, 1));
  __m128i m = _mm_min_epu8(_mm256_castsi256_si128(half), _mm256_extracti128_si256(half, 1));
  m = _mm_min_epu8(m, _mm_srli_si128(m, 8));
  m = _mm_min_epu8(m, _mm_srli_si128(m, 4));
  m = _mm_min_epu8(m, _mm_srli_si128(m, 2));
  m = _mm_min_epu8(m, _mm_srli_si128(m, 1));
  return static_cast<unsigned char>(_mm_cvtsi128_si32(m) & 0xFF);
}

RADARPR_AVX512_TARGET inline unsigned char largest_byte(__m512i v) {
  const __m256i half = _mm256_max_epu8(_mm512_castsi512_si256(v), _mm512_extracti64x4_epi64(v, 1));
  __m128i m = _mm_max_epu8(_mm256_castsi256_si128(half), _mm256_extracti128_si256(half, 1));
  m = _mm_max_epu8(m, _mm_srli_si128(m, 8));
  m = _mm_max_epu8(m, _mm_srli_si128(m, 4));
  m = _mm_max_epu8(m, _mm_srli_si128(m, 2));
  m = _mm_max_epu8(m, _mm_srli_si128(m, 1));
  return static_cast<unsigned char>(_mm_cvtsi128_si32(m) & 0xFF);
}

RADARPR_AVX512_TARGET ByteRange byte_range_avx512(const unsigned char* x, int count) {
  const __m512i zero = _mm512_setzero_si512();
  const __m512i all_ones = _mm512_set1_epi8(static_cast<char>(255));
  __m512i total = zero;
  __m512i smallest = all_ones;
  __m512i largest = zero;
  int r = 0;
  for (; r + 64 <= count; r += 64) {
    const __m512i v = _mm512_loadu_si512(x + r);
    total = _mm512_add_epi64(total, _mm512_sad_epu8(v, zero));
    smallest = _mm512_min_epu8(smallest, v);
    largest = _mm512_max_epu8(largest, v);
  }
  if (r < count) {
    // Missing bytes read as 0 for the sum and the largest, as 255 for the smallest.
    const __mmask64 lanes = lanes_from(r, count);
    const __m512i v = _mm512_maskz_loadu_epi8(lanes, x + r);
    total = _mm512_add_epi64(total, _mm512_sad_epu8(v, zero));
    smallest = _mm512_min_epu8(smallest, _mm512_mask_mov_epi8(all_ones, lanes, v));
    largest = _mm512_max_epu8(largest, v);
  }
  ByteRange range;
  range.sum = sum_of_lanes(total);
  range.smallest = smallest_byte(smallest);
  range.largest = largest_byte(largest);
  return range;
}

RADARPR_AVX512_TARGET ByteSums byte_sums_below_avx512(const unsigned char* x, int count,
                                                      unsigned char below) {
  ByteSums sums;
  if (below == 0) return sums;
  // 8192 steps add at most 8192 * 4 * 255^2 < 2^31 to each 32-bit lane of squares.
  constexpr int kChunk = 8192 * 64;
  const __m512i zero = _mm512_setzero_si512();
  const __m512i limit = _mm512_set1_epi8(static_cast<char>(below - 1));
  __m512i values = zero;
  // Below 128, the kept bytes are also valid signed bytes: one multiply-add of byte quadruples
  // squares and sums 64 of them (at most 4 * 127^2 per lane and step).
  const bool small = below <= 128;
  for (int r = 0; r < count;) {
    const int chunk_end = std::min(count, r + kChunk);
    __m512i squares = zero;
    for (; r < chunk_end; r += 64) {
      const __mmask64 lanes = lanes_from(r, chunk_end);
      const __m512i v = _mm512_maskz_loadu_epi8(lanes, x + r);
      const __mmask64 is_below = _mm512_mask_cmple_epu8_mask(lanes, v, limit);
      const __m512i kept = _mm512_maskz_mov_epi8(is_below, v);
      values = _mm512_add_epi64(values, _mm512_sad_epu8(kept, zero));
      sums.count += static_cast<std::uint64_t>(_mm_popcnt_u64(_cvtmask64_u64(is_below)));
      if (small) {
        squares = _mm512_dpbusd_epi32(squares, kept, kept);
        continue;
      }
      const __m512i low = _mm512_unpacklo_epi8(kept, zero);
      const __m512i high = _mm512_unpackhi_epi8(kept, zero);
      squares = _mm512_add_epi32(
          squares, _mm512_add_epi32(_mm512_madd_epi16(low, low), _mm512_madd_epi16(high, high)));
    }
    // Each lane is below 2^31, so widening its 32 bits as unsigned is exact.
    sums.sum_of_squares += sum_of_lanes(
        _mm512_add_epi64(_mm512_cvtepu32_epi64(_mm512_castsi512_si256(squares)),
                         _mm512_cvtepu32_epi64(_mm512_extracti64x4_epi64(squares, 1))));
  }
  sums.sum = sum_of_lanes(values);
  return sums;
}

// exp of sixteen floats: the operations of exp_of_eight and the four-lane version of
// cen2018_responses.cpp, with the constants of cen2018_float_test.hpp.

RADARPR_AVX512_TARGET inline __m512 exp_of_sixteen(__m512 x) {
  x = _mm512_max_ps(x, _mm512_set1_ps(kLowestArgument));  // NaN gives the lowest argument
  const __m512i n = _mm512_cvtps_epi32(_mm512_mul_ps(x, _mm512_set1_ps(kLog2E)));
  const __m512 nf = _mm512_cvtepi32_ps(n);
  const __m512 r = _mm512_sub_ps(_mm512_sub_ps(x, _mm512_mul_ps(nf, _mm512_set1_ps(kLn2High))),
                                 _mm512_mul_ps(nf, _mm512_set1_ps(kLn2Low)));
  __m512 e = _mm512_set1_ps(kTaylor[0]);
  for (int t = 1; t < 7; ++t) e = _mm512_add_ps(_mm512_mul_ps(e, r), _mm512_set1_ps(kTaylor[t]));
  const __m512i bits = _mm512_slli_epi32(_mm512_add_epi32(n, _mm512_set1_epi32(127)), 23);
  return _mm512_mul_ps(e, _mm512_castsi512_ps(bits));
}

// |v|: the sign bit cleared.
RADARPR_AVX512_TARGET inline __m512 magnitude(__m512 v, __m512i sign) {
  return _mm512_castsi512_ps(_mm512_and_si512(_mm512_castps_si512(v), sign));
}

// The window product of one candidate, as sixteen partial sums: 32 taps per multiply-add of
// 16-bit pairs; a last half step of 16 taps reads only its 16 bytes (a masked load). kSteps >= 0:
// that many whole steps, known when compiled (the common kernels, unrolled); -1: `length` taps.
// The taps of step s (32 of them; for a last half step, 16 in the lower half: the bytes they meet
// in the upper half are zero).
RADARPR_AVX512_TARGET inline __m512i taps_of_step(const std::int16_t* taps, std::size_t first,
                                                  bool half) {
  return half ? _mm512_castsi256_si512(
                    _mm256_loadu_si256(reinterpret_cast<const __m256i*>(taps + first)))
              : _mm512_loadu_si512(taps + first);
}

// kSteps >= 0: the taps of every step are held in registers (`held`, loaded once per row).
template <int kSteps, bool kHalfStep>
RADARPR_AVX512_TARGET inline __m512i window_product(const std::int16_t* taps, std::size_t length,
                                                    const __m512i* held,
                                                    const unsigned char* window) {
  __m512i total = _mm512_setzero_si512();
  const std::size_t whole = kSteps >= 0 ? static_cast<std::size_t>(kSteps) * 32 : length / 32 * 32;
  for (std::size_t k = 0; k < whole; k += 32) {
    const __m512i bytes =
        _mm512_cvtepu8_epi16(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(window + k)));
    total = _mm512_dpwssd_epi32(total, bytes,
                                kSteps >= 0 ? held[k / 32] : taps_of_step(taps, k, false));
  }
  if (kSteps >= 0 ? kHalfStep : whole < length) {  // the upper 16 words of the step are zero
    const __m512i bytes = _mm512_cvtepu8_epi16(_mm256_maskz_loadu_epi8(0xFFFFu, window + whole));
    total = _mm512_dpwssd_epi32(total, bytes,
                                kSteps >= 0 ? held[whole / 32] : taps_of_step(taps, whole, true));
  }
  return total;
}

// Four candidates' partial sums reduced within each 128-bit lane: lane l of the result holds,
// for a, b, c and d in turn, the sum of their four words of lane l.
RADARPR_AVX512_TARGET inline __m512i interleave_four(__m512i a, __m512i b, __m512i c, __m512i d) {
  const __m512i ab = _mm512_add_epi32(_mm512_unpacklo_epi32(a, b), _mm512_unpackhi_epi32(a, b));
  const __m512i cd = _mm512_add_epi32(_mm512_unpacklo_epi32(c, d), _mm512_unpackhi_epi32(c, d));
  return _mm512_add_epi32(_mm512_unpacklo_epi64(ab, cd), _mm512_unpackhi_epi64(ab, cd));
}

// Sixteen candidates' sums from the interleaved partial sums of their four groups: the four
// 128-bit lanes of each group added, group g landing in lane g.
RADARPR_AVX512_TARGET inline __m512i sixteen_sums(__m512i g0, __m512i g1, __m512i g2, __m512i g3) {
  const __m512i u01 =
      _mm512_add_epi32(_mm512_shuffle_i32x4(g0, g1, 0x44), _mm512_shuffle_i32x4(g0, g1, 0xEE));
  const __m512i u23 =
      _mm512_add_epi32(_mm512_shuffle_i32x4(g2, g3, 0x44), _mm512_shuffle_i32x4(g2, g3, 0xEE));
  return _mm512_add_epi32(_mm512_shuffle_i32x4(u01, u23, 0x88),
                          _mm512_shuffle_i32x4(u01, u23, 0xDD));
}

}  // namespace

NegativePart byte_row_mean_avx512(const unsigned char* x, int count, float& mean) {
  return negative_part_of_bytes(x, count, mean, byte_range_avx512, byte_sums_below_avx512);
}

RADARPR_AVX512_TARGET std::size_t byte_candidates_avx512(const unsigned char* x, int count,
                                                         int least, int sure, int* bins,
                                                         std::uint64_t* passing,
                                                         std::uint64_t* band_words) {
  band_words[count / 64] = 0;  // a whole last word of the row is not written below
  if (least > 255) {
    std::fill(band_words, band_words + count / 64, std::uint64_t{0});
    return 0;
  }
  // x >= least <=> candidate. A sure value of 256 is never reached: its compare runs against 255
  // and is masked off.
  const __m512i candidate = _mm512_set1_epi8(static_cast<char>(least));
  const __m512i passes = _mm512_set1_epi8(static_cast<char>(std::min(sure, 255)));
  const std::uint64_t sure_possible = sure <= 255 ? ~std::uint64_t{0} : 0;
  const __m512i first_bins =
      _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
  std::size_t n = 0;
  for (int r = 0; r < count; r += 64) {
    const __mmask64 lanes = lanes_from(r, count);
    const __m512i v = _mm512_maskz_loadu_epi8(lanes, x + r);
    const std::uint64_t candidates =
        _cvtmask64_u64(_mm512_mask_cmpge_epu8_mask(lanes, v, candidate));
    band_words[r / 64] = 0;
    if (candidates == 0) continue;
    const std::uint64_t sure_bits =
        _cvtmask64_u64(_mm512_mask_cmpge_epu8_mask(lanes, v, passes)) & sure_possible;
    passing[r / 64] |= sure_bits;  // r is a multiple of 64: one whole word
    const std::uint64_t band = candidates & ~sure_bits;
    band_words[r / 64] = band;
    // The band's positions, 16 at a time, compressed into consecutive lanes and stored whole.
    for (int group = 0; group < 4; ++group) {
      const auto mask = static_cast<__mmask16>(band >> (16 * group));
      const __m512i positions = _mm512_add_epi32(first_bins, _mm512_set1_epi32(r + 16 * group));
      _mm512_storeu_si512(bins + n, _mm512_maskz_compress_epi32(mask, positions));
      n += static_cast<std::size_t>(_mm_popcnt_u32(mask));
    }
  }
  // The last candidate repeated over the next 16 entries, so that steps of 16 read bins only.
  if (n > 0) std::fill(bins + n, bins + n + 16, bins[n - 1]);
  return n;
}

namespace {

// The float test of classify_eight_at_a_time on sixteen lanes: the bits of the lanes of `valid`
// that pass and of those that fail.
struct FloatTest {
  __m512 scale;  // -1 / (2 sigma^2)
  __m512 threshold;
  __m512 relative;
  __m512 absolute;
  __m512i sign;
};

struct Verdicts {
  unsigned passes = 0;
  unsigned fails = 0;
};

RADARPR_AVX512_TARGET inline Verdicts test_sixteen(const FloatTest& test, __m512 q, __m512 p,
                                                   __mmask16 valid) {
  const __m512 d = _mm512_sub_ps(q, p);
  const __m512 y = _mm512_sub_ps(
      _mm512_sub_ps(
          q, _mm512_mul_ps(d, exp_of_sixteen(_mm512_mul_ps(_mm512_mul_ps(d, d), test.scale)))),
      _mm512_mul_ps(p, exp_of_sixteen(_mm512_mul_ps(_mm512_mul_ps(p, p), test.scale))));
  const __m512 magnitudes =
      _mm512_add_ps(_mm512_add_ps(_mm512_add_ps(magnitude(q, test.sign), magnitude(d, test.sign)),
                                  magnitude(p, test.sign)),
                    test.threshold);
  const __m512 margin = _mm512_add_ps(test.absolute, _mm512_mul_ps(test.relative, magnitudes));
  return {_cvtmask16_u32(
              _mm512_mask_cmp_ps_mask(valid, y, _mm512_add_ps(test.threshold, margin), _CMP_GT_OQ)),
          _cvtmask16_u32(_mm512_mask_cmp_ps_mask(valid, y, _mm512_sub_ps(test.threshold, margin),
                                                 _CMP_LT_OQ))};
}

// The lanes of a step of sixteen candidates from `first` that exist.
inline __mmask16 lanes_of(std::size_t first, std::size_t n) {
  const std::size_t lanes = first < n ? std::min<std::size_t>(16, n - first) : 0;
  return static_cast<__mmask16>((1u << lanes) - 1u);
}

// Two passes over the candidates: q and p of sixteen at a time into test.detrended and
// test.smoothed, then the float test of thirty-two at a time (two independent chains of
// exponentials, so their latencies overlap).
template <int kSteps, bool kHalfStep>
RADARPR_AVX512_TARGET std::size_t decide(const CandidateTest& test, const int* bins, std::size_t n,
                                         std::uint16_t* chunk_passes, int* undecided) {
  const __m512 mean = _mm512_set1_ps(test.mean);
  const __m512d offset = _mm512_set1_pd(test.offset);
  const __m512d fixed_scale = _mm512_set1_pd(test.scale);
  auto window_of = [&test](int bin) {
    if (bin >= test.radius && bin <= test.last_inside) return test.bytes + (bin - test.radius);
    if (bin < test.radius) return test.left_edge + bin;
    return test.right_edge + (bin - test.right_origin);
  };
  constexpr int kHeld = kSteps >= 0 ? kSteps + (kHalfStep ? 1 : 0) : 0;
  __m512i held[kHeld > 0 ? kHeld : 1];
  for (int step = 0; step < kHeld; ++step) {
    held[step] = taps_of_step(test.taps, static_cast<std::size_t>(step) * 32, step == kSteps);
  }
  alignas(64) std::int32_t values[16] = {};
  for (std::size_t i = 0; i < n; i += 16) {
    const std::size_t lanes = std::min<std::size_t>(16, n - i);
    __m512i groups[4];
    for (std::size_t group = 0; group < 4; ++group) {
      if (4 * group >= lanes) {
        groups[group] = _mm512_setzero_si512();  // no candidate left: masked off later
        continue;
      }
      __m512i products[4];
      for (std::size_t j = 0; j < 4; ++j) {
        // Past the last candidate, bins repeats it (its lanes are masked off later).
        const int bin = bins[i + 4 * group + j];
        values[4 * group + j] = test.bytes[bin];
        products[j] =
            window_product<kSteps, kHalfStep>(test.taps, test.length, held, window_of(bin));
      }
      groups[group] = interleave_four(products[0], products[1], products[2], products[3]);
    }
    const __m512i sum = sixteen_sums(groups[0], groups[1], groups[2], groups[3]);
    // p = float((sum - offset) * scale) and q = float(byte) - mean, as the portable path.
    const __m256 p_low = _mm512_cvtpd_ps(_mm512_mul_pd(
        _mm512_sub_pd(_mm512_cvtepi32_pd(_mm512_castsi512_si256(sum)), offset), fixed_scale));
    const __m256 p_high = _mm512_cvtpd_ps(_mm512_mul_pd(
        _mm512_sub_pd(_mm512_cvtepi32_pd(_mm512_extracti64x4_epi64(sum, 1)), offset), fixed_scale));
    _mm512_storeu_ps(test.smoothed + i, _mm512_castpd_ps(_mm512_insertf64x4(
                                            _mm512_castpd256_pd512(_mm256_castps_pd(p_low)),
                                            _mm256_castps_pd(p_high), 1)));
    _mm512_storeu_ps(test.detrended + i,
                     _mm512_sub_ps(_mm512_cvtepi32_ps(_mm512_load_si512(values)), mean));
  }
  // Lanes past the last step read zeros, not stale values.
  const std::size_t end = (n + 15) / 16 * 16;
  _mm512_storeu_ps(test.smoothed + end, _mm512_setzero_ps());
  _mm512_storeu_ps(test.detrended + end, _mm512_setzero_ps());

  FloatTest float_test;
  float_test.scale = _mm512_set1_ps(static_cast<float>(-1.0 / (2.0 * test.sigma * test.sigma)));
  float_test.threshold = _mm512_set1_ps(static_cast<float>(test.threshold));
  float_test.relative = _mm512_set1_ps(kRelativeMargin);
  float_test.absolute = _mm512_set1_ps(static_cast<float>(2.0 * test.p_error));
  float_test.sign = _mm512_set1_epi32(0x7FFFFFFF);
  std::size_t open = 0;
  for (std::size_t i = 0; i < n; i += 32) {
    const __mmask16 valid[2] = {lanes_of(i, n), lanes_of(i + 16, n)};
    const Verdicts verdicts[2] = {test_sixteen(float_test, _mm512_loadu_ps(test.detrended + i),
                                               _mm512_loadu_ps(test.smoothed + i), valid[0]),
                                  test_sixteen(float_test, _mm512_loadu_ps(test.detrended + i + 16),
                                               _mm512_loadu_ps(test.smoothed + i + 16), valid[1])};
    for (std::size_t k = 0; k < 2; ++k) {
      chunk_passes[i / 16 + k] = static_cast<std::uint16_t>(verdicts[k].passes);
      // The undecided bins compressed into consecutive lanes and stored whole.
      const auto open_bits =
          static_cast<__mmask16>(valid[k] & ~(verdicts[k].passes | verdicts[k].fails));
      _mm512_storeu_si512(undecided + open, _mm512_maskz_compress_epi32(
                                                open_bits, _mm512_loadu_si512(bins + i + 16 * k)));
      open += static_cast<std::size_t>(_mm_popcnt_u32(open_bits));
    }
  }
  return open;
}

}  // namespace

RADARPR_AVX512_TARGET std::size_t decide_candidates_avx512(const CandidateTest& test,
                                                           const int* bins, std::size_t n,
                                                           const std::uint64_t* band_words,
                                                           std::uint16_t* chunk_passes,
                                                           std::uint64_t* passing, int* undecided) {
  // The box kernel (17 taps: one step) and the default Gaussian (sigma 17, 103 taps: three and a
  // half) unrolled; any other length in a loop.
  const std::size_t open =
      test.length == 32    ? decide<1, false>(test, bins, n, chunk_passes, undecided)
      : test.length == 112 ? decide<3, true>(test, bins, n, chunk_passes, undecided)
                           : decide<-1, false>(test, bins, n, chunk_passes, undecided);
  // The verdicts are in the order of the band's set bits: deposit them there, a word at a time.
  const std::size_t chunks = (n + 15) / 16;
  std::fill(chunk_passes + chunks, chunk_passes + chunks + 8, std::uint16_t{0});
  std::size_t offset = 0;
  for (std::size_t w = 0; w <= static_cast<std::size_t>(test.count) / 64; ++w) {
    const std::uint64_t band = band_words[w];
    if (band == 0) continue;
    const std::uint16_t* first = chunk_passes + offset / 16;
    const unsigned shift = offset % 16;
    std::uint64_t low = 0;
    std::uint64_t high = 0;
    std::memcpy(&low, first, sizeof low);
    std::memcpy(&high, first + 4, sizeof high);
    const std::uint64_t verdicts = low >> shift | (high << 1) << (63 - shift);
    passing[w] |= _pdep_u64(verdicts, band);
    offset += static_cast<std::size_t>(_mm_popcnt_u64(band));
  }
  return open;
}

#else

bool has_avx512() {
  return false;
}
NegativePart byte_row_mean_avx512(const unsigned char* x, int count, float& mean) {
  return byte_row_mean(x, count, mean);
}
std::size_t byte_candidates_avx512(const unsigned char*, int, int, int, int*, std::uint64_t*,
                                   std::uint64_t*) {
  throw std::logic_error("cen2018: byte_candidates_avx512 called without AVX-512");
}
std::size_t decide_candidates_avx512(const CandidateTest&, const int*, std::size_t,
                                     const std::uint64_t*, std::uint16_t*, std::uint64_t*, int*) {
  throw std::logic_error("cen2018: decide_candidates_avx512 called without AVX-512");
}

#endif

}  // namespace radarpr::cen2018_detail
