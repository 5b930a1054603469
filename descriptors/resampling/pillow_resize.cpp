#include "descriptors/resampling/pillow_resize.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

#include <opencv2/core.hpp>

namespace radarpr {
namespace {

// Pillow's bicubic filter: cubic convolution with a = -0.5, support 2.
constexpr double kBicubicSupport = 2.0;
double bicubic(double x) {
  constexpr double a = -0.5;
  const double t = std::abs(x);
  if (t < 1.0) return ((a + 2.0) * t - (a + 3.0)) * t * t + 1.0;
  if (t < 2.0) return (((t - 5.0) * t + 8.0) * t - 4.0) * a;
  return 0.0;
}

}  // namespace

ResamplingAxis pillow_bicubic_axis(int input_length, int output_length) {
  if (input_length < 1 || output_length < 1) {
    throw std::invalid_argument("pillow_resize: expected lengths >= 1, got " +
                                std::to_string(input_length) + " -> " +
                                std::to_string(output_length));
  }
  const double scale = static_cast<double>(input_length) / output_length;
  const double filter_scale = std::max(scale, 1.0);
  const double support = kBicubicSupport * filter_scale;
  const double inverse_filter_scale = 1.0 / filter_scale;
  ResamplingAxis axis(static_cast<std::size_t>(output_length));
  for (int x = 0; x < output_length; ++x) {
    const double centre = (x + 0.5) * scale;
    // Truncation toward zero, as Pillow's cast; a negative start is clipped to 0 anyway.
    const int first = std::max(static_cast<int>(centre - support + 0.5), 0);
    const int end = std::min(static_cast<int>(centre + support + 0.5), input_length);
    ResamplingTaps& taps = axis[static_cast<std::size_t>(x)];
    double sum = 0.0;
    for (int i = first; i < end; ++i) {
      const double weight = bicubic((i - centre + 0.5) * inverse_filter_scale);
      taps.indices.push_back(i);
      taps.weights.push_back(weight);
      sum += weight;
    }
    if (sum != 0.0) {
      for (double& weight : taps.weights) weight /= sum;
    }
  }
  return axis;
}

cv::Mat pillow_resize(const cv::Mat& image, int rows, int cols) {
  if (image.empty() || image.type() != CV_32FC1) {
    throw std::invalid_argument("pillow_resize: expected a non-empty CV_32FC1 image, got " +
                                std::to_string(image.rows) + " x " + std::to_string(image.cols) +
                                " of type " + cv::typeToString(image.type()));
  }
  if (rows < 1 || cols < 1) {
    throw std::invalid_argument("pillow_resize: the output size must be >= 1 x 1, got " +
                                std::to_string(rows) + " x " + std::to_string(cols));
  }
  cv::Mat current = image.clone();
  if (cols != image.cols) {
    cv::Mat values;
    current.convertTo(values, CV_64F);
    resample_along_rows(values, pillow_bicubic_axis(image.cols, cols)).convertTo(current, CV_32F);
  }
  if (rows != image.rows) {
    cv::Mat values;
    current.convertTo(values, CV_64F);
    resample_along_columns(values, pillow_bicubic_axis(image.rows, rows))
        .convertTo(current, CV_32F);
  }
  return current;
}

}  // namespace radarpr
