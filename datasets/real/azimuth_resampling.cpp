#include "datasets/real/azimuth_resampling.hpp"

#include <cmath>
#include <cstdint>
#include <stdexcept>

#include <fmt/format.h>

namespace radarpr {

cv::Mat resample_azimuth_rows(const cv::Mat& power, int azimuths) {
  if (power.empty() || power.type() != CV_8UC1) {
    throw std::invalid_argument("resample_azimuth_rows: expected a non-empty CV_8UC1 image");
  }
  if (azimuths < 1) {
    throw std::invalid_argument(
        fmt::format("resample_azimuth_rows: azimuths must be >= 1, got {}", azimuths));
  }
  const int rows = power.rows;
  if (rows == azimuths) return power.clone();
  cv::Mat out(azimuths, power.cols, CV_8UC1);
  for (int a = 0; a < azimuths; ++a) {
    const double position = static_cast<double>(a) * rows / azimuths;
    const int below = static_cast<int>(std::floor(position));
    const int above = (below + 1) % rows;
    const double f = position - below;
    const std::uint8_t* low = power.ptr<std::uint8_t>(below);
    const std::uint8_t* high = power.ptr<std::uint8_t>(above);
    std::uint8_t* target = out.ptr<std::uint8_t>(a);
    for (int r = 0; r < power.cols; ++r) {
      const double value = (1.0 - f) * low[r] + f * high[r];
      target[r] = static_cast<std::uint8_t>(std::lround(value));
    }
  }
  return out;
}

}  // namespace radarpr
