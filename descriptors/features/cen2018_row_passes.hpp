#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <opencv2/core/hal/intrin.hpp>

namespace radarpr::cen2018_detail {

// The passes of the Cen 2018 extraction (cen2018.cpp) that touch every bin of every row: they
// set its speed, so they are written to vectorise - integer loops the compiler vectorises, and
// OpenCV's universal intrinsics (SSE2, NEON, ...) where it would not (float max, float-to-double
// sums, without -ffast-math).

// Over a detrended row q: the squares of its negative part min(q, 0) summed in double (the
// definition of sigma_a), the number of negative bins, and the largest |q|.
struct NegativePart {
  double sum_of_squares = 0.0;
  int count = 0;
  float largest_magnitude = 0.0f;
};
NegativePart negative_part(const float* q, int count);

// The row-mean detrend of a uint8 row: q[r] = x[r] - mean in float32, the mean rounded to float as
// for a float row, so q is the same as for the row converted to float. Returns negative_part(q)
// from exact integer sums instead of a pass over q: q < 0 exactly where x < ceil(mean), and there
// q = x - mean without rounding (|q| <= mean), so the sum of squares is
// S2 - 2 mean S1 + n mean^2 over those bins (within 1e-12 relative of summing the squares).
// `mean` receives the float mean subtracted.
NegativePart subtract_byte_row_mean(const unsigned char* x, int count, float* q, float& mean);

// The same without writing q: the mean and the negative part only.
NegativePart byte_row_mean(const unsigned char* x, int count, float& mean);

// The sum of x[0] .. x[length - 1], 16 bytes per step (inline: it runs once per candidate bin).
inline std::uint32_t window_byte_sum(const unsigned char* x, std::size_t length) {
  std::uint32_t sum = 0;
  std::size_t k = 0;
#if CV_SIMD128
  for (; k + 16 <= length; k += 16) sum += cv::v_reduce_sum(cv::v_load(x + k));
#endif
  for (; k < length; ++k) sum += x[k];
  return sum;
}

// Writes to `bins` every r < count with q[r] > bound, increasing, and returns how many. `bins` has
// room for count + 16. Most rows have few such bins: this tests 16 bins per step.
std::size_t bins_above(const float* q, int count, float bound, int* bins);

// Writes to `bins` every r < count with x[r] >= least, increasing, and returns how many: the
// candidate test of a uint8 row on its bytes, 16 bins per step (16 bytes against 16 floats of q),
// the bins of a step written without a branch per bin. `bins` has room for count + 16.
std::size_t bytes_at_least(const unsigned char* x, int count, int least, int* bins);

// sum over k < length of a[k] * b[k], in float, in a fixed order (the result does not depend on
// where it is called from).
float dot_product(const float* a, const float* b, std::size_t length);

}  // namespace radarpr::cen2018_detail
