#pragma once

#include <cstddef>
#include <cstdint>

namespace radarpr::cen2018_detail {

// The response test of the Cen 2018 extraction (cen2018.cpp) at its candidate bins, in float32
// SIMD, four bins per step. y = q - d G(d) - p G(p) with d = q - p and G(x) = exp(-x^2 / (2
// sigma^2)) is evaluated with a polynomial exponential; a bin whose approximate y lies further
// from the threshold than the error bound is decided here, the others are left to the exact
// double-precision computation, so the features are those of the exact computation.

enum class Verdict : std::uint8_t { fails = 0, passes = 1, undecided = 2 };

// exp(x) for x <= 0 in float32 (inputs below -87 give exp(-87)): relative error below 1e-6 (the
// bound the verdicts assume is ten times that). Exposed for its test.
float approximate_exp(float x);

// For i < count: the verdict on y(q[i], p[i]) > threshold, where p[i] is within p_error of the
// value the exact computation uses (0 when p is that value). |dy/dp| <= 2 everywhere, so an error
// in p moves y by at most twice as much. A bin whose q or p is not finite stays undecided.
void classify_responses(const float* q, const float* p, std::size_t count, double sigma,
                        double threshold, double p_error, Verdict* verdicts);

}  // namespace radarpr::cen2018_detail
