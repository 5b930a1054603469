#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace radarpr::cen2018_detail {

// The passes of the Cen 2018 extraction (cen2018.cpp) that touch every bin of every row: they
// set its speed, so they are written to vectorise - integer loops the compiler vectorises, and
// SSE2 intrinsics where it would not (float max, float-to-double sums, without -ffast-math), with
// plain code computing the same sums in the same order on other processors.

// Over a detrended row q: the squares of its negative part min(q, 0) summed in double (the
// definition of sigma_a), the number of negative bins, and the largest |q|.
struct NegativePart {
  double sum_of_squares = 0.0;
  int count = 0;
  float largest_magnitude = 0.0f;
};
NegativePart negative_part(const float* q, int count);

// Over a uint8 row: the sum of its bytes, the smallest and the largest.
struct ByteRange {
  std::uint64_t sum = 0;
  unsigned char smallest = 255;
  unsigned char largest = 0;
};
ByteRange byte_range(const unsigned char* x, int count);

// Over the bytes x < below of a uint8 row: their count, sum and sum of squares.
struct ByteSums {
  std::uint64_t count = 0;
  std::uint64_t sum = 0;
  std::uint64_t sum_of_squares = 0;
};
ByteSums byte_sums_below(const unsigned char* x, int count, unsigned char below);

// byte_row_mean from the two passes above (or faster versions of them: exact integers either way).
NegativePart negative_part_of_bytes(const unsigned char* x, int count, float& mean,
                                    ByteRange (*range)(const unsigned char*, int),
                                    ByteSums (*sums_below)(const unsigned char*, int,
                                                           unsigned char));

// The row-mean detrend of a uint8 row: q[r] = x[r] - mean in float32, the mean rounded to float as
// for a float row, so q is the same as for the row converted to float. Returns negative_part(q)
// from exact integer sums instead of a pass over q: q < 0 exactly where x < ceil(mean), and there
// q = x - mean without rounding (|q| <= mean), so the sum of squares is
// S2 - 2 mean S1 + n mean^2 over those bins (within 1e-12 relative of summing the squares).
// `mean` receives the float mean subtracted.
NegativePart subtract_byte_row_mean(const unsigned char* x, int count, float* q, float& mean);

// The same without writing q: the mean and the negative part only.
NegativePart byte_row_mean(const unsigned char* x, int count, float& mean);

// sum over k < length of taps[k] * x[k] in exact integer arithmetic, 16 bytes per step (two
// multiply-adds of 16-bit pairs on SSE2); `length` is a multiple of 16 and the sum must fit in 31
// bits. Inline: it runs once per candidate bin.
inline std::int32_t window_dot_product(const std::int16_t* taps, const unsigned char* x,
                                       std::size_t length) {
#if defined(__SSE2__)
  const __m128i zero = _mm_setzero_si128();
  __m128i first = zero;
  __m128i second = zero;
  for (std::size_t k = 0; k < length; k += 16) {
    const __m128i bytes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(x + k));
    const __m128i low = _mm_unpacklo_epi8(bytes, zero);  // the bytes widened to 16 bits
    const __m128i high = _mm_unpackhi_epi8(bytes, zero);
    first = _mm_add_epi32(
        first, _mm_madd_epi16(low, _mm_loadu_si128(reinterpret_cast<const __m128i*>(taps + k))));
    second = _mm_add_epi32(
        second,
        _mm_madd_epi16(high, _mm_loadu_si128(reinterpret_cast<const __m128i*>(taps + k + 8))));
  }
  __m128i total = _mm_add_epi32(first, second);
  total = _mm_add_epi32(total, _mm_shuffle_epi32(total, 0x4E));  // lanes (2, 3, 0, 1)
  total = _mm_add_epi32(total, _mm_shuffle_epi32(total, 0xB1));  // lanes (1, 0, 3, 2)
  return _mm_cvtsi128_si32(total);
#else
  std::int32_t sum = 0;
  for (std::size_t k = 0; k < length; ++k) sum += taps[k] * x[k];
  return sum;
#endif
}

// For each i < n: sums[i] = window_dot_product(taps, windows[i], length). Where the processor has
// AVX2 (checked once at run time) 16 bytes per multiply-add instead of 8: exact integers, so the
// sums are the same either way.
void window_dot_products(const std::int16_t* taps, std::size_t length,
                         const unsigned char* const* windows, std::size_t n, std::int32_t* sums);

// Writes to `bins` every r < count with q[r] > bound, increasing, and returns how many. `bins` has
// room for count + 16. Most rows have few such bins: this tests 16 bins per step.
std::size_t bins_above(const float* q, int count, float bound, int* bins);

// The candidate test of a uint8 row on its bytes, 16 bins per step (16 bytes against 16 floats of
// q): every r < count with x[r] >= sure sets bit r of `passing` (zeroed, count / 64 + 1 words);
// every other r with x[r] >= least is written to `bins`, increasing, without a branch per bin.
// Returns how many; `bins` has room for count + 16.
std::size_t byte_candidates(const unsigned char* x, int count, int least, int sure, int* bins,
                            std::uint64_t* passing);

// sum over k < length of a[k] * b[k], in float, in a fixed order (the result does not depend on
// where it is called from).
float dot_product(const float* a, const float* b, std::size_t length);

}  // namespace radarpr::cen2018_detail
