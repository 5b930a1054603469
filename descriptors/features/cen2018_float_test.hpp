#pragma once

// The constants of Cen 2018's float32 candidate test, shared by every code path that runs it (the
// baseline and AVX2 paths in cen2018_responses.cpp, the AVX-512 path in cen2018_avx512.cpp): the
// error bound the verdicts rest on holds only for this exponential and this margin.
namespace radarpr::cen2018_detail {

// exp(x) = 2^n e^r with n = round(x log2 e) and r = x - n ln 2 (ln 2 split in two so that n ln 2
// is exact to float precision), |r| <= ln(2) / 2; e^r by its Taylor polynomial of degree 6, whose
// truncation error is below 1.3e-7 there.
inline constexpr float kLog2E = 1.44269504088896341f;
inline constexpr float kLn2High = 0.693359375f;  // 8 significant bits: n * kLn2High is exact
inline constexpr float kLn2Low = -2.12194440e-4f;
inline constexpr float kLowestArgument = -87.0f;  // 2^-126 <= exp(-87): the result stays normal
inline constexpr float kTaylor[] = {1.0f / 720, 1.0f / 120, 1.0f / 24, 1.0f / 6, 0.5f, 1.0f, 1.0f};

// The relative error the verdicts allow for the whole float evaluation of y: the exponential
// (below 1e-6) and a few roundings of 6e-8 each, with a margin of five.
inline constexpr float kRelativeMargin = 1e-5f;

}  // namespace radarpr::cen2018_detail
