#include "descriptors/resampling/matlab_imresize.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace radarpr {
namespace {

// Keys' cubic convolution kernel with a = -0.5, support [-2, 2].
double cubic(double x) {
  const double t = std::abs(x);
  if (t <= 1.0) return (1.5 * t - 2.5) * t * t + 1.0;
  if (t <= 2.0) return ((-0.5 * t + 2.5) * t - 4.0) * t + 2.0;
  return 0.0;
}

// Symmetric padding: ..., 1, 0 | 0, 1, ..., n-1 | n-1, n-2, ... (0-based), period 2n.
int mirrored(std::int64_t index, int length) {
  const std::int64_t period = 2 * static_cast<std::int64_t>(length);
  std::int64_t folded = index % period;
  if (folded < 0) folded += period;
  return static_cast<int>(folded < length ? folded : period - 1 - folded);
}

void check_image(const cv::Mat& image, const char* function) {
  if (image.empty() || image.channels() != 1 ||
      (image.depth() != CV_8U && image.depth() != CV_32F && image.depth() != CV_64F)) {
    throw std::invalid_argument(std::string(function) +
                                ": expected a non-empty single-channel CV_8U, CV_32F or CV_64F "
                                "image, got " +
                                std::to_string(image.rows) + " x " + std::to_string(image.cols) +
                                " of type " + cv::typeToString(image.type()));
  }
}

// The pass's result in the input's class: CV_8U rounded half away from zero and clipped (MATLAB's
// conversion of a double to uint8), CV_32F rounded to float, CV_64F as it is.
cv::Mat in_class_of(const cv::Mat& values, int depth) {
  if (depth == CV_64F) return values;
  cv::Mat converted(values.size(), CV_MAKETYPE(depth, 1));
  for (int r = 0; r < values.rows; ++r) {
    const auto* in = values.ptr<double>(r);
    if (depth == CV_8U) {
      auto* out = converted.ptr<unsigned char>(r);
      for (int c = 0; c < values.cols; ++c) {
        out[c] = static_cast<unsigned char>(std::clamp(std::round(in[c]), 0.0, 255.0));
      }
    } else {
      auto* out = converted.ptr<float>(r);
      for (int c = 0; c < values.cols; ++c) out[c] = static_cast<float>(in[c]);
    }
  }
  return converted;
}

cv::Mat resize_with_scales(const cv::Mat& image, int rows, int cols, double row_scale,
                           double col_scale) {
  const ResamplingAxis row_taps = matlab_imresize_axis(image.rows, rows, row_scale);
  const ResamplingAxis col_taps = matlab_imresize_axis(image.cols, cols, col_scale);
  const int depth = image.depth();
  cv::Mat current;
  image.convertTo(current, CV_64F);
  // The axis with the smaller scale first; ties: rows (MATLAB's first dimension) first.
  const bool rows_first = row_scale <= col_scale;
  for (int pass = 0; pass < 2; ++pass) {
    const bool along_rows_axis = (pass == 0) == rows_first;
    cv::Mat resized = along_rows_axis ? resample_along_columns(current, row_taps)
                                      : resample_along_rows(current, col_taps);
    in_class_of(resized, depth).convertTo(current, CV_64F);
  }
  return in_class_of(current, depth);
}

}  // namespace

ResamplingAxis matlab_imresize_axis(int input_length, int output_length, double scale) {
  if (input_length < 1 || output_length < 1 || !(scale > 0.0) || !std::isfinite(scale)) {
    throw std::invalid_argument(
        "matlab_imresize: expected lengths >= 1 and a finite scale > 0, "
        "got " +
        std::to_string(input_length) + " -> " + std::to_string(output_length) + " at scale " +
        std::to_string(scale));
  }
  const bool antialias = scale < 1.0;
  const double kernel_width = antialias ? 4.0 / scale : 4.0;
  const auto candidates = static_cast<std::size_t>(std::ceil(kernel_width)) + 2;

  // Candidate weights of every output (before dropping the all-zero candidate columns).
  std::vector<std::vector<double>> weights(static_cast<std::size_t>(output_length));
  std::vector<std::int64_t> first(static_cast<std::size_t>(output_length));
  std::vector<bool> used(candidates, false);
  for (int i = 0; i < output_length; ++i) {
    const double u = (i + 1) / scale + 0.5 * (1.0 - 1.0 / scale);  // 1-based input coordinate
    const auto left = static_cast<std::int64_t>(std::floor(u - kernel_width / 2.0));
    auto& row = weights[static_cast<std::size_t>(i)];
    row.resize(candidates);
    double sum = 0.0;
    for (std::size_t k = 0; k < candidates; ++k) {
      const double x = u - static_cast<double>(left + static_cast<std::int64_t>(k));
      row[k] = antialias ? scale * cubic(scale * x) : cubic(x);
      sum += row[k];
    }
    for (std::size_t k = 0; k < candidates; ++k) {
      row[k] /= sum;
      if (row[k] != 0.0) used[k] = true;
    }
    first[static_cast<std::size_t>(i)] = left;
  }

  ResamplingAxis axis(static_cast<std::size_t>(output_length));
  for (std::size_t i = 0; i < axis.size(); ++i) {
    for (std::size_t k = 0; k < candidates; ++k) {
      if (!used[k]) continue;
      // first[i] + k is 1-based; mirrored() works 0-based.
      axis[i].indices.push_back(
          mirrored(first[i] + static_cast<std::int64_t>(k) - 1, input_length));
      axis[i].weights.push_back(weights[i][k]);
    }
  }
  return axis;
}

cv::Mat matlab_imresize(const cv::Mat& image, int rows, int cols) {
  check_image(image, "matlab_imresize");
  if (rows < 1 || cols < 1) {
    throw std::invalid_argument("matlab_imresize: the output size must be >= 1 x 1, got " +
                                std::to_string(rows) + " x " + std::to_string(cols));
  }
  return resize_with_scales(image, rows, cols, static_cast<double>(rows) / image.rows,
                            static_cast<double>(cols) / image.cols);
}

cv::Mat matlab_imresize_scale(const cv::Mat& image, double scale) {
  check_image(image, "matlab_imresize_scale");
  if (!(scale > 0.0) || !std::isfinite(scale)) {
    throw std::invalid_argument("matlab_imresize_scale: the scale must be finite and > 0, got " +
                                std::to_string(scale));
  }
  const auto rows = static_cast<int>(std::ceil(scale * image.rows));
  const auto cols = static_cast<int>(std::ceil(scale * image.cols));
  return resize_with_scales(image, rows, cols, scale, scale);
}

}  // namespace radarpr
