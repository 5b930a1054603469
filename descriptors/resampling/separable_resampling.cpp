#include "descriptors/resampling/separable_resampling.hpp"

#include <cstddef>
#include <stdexcept>
#include <string>

#include <opencv2/core.hpp>

namespace radarpr {
namespace {

void check_input(const cv::Mat& image, const ResamplingAxis& taps, int input_length,
                 const char* function) {
  if (image.empty() || image.type() != CV_64FC1) {
    throw std::invalid_argument(std::string(function) +
                                ": expected a non-empty CV_64FC1 matrix, got " +
                                std::to_string(image.rows) + " x " + std::to_string(image.cols) +
                                " of type " + cv::typeToString(image.type()));
  }
  for (const ResamplingTaps& output : taps) {
    if (output.indices.size() != output.weights.size()) {
      throw std::invalid_argument(std::string(function) + ": taps with " +
                                  std::to_string(output.indices.size()) + " indices and " +
                                  std::to_string(output.weights.size()) + " weights");
    }
    for (const int index : output.indices) {
      if (index < 0 || index >= input_length) {
        throw std::invalid_argument(std::string(function) + ": tap index " + std::to_string(index) +
                                    " outside 0 .. " + std::to_string(input_length - 1));
      }
    }
  }
}

}  // namespace

cv::Mat resample_along_rows(const cv::Mat& image, const ResamplingAxis& taps) {
  check_input(image, taps, image.cols, "resample_along_rows");
  cv::Mat out(image.rows, static_cast<int>(taps.size()), CV_64FC1);
  for (int r = 0; r < image.rows; ++r) {
    const auto* in = image.ptr<double>(r);
    auto* result = out.ptr<double>(r);
    for (std::size_t x = 0; x < taps.size(); ++x) {
      double sum = 0.0;
      for (std::size_t k = 0; k < taps[x].indices.size(); ++k) {
        sum += in[taps[x].indices[k]] * taps[x].weights[k];
      }
      result[x] = sum;
    }
  }
  return out;
}

cv::Mat resample_along_columns(const cv::Mat& image, const ResamplingAxis& taps) {
  check_input(image, taps, image.rows, "resample_along_columns");
  cv::Mat out(static_cast<int>(taps.size()), image.cols, CV_64FC1, cv::Scalar(0.0));
  // Tap by tap over whole rows: each element still sums its taps in order, row-major reads.
  for (std::size_t y = 0; y < taps.size(); ++y) {
    auto* result = out.ptr<double>(static_cast<int>(y));
    for (std::size_t k = 0; k < taps[y].indices.size(); ++k) {
      const auto* in = image.ptr<double>(taps[y].indices[k]);
      const double weight = taps[y].weights[k];
      for (int c = 0; c < image.cols; ++c) result[c] += in[c] * weight;
    }
  }
  return out;
}

}  // namespace radarpr
