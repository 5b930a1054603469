#include "descriptors/raplace/radon_transform.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "descriptors/raplace/segment_radon.hpp"

namespace radarpr::raplace {
namespace {

struct PixelMass {
  double x = 0.0;
  double y = 0.0;
  double value = 0.0;
};

// The non-zero pixels: a Cartesian radar image is mostly zero beyond the sensor's range circle
// and in shadows, and zero pixels add nothing to any projection.
std::vector<PixelMass> nonzero_pixels(const cv::Mat& image) {
  cv::Mat values;
  image.convertTo(values, CV_64F);
  const double centre_x = (values.cols - 1) / 2.0;
  const double centre_y = (values.rows - 1) / 2.0;
  std::vector<PixelMass> pixels;
  for (int i = 0; i < values.rows; ++i) {
    const auto* row = values.ptr<double>(i);
    for (int j = 0; j < values.cols; ++j) {
      if (row[j] != 0.0) pixels.push_back({j - centre_x, centre_y - i, row[j]});
    }
  }
  return pixels;
}

void check_image(const cv::Mat& image) {
  if (image.empty() || image.channels() != 1 ||
      (image.depth() != CV_32F && image.depth() != CV_64F)) {
    throw std::invalid_argument(
        "raplace: the Radon transform expects a non-empty single-channel CV_32F or CV_64F "
        "image, got " +
        std::to_string(image.rows) + " x " + std::to_string(image.cols) + " of type " +
        cv::typeToString(image.type()));
  }
}

}  // namespace

int radon_rho_bins(int width, int height) {
  const std::int64_t squared =
      static_cast<std::int64_t>(width) * width + static_cast<std::int64_t>(height) * height;
  auto bins = static_cast<std::int64_t>(std::sqrt(static_cast<double>(squared)));
  while (bins * bins < squared) ++bins;  // exact ceiling, whatever sqrt rounded to
  while (bins > 0 && (bins - 1) * (bins - 1) >= squared) --bins;
  return static_cast<int>(bins);
}

cv::Mat radon_transform(const cv::Mat& image) {
  check_image(image);
  if (image.rows != image.cols) return radon_transform_by_pixels(image);
  cv::Mat values;
  image.convertTo(values, CV_64F);
  return square_radon_by_segments(values, radon_rho_bins(image.cols, image.rows));
}

cv::Mat radon_transform_by_pixels(const cv::Mat& image) {
  check_image(image);
  const int rho_bins = radon_rho_bins(image.cols, image.rows);
  const double rho_centre = (rho_bins - 1) / 2.0;
  const std::vector<PixelMass> pixels = nonzero_pixels(image);

  cv::Mat sinogram(rho_bins, kRadonAngles, CV_64FC1, cv::Scalar(0.0));
  std::vector<double> projection(static_cast<std::size_t>(rho_bins));
  for (int theta = 0; theta < kRadonAngles; ++theta) {
    const double angle = theta * std::numbers::pi / 180.0;
    const double cos_theta = std::cos(angle);
    const double sin_theta = std::sin(angle);
    std::fill(projection.begin(), projection.end(), 0.0);
    for (const PixelMass& pixel : pixels) {
      // |rho| <= half the centre-to-centre diagonal <= (rho_bins - 1) / 2: the clamp only
      // absorbs rounding.
      const double position = std::clamp(pixel.x * cos_theta + pixel.y * sin_theta + rho_centre,
                                         0.0, static_cast<double>(rho_bins - 1));
      const auto bin = static_cast<std::size_t>(position);
      const double weight_next = position - static_cast<double>(bin);
      projection[bin] += (1.0 - weight_next) * pixel.value;
      if (weight_next > 0.0) projection[bin + 1] += weight_next * pixel.value;
    }
    for (int k = 0; k < rho_bins; ++k) {
      sinogram.at<double>(k, theta) = projection[static_cast<std::size_t>(k)];
    }
  }
  return sinogram;
}

}  // namespace radarpr::raplace
