#pragma once

#include <cstddef>
#include <vector>

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

// Appends to `bins` every r < count with q[r] > bound, increasing. Most rows have few such bins:
// this tests 16 bins per step.
void append_bins_above(const float* q, int count, float bound, std::vector<int>& bins);

// Appends to `bins` every r < count with x[r] >= least, increasing: the candidate test of a uint8
// row on its bytes, 16 bins per step (16 bytes against 16 floats of q).
void append_bytes_at_least(const unsigned char* x, int count, int least, std::vector<int>& bins);

// sum over k < length of a[k] * b[k], in float, in a fixed order (the result does not depend on
// where it is called from).
float dot_product(const float* a, const float* b, std::size_t length);

}  // namespace radarpr::cen2018_detail
