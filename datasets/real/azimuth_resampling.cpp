#include "datasets/real/azimuth_resampling.hpp"

#include <cmath>
#include <cstdint>
#include <stdexcept>

#include <fmt/format.h>

namespace radarpr {
namespace {

// (1 - f) low + f high as OpenCV's vectorised cv::addWeighted computes it for bytes, which the
// results were made with: float weights, low * (1 - f) + (high * f rounded to float) rounded
// once (a fused multiply-add), then to the nearest integer with ties to even. Here the sum is
// taken in double, where it is exact (the terms are below 2^8 and their lowest bits no finer than
// 2^-25 min(f, 1 - f), and both weights are at least 1/azimuths when not 0), so one rounding to
// float gives the fused result; std::fma would be a library call per pixel on baseline x86-64.
// tests/datasets/scan_window_test.cpp checks every (low, high) pair against cv::addWeighted.
void blend_rows(const std::uint8_t* low, const std::uint8_t* high, double f, int count,
                std::uint8_t* out) {
  const auto low_weight = static_cast<double>(static_cast<float>(1.0 - f));
  const auto high_weight = static_cast<float>(f);
  for (int c = 0; c < count; ++c) {
    const float high_part = static_cast<float>(high[c]) * high_weight;
    const auto sum = static_cast<float>(low[c] * low_weight + static_cast<double>(high_part));
    // Adding and taking away 1.5 * 2^23 rounds a float below 2^22 to the nearest integer, ties
    // to even, in two vectorisable operations (std::nearbyint is a library call on baseline
    // x86-64). Both weights are in [0, 1] and sum to 1 up to rounding: the value is in [0, 255].
    constexpr float kRoundingShift = 12582912.0f;
    out[c] = static_cast<std::uint8_t>((sum + kRoundingShift) - kRoundingShift);
  }
}

}  // namespace

ByteImage resample_azimuth_rows(const ByteImage& power, int azimuths) {
  if (power.empty()) {
    throw std::invalid_argument("resample_azimuth_rows: expected a non-empty image");
  }
  if (azimuths < 1) {
    throw std::invalid_argument(
        fmt::format("resample_azimuth_rows: azimuths must be >= 1, got {}", azimuths));
  }
  const int rows = power.rows();
  if (rows == azimuths) return power;
  ByteImage out = ByteImage::uninitialised(azimuths, power.cols());
  for (int a = 0; a < azimuths; ++a) {
    const double position = static_cast<double>(a) * rows / azimuths;
    const int below = static_cast<int>(std::floor(position));
    const int above = (below + 1) % rows;
    blend_rows(power.row(below), power.row(above), position - below, power.cols(), out.row(a));
  }
  return out;
}

}  // namespace radarpr
