#include "descriptors/raplace/matlab_radon.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "descriptors/raplace/radon_transform.hpp"

namespace radarpr::raplace {
namespace {

int half_length(int rows, int cols) {
  const double dy = rows - std::floor((rows - 1) / 2.0) - 1.0;
  const double dx = cols - std::floor((cols - 1) / 2.0) - 1.0;
  return static_cast<int>(std::ceil(std::sqrt(dx * dx + dy * dy))) + 1;
}

struct SubPixel {
  double x = 0.0;
  double y = 0.0;
  double value = 0.0;  // a quarter of the pixel's
};

}  // namespace

int matlab_radon_rho_bins(int rows, int cols) {
  return 2 * half_length(rows, cols) + 1;
}

cv::Mat matlab_radon(const cv::Mat& image) {
  if (image.empty() || image.channels() != 1 ||
      (image.depth() != CV_8U && image.depth() != CV_32F && image.depth() != CV_64F)) {
    throw std::invalid_argument(
        "raplace: the MATLAB-style Radon transform expects a non-empty single-channel CV_8U, "
        "CV_32F or CV_64F image, got " +
        std::to_string(image.rows) + " x " + std::to_string(image.cols) + " of type " +
        cv::typeToString(image.type()));
  }
  cv::Mat values;
  image.convertTo(values, CV_64F);
  const double centre_row = std::floor((values.rows - 1) / 2.0);
  const double centre_col = std::floor((values.cols - 1) / 2.0);
  const int half = half_length(values.rows, values.cols);
  const int bins = 2 * half + 1;

  // Zero pixels add nothing: a radar Cartesian image is mostly zero outside its range circle.
  std::vector<SubPixel> sub_pixels;
  for (int i = 0; i < values.rows; ++i) {
    const auto* row = values.ptr<double>(i);
    for (int j = 0; j < values.cols; ++j) {
      if (row[j] == 0.0) continue;
      const double x = j - centre_col;
      const double y = centre_row - i;
      const double quarter = row[j] * 0.25;
      for (const double dx : {-0.25, 0.25}) {
        for (const double dy : {-0.25, 0.25}) sub_pixels.push_back({x + dx, y + dy, quarter});
      }
    }
  }

  cv::Mat sinogram(bins, kRadonAngles, CV_64FC1, cv::Scalar(0.0));
  std::vector<double> projection(static_cast<std::size_t>(bins) + 1);
  for (int theta = 0; theta < kRadonAngles; ++theta) {
    const double angle = theta * std::numbers::pi / 180.0;
    const double cos_theta = std::cos(angle);
    const double sin_theta = std::sin(angle);
    std::fill(projection.begin(), projection.end(), 0.0);
    for (const SubPixel& p : sub_pixels) {
      // Offset from rho = -half; inside [0, 2 half - 1) for every sub-pixel of the image.
      const double position = p.x * cos_theta + p.y * sin_theta + half;
      const auto bin = static_cast<std::size_t>(position);
      const double next = position - static_cast<double>(bin);
      projection[bin] += p.value * (1.0 - next);
      projection[bin + 1] += p.value * next;
    }
    for (int k = 0; k < bins; ++k) {
      sinogram.at<double>(k, theta) = projection[static_cast<std::size_t>(k)];
    }
  }
  return sinogram;
}

}  // namespace radarpr::raplace
