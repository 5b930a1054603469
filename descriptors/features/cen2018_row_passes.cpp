#include "descriptors/features/cen2018_row_passes.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include <opencv2/core/hal/intrin.hpp>

namespace radarpr::cen2018_detail {

NegativePart negative_part(const float* q, int count) {
  NegativePart part;
  int r = 0;
#if CV_SIMD128 && CV_SIMD128_64F
  const cv::v_float32x4 zero = cv::v_setzero_f32();
  cv::v_float64x2 squares_low = cv::v_setzero_f64();
  cv::v_float64x2 squares_high = cv::v_setzero_f64();
  cv::v_int32x4 negatives = cv::v_setzero_s32();
  cv::v_float32x4 largest = zero;
  for (; r + 4 <= count; r += 4) {
    const cv::v_float32x4 v = cv::v_load(q + r);
    const cv::v_float32x4 negative = cv::v_min(v, zero);
    // A float squared is exact in double, so only the additions round (as in a scalar loop).
    const cv::v_float64x2 low = cv::v_cvt_f64(negative);
    const cv::v_float64x2 high = cv::v_cvt_f64_high(negative);
    squares_low += low * low;
    squares_high += high * high;
    negatives -= cv::v_reinterpret_as_s32(v < zero);  // a true lane is all ones, i.e. -1
    largest = cv::v_max(largest, cv::v_abs(v));
  }
  part.sum_of_squares = cv::v_reduce_sum(squares_low + squares_high);
  part.count = cv::v_reduce_sum(negatives);
  part.largest_magnitude = cv::v_reduce_max(largest);
#endif
  for (; r < count; ++r) {
    const double negative = std::min(q[r], 0.0f);
    part.sum_of_squares += negative * negative;
    part.count += q[r] < 0.0f ? 1 : 0;
    part.largest_magnitude = std::max(part.largest_magnitude, std::abs(q[r]));
  }
  return part;
}

namespace {

// Sums over the bytes x < below of a row: their count, sum and sum of squares; and the row's
// smallest and largest byte.
struct ByteSums {
  std::uint64_t count = 0;
  std::uint64_t sum = 0;
  std::uint64_t sum_of_squares = 0;
  unsigned char smallest = 255;
  unsigned char largest = 0;
};

ByteSums byte_sums_below(const unsigned char* x, int count, unsigned char below) {
  ByteSums sums;
  int r = 0;
#if CV_SIMD128
  // 32768 bytes add at most 32768 * 255^2 < 2^31 to the 32-bit lanes.
  constexpr int kChunk = 1 << 15;
  const cv::v_uint8x16 bound = cv::v_setall_u8(below);
  const cv::v_uint8x16 one_byte = cv::v_setall_u8(1);
  const cv::v_int16x8 ones = cv::v_setall_s16(1);
  cv::v_uint8x16 smallest = cv::v_setall_u8(255);
  cv::v_uint8x16 largest = cv::v_setzero_u8();
  while (r + 16 <= count) {
    const int chunk_end = std::min(count, r + kChunk);
    cv::v_int32x4 counts = cv::v_setzero_s32();
    cv::v_int32x4 values = cv::v_setzero_s32();
    cv::v_int32x4 squares = cv::v_setzero_s32();
    for (; r + 16 <= chunk_end; r += 16) {
      const cv::v_uint8x16 v = cv::v_load(x + r);
      const cv::v_uint8x16 is_below = v < bound;  // all ones where x < below
      cv::v_uint16x8 low;
      cv::v_uint16x8 high;
      cv::v_expand(v & is_below, low, high);
      const cv::v_int16x8 a = cv::v_reinterpret_as_s16(low);
      const cv::v_int16x8 b = cv::v_reinterpret_as_s16(high);
      squares += cv::v_dotprod(a, a) + cv::v_dotprod(b, b);
      values += cv::v_dotprod(a, ones) + cv::v_dotprod(b, ones);
      cv::v_expand(is_below & one_byte, low, high);
      counts += cv::v_dotprod(cv::v_reinterpret_as_s16(low + high), ones);
      smallest = cv::v_min(smallest, v);
      largest = cv::v_max(largest, v);
    }
    sums.count += static_cast<std::uint64_t>(cv::v_reduce_sum(counts));
    sums.sum += static_cast<std::uint64_t>(cv::v_reduce_sum(values));
    sums.sum_of_squares += static_cast<std::uint64_t>(cv::v_reduce_sum(squares));
  }
  sums.smallest = static_cast<unsigned char>(cv::v_reduce_min(smallest));
  sums.largest = static_cast<unsigned char>(cv::v_reduce_max(largest));
#endif
  for (; r < count; ++r) {
    const std::uint64_t v = x[r];
    if (x[r] < below) {
      ++sums.count;
      sums.sum += v;
      sums.sum_of_squares += v * v;
    }
    sums.smallest = std::min(sums.smallest, x[r]);
    sums.largest = std::max(sums.largest, x[r]);
  }
  return sums;
}

}  // namespace

NegativePart byte_row_mean(const unsigned char* x, int count, float& mean) {
  // An integer sum is exact. 16 bytes at a time through a sum of absolute differences (one
  // instruction on SSE2), which widening additions of single bytes are not.
  std::uint64_t total = 0;
  int r = 0;
#if CV_SIMD128
  for (; r + 16 <= count; r += 16) total += cv::v_reduce_sum(cv::v_load(x + r));
#endif
  for (; r < count; ++r) total += x[r];
  mean = static_cast<float>(static_cast<double>(total) / count);

  // x < mean <=> x < ceil(mean), at most 255.
  const auto below = static_cast<unsigned char>(std::ceil(mean));
  const ByteSums sums = byte_sums_below(x, count, below);
  const double m = mean;
  NegativePart part;
  part.count = static_cast<int>(sums.count);
  part.sum_of_squares = std::max(0.0, static_cast<double>(sums.sum_of_squares) -
                                          2.0 * m * static_cast<double>(sums.sum) +
                                          static_cast<double>(sums.count) * m * m);
  part.largest_magnitude = static_cast<float>(std::max(sums.largest - m, m - sums.smallest));
  return part;
}

NegativePart subtract_byte_row_mean(const unsigned char* x, int count, float* q, float& mean) {
  const NegativePart part = byte_row_mean(x, count, mean);
  for (int i = 0; i < count; ++i) q[i] = static_cast<float>(x[i]) - mean;
  return part;
}

std::size_t bins_above(const float* q, int count, float bound, int* bins) {
  std::size_t n = 0;
  int r = 0;
#if CV_SIMD128
  const cv::v_float32x4 threshold = cv::v_setall_f32(bound);
  for (; r + 16 <= count; r += 16) {
    auto mask = static_cast<unsigned>(cv::v_signmask(cv::v_load(q + r) > threshold) |
                                      cv::v_signmask(cv::v_load(q + r + 4) > threshold) << 4 |
                                      cv::v_signmask(cv::v_load(q + r + 8) > threshold) << 8 |
                                      cv::v_signmask(cv::v_load(q + r + 12) > threshold) << 12);
    for (; mask != 0; mask &= mask - 1) bins[n++] = r + std::countr_zero(mask);
  }
#endif
  for (; r < count; ++r) {
    if (q[r] > bound) bins[n++] = r;
  }
  return n;
}

namespace {

// For each 8-bit mask, the positions of its set bits, lowest first (the rest zero).
struct SetBitTable {
  unsigned char positions[256][8] = {};
  constexpr SetBitTable() {
    for (int mask = 0; mask < 256; ++mask) {
      int n = 0;
      for (int bit = 0; bit < 8; ++bit) {
        if ((mask >> bit & 1) != 0) positions[mask][n++] = static_cast<unsigned char>(bit);
      }
    }
  }
};
constexpr SetBitTable kSetBits;

// Writes base + the set-bit positions of the 8-bit `mask` to out (always 8 values, of which the
// first popcount(mask) count) and returns popcount(mask).
inline std::size_t write_set_bits(unsigned mask, int base, int* out) {
  const unsigned char* positions = kSetBits.positions[mask];
#if CV_SIMD128
  const cv::v_int32x4 offset = cv::v_setall_s32(base);
  cv::v_store(out, cv::v_reinterpret_as_s32(cv::v_load_expand_q(positions)) + offset);
  cv::v_store(out + 4, cv::v_reinterpret_as_s32(cv::v_load_expand_q(positions + 4)) + offset);
#else
  for (int k = 0; k < 8; ++k) out[k] = base + positions[k];
#endif
  return static_cast<std::size_t>(std::popcount(mask));
}

}  // namespace

std::size_t bytes_at_least(const unsigned char* x, int count, int least, int* bins) {
  if (least > 255) return 0;
  std::size_t n = 0;
  int r = 0;
#if CV_SIMD128
  // x >= least <=> max(x, least) == x, for unsigned bytes.
  const cv::v_uint8x16 threshold = cv::v_setall_u8(static_cast<unsigned char>(least));
  for (; r + 16 <= count; r += 16) {
    const cv::v_uint8x16 v = cv::v_load(x + r);
    const auto mask = static_cast<unsigned>(cv::v_signmask(cv::v_max(v, threshold) == v));
    if (mask == 0) continue;
    n += write_set_bits(mask & 0xFFu, r, bins + n);
    n += write_set_bits(mask >> 8, r + 8, bins + n);
  }
#endif
  for (; r < count; ++r) {
    if (x[r] >= least) bins[n++] = r;
  }
  return n;
}

float dot_product(const float* a, const float* b, std::size_t length) {
  float sum = 0.0f;
  std::size_t k = 0;
#if CV_SIMD128
  cv::v_float32x4 first = cv::v_setzero_f32();
  cv::v_float32x4 second = cv::v_setzero_f32();
  for (; k + 8 <= length; k += 8) {
    first += cv::v_load(a + k) * cv::v_load(b + k);
    second += cv::v_load(a + k + 4) * cv::v_load(b + k + 4);
  }
  sum = cv::v_reduce_sum(first + second);
#endif
  for (; k < length; ++k) sum += a[k] * b[k];
  return sum;
}

}  // namespace radarpr::cen2018_detail
