#include "datasets/real/azimuth_resampling.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>
#include <opencv2/core.hpp>

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
    cv::Mat target = out.row(a);
    // (1 - f) low + f high, rounded to the nearest value and saturated.
    cv::addWeighted(power.row(below), 1.0 - f, power.row(above), f, 0.0, target);
  }
  return out;
}

}  // namespace radarpr
