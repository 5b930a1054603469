#include "descriptors/features/cen2018_row_passes.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "datasets/cpu_features.hpp"

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace radarpr::cen2018_detail {

// The sums over whole steps of four bins run in four lanes, bin r in lane r % 4, and the lanes
// are added as (0 + 2) + (1 + 3) at the end: SSE2 where the processor has it, plain code in the
// same order elsewhere, so the rounded sums are the same on every processor.
NegativePart negative_part(const float* q, int count) {
  NegativePart part;
  int r = 0;
  if (count >= 4) {
#if defined(__SSE2__)
    const __m128 zero = _mm_setzero_ps();
    const __m128 magnitude_bits = _mm_castsi128_ps(_mm_set1_epi32(0x7fffffff));
    __m128d squares_low = _mm_setzero_pd();   // lanes 0 and 1
    __m128d squares_high = _mm_setzero_pd();  // lanes 2 and 3
    __m128i negatives = _mm_setzero_si128();
    __m128 largest = zero;
    for (; r + 4 <= count; r += 4) {
      const __m128 v = _mm_loadu_ps(q + r);
      const __m128 negative = _mm_min_ps(v, zero);
      // A float squared is exact in double, so only the additions round (as in a scalar loop).
      const __m128d low = _mm_cvtps_pd(negative);
      const __m128d high = _mm_cvtps_pd(_mm_movehl_ps(negative, negative));
      squares_low = _mm_add_pd(squares_low, _mm_mul_pd(low, low));
      squares_high = _mm_add_pd(squares_high, _mm_mul_pd(high, high));
      // A true lane is all ones, i.e. -1.
      negatives = _mm_sub_epi32(negatives, _mm_castps_si128(_mm_cmplt_ps(v, zero)));
      largest = _mm_max_ps(largest, _mm_and_ps(v, magnitude_bits));
    }
    alignas(16) double squares[2];
    _mm_store_pd(squares, _mm_add_pd(squares_low, squares_high));
    alignas(16) std::int32_t counts[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(counts), negatives);
    alignas(16) float largests[4];
    _mm_store_ps(largests, largest);
    part.sum_of_squares = squares[0] + squares[1];
    part.count = counts[0] + counts[1] + counts[2] + counts[3];
    part.largest_magnitude =
        std::max(std::max(largests[0], largests[1]), std::max(largests[2], largests[3]));
#else
    double squares[4] = {};
    int counts[4] = {};
    float largests[4] = {};
    for (; r + 4 <= count; r += 4) {
      for (int lane = 0; lane < 4; ++lane) {
        const float v = q[r + lane];
        const double negative = std::min(v, 0.0f);
        squares[lane] += negative * negative;
        counts[lane] += v < 0.0f ? 1 : 0;
        largests[lane] = std::max(largests[lane], std::abs(v));
      }
    }
    part.sum_of_squares = (squares[0] + squares[2]) + (squares[1] + squares[3]);
    part.count = counts[0] + counts[1] + counts[2] + counts[3];
    part.largest_magnitude =
        std::max(std::max(largests[0], largests[1]), std::max(largests[2], largests[3]));
#endif
  }
  for (; r < count; ++r) {
    const double negative = std::min(q[r], 0.0f);
    part.sum_of_squares += negative * negative;
    part.count += q[r] < 0.0f ? 1 : 0;
    part.largest_magnitude = std::max(part.largest_magnitude, std::abs(q[r]));
  }
  return part;
}

namespace {

#if defined(__SSE2__)
// Sums of bytes through sums of absolute differences against zero (psadbw: 16 bytes into two
// 64-bit lanes in one instruction), squares through 16-bit multiply-adds.
std::uint64_t sum_of_lanes(__m128i v) {
  return static_cast<std::uint64_t>(_mm_cvtsi128_si64(v)) +
         static_cast<std::uint64_t>(_mm_cvtsi128_si64(_mm_unpackhi_epi64(v, v)));
}
#endif

}  // namespace

ByteSums byte_sums_below(const unsigned char* x, int count, unsigned char below) {
  ByteSums sums;
  if (below == 0) return sums;
  int r = 0;
#if defined(__SSE2__)
  // 8192 steps add at most 8192 * 4 * 255^2 < 2^31 to each 32-bit lane of squares.
  constexpr int kChunk = 8192 * 16;
  const __m128i zero = _mm_setzero_si128();
  const __m128i one = _mm_set1_epi8(1);
  const __m128i limit = _mm_set1_epi8(static_cast<char>(below - 1));
  __m128i values = zero;
  __m128i counts = zero;
  while (r + 16 <= count) {
    const int chunk_end = std::min(count, r + kChunk);
    __m128i squares = zero;
    for (; r + 16 <= chunk_end; r += 16) {
      const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(x + r));
      const __m128i is_below = _mm_cmpeq_epi8(_mm_min_epu8(v, limit), v);  // x <= below - 1
      const __m128i kept = _mm_and_si128(v, is_below);
      values = _mm_add_epi64(values, _mm_sad_epu8(kept, zero));
      counts = _mm_add_epi64(counts, _mm_sad_epu8(_mm_and_si128(is_below, one), zero));
      const __m128i low = _mm_unpacklo_epi8(kept, zero);
      const __m128i high = _mm_unpackhi_epi8(kept, zero);
      squares = _mm_add_epi32(squares,
                              _mm_add_epi32(_mm_madd_epi16(low, low), _mm_madd_epi16(high, high)));
    }
    alignas(16) std::uint32_t lanes[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(lanes), squares);
    sums.sum_of_squares += std::uint64_t{lanes[0]} + lanes[1] + lanes[2] + lanes[3];
  }
  sums.sum = sum_of_lanes(values);
  sums.count = sum_of_lanes(counts);
#endif
  for (; r < count; ++r) {
    const std::uint64_t v = x[r];
    if (x[r] < below) {
      ++sums.count;
      sums.sum += v;
      sums.sum_of_squares += v * v;
    }
  }
  return sums;
}

ByteRange byte_range(const unsigned char* x, int count) {
  ByteRange range;
  int r = 0;
#if defined(__SSE2__)
  const __m128i zero = _mm_setzero_si128();
  __m128i total = zero;
  __m128i smallest = _mm_set1_epi8(static_cast<char>(255));
  __m128i largest = zero;
  for (; r + 16 <= count; r += 16) {
    const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(x + r));
    total = _mm_add_epi64(total, _mm_sad_epu8(v, zero));
    smallest = _mm_min_epu8(smallest, v);
    largest = _mm_max_epu8(largest, v);
  }
  range.sum = sum_of_lanes(total);
  alignas(16) unsigned char lanes[2][16];
  _mm_store_si128(reinterpret_cast<__m128i*>(lanes[0]), smallest);
  _mm_store_si128(reinterpret_cast<__m128i*>(lanes[1]), largest);
  for (int i = 0; i < 16; ++i) {
    range.smallest = std::min(range.smallest, lanes[0][i]);
    range.largest = std::max(range.largest, lanes[1][i]);
  }
#endif
  for (; r < count; ++r) {
    range.sum += x[r];
    range.smallest = std::min(range.smallest, x[r]);
    range.largest = std::max(range.largest, x[r]);
  }
  return range;
}

NegativePart negative_part_of_bytes(const unsigned char* x, int count, float& mean,
                                    ByteRange (*range_of)(const unsigned char*, int),
                                    ByteSums (*sums_below)(const unsigned char*, int,
                                                           unsigned char)) {
  // An integer sum is exact.
  const ByteRange range = range_of(x, count);
  mean = static_cast<float>(static_cast<double>(range.sum) / count);

  // x < mean <=> x < ceil(mean), at most 255.
  const auto below = static_cast<unsigned char>(std::ceil(mean));
  const ByteSums sums = sums_below(x, count, below);
  const double m = mean;
  NegativePart part;
  part.count = static_cast<int>(sums.count);
  part.sum_of_squares = std::max(0.0, static_cast<double>(sums.sum_of_squares) -
                                          2.0 * m * static_cast<double>(sums.sum) +
                                          static_cast<double>(sums.count) * m * m);
  part.largest_magnitude = static_cast<float>(std::max(range.largest - m, m - range.smallest));
  return part;
}

NegativePart byte_row_mean(const unsigned char* x, int count, float& mean) {
  return negative_part_of_bytes(x, count, mean, byte_range, byte_sums_below);
}

NegativePart subtract_byte_row_mean(const unsigned char* x, int count, float* q, float& mean) {
  const NegativePart part = byte_row_mean(x, count, mean);
  for (int i = 0; i < count; ++i) q[i] = static_cast<float>(x[i]) - mean;
  return part;
}

std::size_t bins_above(const float* q, int count, float bound, int* bins) {
  std::size_t n = 0;
  int r = 0;
#if defined(__SSE2__)
  const __m128 threshold = _mm_set1_ps(bound);
  const auto above = [&](int first) {
    return static_cast<unsigned>(_mm_movemask_ps(_mm_cmpgt_ps(_mm_loadu_ps(q + first), threshold)));
  };
  for (; r + 16 <= count; r += 16) {
    unsigned mask = above(r) | above(r + 4) << 4 | above(r + 8) << 8 | above(r + 12) << 12;
    for (; mask != 0; mask &= mask - 1) bins[n++] = r + std::countr_zero(mask);
  }
#endif
  for (; r < count; ++r) {
    if (q[r] > bound) bins[n++] = r;
  }
  return n;
}

namespace {

// For each 8-bit mask, the positions of its set bits, lowest first (the rest zero), and their
// number (std::popcount is a library call on baseline x86-64).
struct SetBitTable {
  unsigned char positions[256][8] = {};
  unsigned char counts[256] = {};
  constexpr SetBitTable() {
    for (int mask = 0; mask < 256; ++mask) {
      int n = 0;
      for (int bit = 0; bit < 8; ++bit) {
        if ((mask >> bit & 1) != 0) positions[mask][n++] = static_cast<unsigned char>(bit);
      }
      counts[mask] = static_cast<unsigned char>(n);
    }
  }
};
constexpr SetBitTable kSetBits;

// Writes base + the set-bit positions of the 8-bit `mask` to out (always 8 values, of which the
// first popcount(mask) count) and returns popcount(mask).
inline std::size_t write_set_bits(unsigned mask, int base, int* out) {
  const unsigned char* positions = kSetBits.positions[mask];
#if defined(__SSE2__)
  // The eight positions widened to 32 bits (bytes to 16, then to 32, against zeros).
  const __m128i zero = _mm_setzero_si128();
  const __m128i words =
      _mm_unpacklo_epi8(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(positions)), zero);
  const __m128i offset = _mm_set1_epi32(base);
  _mm_storeu_si128(reinterpret_cast<__m128i*>(out),
                   _mm_add_epi32(_mm_unpacklo_epi16(words, zero), offset));
  _mm_storeu_si128(reinterpret_cast<__m128i*>(out + 4),
                   _mm_add_epi32(_mm_unpackhi_epi16(words, zero), offset));
#else
  for (int k = 0; k < 8; ++k) out[k] = base + positions[k];
#endif
  return kSetBits.counts[mask];
}

}  // namespace

std::size_t byte_candidates(const unsigned char* x, int count, int least, int sure, int* bins,
                            std::uint64_t* passing) {
  if (least > 255) return 0;
  sure = std::min(sure, 256);
  std::size_t n = 0;
  int r = 0;
#if defined(__SSE2__)
  // x >= least <=> max(x, least) == x, for unsigned bytes. A sure value of 256 is never reached:
  // its compare runs against 255 and is masked off.
  const __m128i candidate = _mm_set1_epi8(static_cast<char>(least));
  const __m128i passes = _mm_set1_epi8(static_cast<char>(std::min(sure, 255)));
  const unsigned sure_possible = sure <= 255 ? 0xFFFFu : 0u;
  const auto at_least = [](__m128i v, __m128i value) {
    return static_cast<unsigned>(_mm_movemask_epi8(_mm_cmpeq_epi8(_mm_max_epu8(v, value), v)));
  };
  for (; r + 16 <= count; r += 16) {
    const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(x + r));
    const unsigned candidates = at_least(v, candidate);
    if (candidates == 0) continue;
    const unsigned sure_bits = at_least(v, passes) & sure_possible;
    passing[r / 64] |= static_cast<std::uint64_t>(sure_bits) << (r % 64);
    const unsigned band = candidates & ~sure_bits;
    n += write_set_bits(band & 0xFFu, r, bins + n);
    n += write_set_bits(band >> 8, r + 8, bins + n);
  }
#endif
  for (; r < count; ++r) {
    if (x[r] >= sure) {
      passing[r / 64] |= std::uint64_t{1} << (r % 64);
    } else if (x[r] >= least) {
      bins[n++] = r;
    }
  }
  return n;
}

namespace {

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define RADARPR_CEN2018_AVX2 1
__attribute__((target("avx2"))) void window_dot_products_avx2(const std::int16_t* taps,
                                                              std::size_t length,
                                                              const unsigned char* const* windows,
                                                              std::size_t n, std::int32_t* sums) {
  for (std::size_t i = 0; i < n; ++i) {
    const unsigned char* x = windows[i];
    __m256i total = _mm256_setzero_si256();
    for (std::size_t k = 0; k < length; k += 16) {
      const __m256i bytes =
          _mm256_cvtepu8_epi16(_mm_loadu_si128(reinterpret_cast<const __m128i*>(x + k)));
      const __m256i weights = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(taps + k));
      total = _mm256_add_epi32(total, _mm256_madd_epi16(bytes, weights));
    }
    __m128i sum = _mm_add_epi32(_mm256_castsi256_si128(total), _mm256_extracti128_si256(total, 1));
    sum = _mm_add_epi32(sum, _mm_shuffle_epi32(sum, 0x4E));
    sum = _mm_add_epi32(sum, _mm_shuffle_epi32(sum, 0xB1));
    sums[i] = _mm_cvtsi128_si32(sum);
  }
}

bool has_avx2() {
  static const bool available = cpu_features().avx2;
  return available;
}
#endif

}  // namespace

void window_dot_products(const std::int16_t* taps, std::size_t length,
                         const unsigned char* const* windows, std::size_t n, std::int32_t* sums) {
#if defined(RADARPR_CEN2018_AVX2)
  if (has_avx2()) {
    window_dot_products_avx2(taps, length, windows, n, sums);
    return;
  }
#endif
  for (std::size_t i = 0; i < n; ++i) sums[i] = window_dot_product(taps, windows[i], length);
}

// Whole steps of eight products in two four-lane sums (product k in lane k % 4 of the first sum
// for k % 8 < 4, of the second otherwise), added lane by lane, then as (0 + 2) + (1 + 3); the
// rest one by one. SSE2 where the processor has it, plain code in the same order elsewhere.
float dot_product(const float* a, const float* b, std::size_t length) {
  float sum = 0.0f;
  std::size_t k = 0;
  if (length >= 8) {
#if defined(__SSE2__)
    __m128 first = _mm_setzero_ps();
    __m128 second = _mm_setzero_ps();
    for (; k + 8 <= length; k += 8) {
      first = _mm_add_ps(first, _mm_mul_ps(_mm_loadu_ps(a + k), _mm_loadu_ps(b + k)));
      second = _mm_add_ps(second, _mm_mul_ps(_mm_loadu_ps(a + k + 4), _mm_loadu_ps(b + k + 4)));
    }
    alignas(16) float lanes[4];
    _mm_store_ps(lanes, _mm_add_ps(first, second));
#else
    float first[4] = {};
    float second[4] = {};
    for (; k + 8 <= length; k += 8) {
      for (std::size_t lane = 0; lane < 4; ++lane) {
        first[lane] += a[k + lane] * b[k + lane];
        second[lane] += a[k + 4 + lane] * b[k + 4 + lane];
      }
    }
    float lanes[4];
    for (std::size_t lane = 0; lane < 4; ++lane) lanes[lane] = first[lane] + second[lane];
#endif
    sum = (lanes[0] + lanes[2]) + (lanes[1] + lanes[3]);
  }
  for (; k < length; ++k) sum += a[k] * b[k];
  return sum;
}

}  // namespace radarpr::cen2018_detail
