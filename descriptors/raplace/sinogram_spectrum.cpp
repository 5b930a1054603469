#include "descriptors/raplace/sinogram_spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace radarpr::raplace {
namespace {

void check_matrix(const cv::Mat& matrix, const char* what) {
  if (matrix.empty() || matrix.type() != CV_64FC1) {
    throw std::invalid_argument(std::string("raplace: ") + what +
                                " expects a non-empty CV_64FC1 matrix, got " +
                                std::to_string(matrix.rows) + " x " + std::to_string(matrix.cols) +
                                " of type " + cv::typeToString(matrix.type()));
  }
}

}  // namespace

cv::Mat normalize_by_max(const cv::Mat& sinogram) {
  check_matrix(sinogram, "normalize_by_max");
  double maximum = 0.0;
  cv::minMaxLoc(sinogram, nullptr, &maximum);
  if (!(maximum > 0.0)) return sinogram.clone();
  return sinogram / maximum;
}

cv::Mat shrink_sinogram(const cv::Mat& sinogram, int rows, int cols) {
  check_matrix(sinogram, "shrink_sinogram");
  if (rows < 1 || rows > sinogram.rows || cols < 1 || cols > sinogram.cols) {
    throw std::invalid_argument("raplace: cannot shrink a " + std::to_string(sinogram.rows) +
                                " x " + std::to_string(sinogram.cols) + " sinogram to " +
                                std::to_string(rows) + " x " + std::to_string(cols) +
                                " (expected 1 <= size <= the sinogram's, per axis)");
  }
  if (rows == sinogram.rows && cols == sinogram.cols) return sinogram.clone();
  cv::Mat shrunk;
  cv::resize(sinogram, shrunk, cv::Size(cols, rows), 0.0, 0.0, cv::INTER_AREA);
  return shrunk;
}

cv::Mat rho_spectrum_magnitude(const cv::Mat& sinogram) {
  check_matrix(sinogram, "rho_spectrum_magnitude");
  if (sinogram.rows < 2) {
    throw std::invalid_argument(
        "raplace: the sinogram needs >= 2 rho rows for a rho spectrum, "
        "got " +
        std::to_string(sinogram.rows));
  }
  // cv::dft transforms rows, so transform the transposed sinogram (one row per theta).
  cv::Mat spectra;
  cv::dft(sinogram.t(), spectra, cv::DFT_ROWS | cv::DFT_COMPLEX_OUTPUT);
  const int kept = sinogram.rows / 2;
  cv::Mat magnitude(kept, sinogram.cols, CV_64FC1);
  for (int theta = 0; theta < sinogram.cols; ++theta) {
    const auto* spectrum = spectra.ptr<cv::Vec2d>(theta);
    for (int k = 0; k < kept; ++k) {
      magnitude.at<double>(k, theta) = std::hypot(spectrum[k][0], spectrum[k][1]);
    }
  }
  return magnitude;
}

std::vector<float> z_score(const cv::Mat& matrix) {
  check_matrix(matrix, "z_score");
  const cv::Mat values = matrix.isContinuous() ? matrix : matrix.clone();
  const auto count = static_cast<std::size_t>(values.total());
  const auto* data = values.ptr<double>(0);
  std::vector<float> scores(count, 0.0f);
  if (count < 2) return scores;
  double sum = 0.0;
  double largest = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    sum += data[i];
    largest = std::max(largest, std::abs(data[i]));
  }
  const double mean = sum / static_cast<double>(count);
  double squares = 0.0;
  for (std::size_t i = 0; i < count; ++i) squares += (data[i] - mean) * (data[i] - mean);
  const double deviation = std::sqrt(squares / static_cast<double>(count - 1));
  // Rounding leaves a tiny deviation on constant data; scaling it up would amplify noise.
  if (!(deviation > 1e-12 * largest)) return scores;
  for (std::size_t i = 0; i < count; ++i) {
    scores[i] = static_cast<float>((data[i] - mean) / deviation);
  }
  return scores;
}

}  // namespace radarpr::raplace
