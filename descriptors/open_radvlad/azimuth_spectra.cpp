#include "descriptors/open_radvlad/azimuth_spectra.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "descriptors/resampling/pillow_resize.hpp"

namespace radarpr {
namespace {

// One input column's share of an output bin.
struct AreaWeight {
  int column = 0;
  double weight = 0.0;
};

// Output bin j covers [j W, (j+1) W) and input column i covers [i width, (i+1) width), both in
// units of 1/width of a column: integer overlaps, so the weights (overlap / W) are exact ratios.
std::vector<std::vector<AreaWeight>> area_weights(int input_width, int width) {
  const auto w_in = static_cast<std::int64_t>(input_width);
  const auto w_out = static_cast<std::int64_t>(width);
  std::vector<std::vector<AreaWeight>> weights(static_cast<std::size_t>(width));
  for (std::int64_t j = 0; j < w_out; ++j) {
    const std::int64_t begin = j * w_in;
    const std::int64_t end = begin + w_in;
    for (std::int64_t i = begin / w_out; i * w_out < end; ++i) {
      const std::int64_t overlap = std::min(end, (i + 1) * w_out) - std::max(begin, i * w_out);
      if (overlap > 0) {
        weights[static_cast<std::size_t>(j)].push_back(
            {static_cast<int>(i), static_cast<double>(overlap) / static_cast<double>(w_in)});
      }
    }
  }
  return weights;
}

void normalise_rows(cv::Mat& rows) {
  for (int a = 0; a < rows.rows; ++a) {
    float* row = rows.ptr<float>(a);
    double squared = 0.0;
    for (int j = 0; j < rows.cols; ++j) squared += static_cast<double>(row[j]) * row[j];
    if (squared == 0.0) continue;  // an empty azimuth stays zero rather than NaN
    const double inverse_norm = 1.0 / std::sqrt(squared);
    for (int j = 0; j < rows.cols; ++j) row[j] = static_cast<float>(row[j] * inverse_norm);
  }
}

}  // namespace

void validate(const AzimuthSpectraParams& params) {
  if (params.min_bin < 0) {
    throw std::invalid_argument("open_radvlad: min_bin must be >= 0, got " +
                                std::to_string(params.min_bin));
  }
  if (params.max_bin < 0) {
    throw std::invalid_argument("open_radvlad: max_bin must be >= 0 (0 = all bins), got " +
                                std::to_string(params.max_bin));
  }
  if (params.bin_dim < 1) {
    throw std::invalid_argument("open_radvlad: bin_dim must be >= 1, got " +
                                std::to_string(params.bin_dim));
  }
}

cv::Mat area_resample_rows(const cv::Mat& rows, int width) {
  if (rows.empty() || rows.type() != CV_32FC1 || width < 1) {
    throw std::invalid_argument(
        "area_resample_rows: expected a non-empty CV_32FC1 matrix and a width >= 1, got " +
        std::to_string(rows.rows) + " x " + std::to_string(rows.cols) + " of type " +
        cv::typeToString(rows.type()) + " and width " + std::to_string(width));
  }
  const auto weights = area_weights(rows.cols, width);
  cv::Mat resampled(rows.rows, width, CV_32FC1);
  for (int a = 0; a < rows.rows; ++a) {
    const float* in = rows.ptr<float>(a);
    float* out = resampled.ptr<float>(a);
    for (int j = 0; j < width; ++j) {
      double sum = 0.0;
      for (const AreaWeight& w : weights[static_cast<std::size_t>(j)]) {
        sum += w.weight * in[w.column];
      }
      out[j] = static_cast<float>(sum);
    }
  }
  return resampled;
}

cv::Mat azimuth_spectra(const PolarImage& scan, const AzimuthSpectraParams& params) {
  validate(params);
  if (scan.power.empty() || scan.power.type() != CV_8UC1) {
    throw std::invalid_argument(
        "open_radvlad: expected a non-empty CV_8UC1 A x R polar image, got " +
        std::to_string(scan.power.rows) + " x " + std::to_string(scan.power.cols) + " of type " +
        cv::typeToString(scan.power.type()));
  }
  const int range_bins = scan.range_bin_count();
  const int cropped = params.max_bin == 0 ? range_bins : std::min(params.max_bin, range_bins);
  // Every kept bin zeroed gives every scan the same spectra, hence the same descriptor (found
  // only by tie-breaking): refused, naming the largest min_bin these scans allow.
  if (params.min_bin >= cropped) {
    throw std::invalid_argument(
        "open_radvlad: min_bin = " + std::to_string(params.min_bin) +
        " zeroes every range bin of a scan with " + std::to_string(range_bins) +
        (cropped < range_bins ? " (cropped to max_bin = " + std::to_string(cropped) + ")" : "") +
        "; at most " + std::to_string(cropped - 1) + " for these scans");
  }
  cv::Mat power;
  scan.power.colRange(0, cropped).convertTo(power, CV_32FC1);
  const int zeroed = std::min(params.min_bin, cropped);
  if (zeroed > 0) power.colRange(0, zeroed).setTo(0.0f);

  const cv::Mat resampled = params.resize == AzimuthResize::pillow_bicubic
                                ? pillow_resize(power, power.rows, params.bin_dim)
                                : area_resample_rows(power, params.bin_dim);
  cv::Mat spectrum;
  cv::dft(resampled, spectrum, cv::DFT_ROWS | cv::DFT_COMPLEX_OUTPUT);
  cv::Mat magnitude(spectrum.rows, params.bin_dim, CV_32FC1);
  for (int a = 0; a < spectrum.rows; ++a) {
    const auto* complex = spectrum.ptr<cv::Vec2f>(a);
    float* out = magnitude.ptr<float>(a);
    for (int k = 0; k < params.bin_dim; ++k) {
      const double re = complex[k][0];
      const double im = complex[k][1];
      out[k] = static_cast<float>(std::sqrt(re * re + im * im));
    }
  }
  normalise_rows(magnitude);
  return magnitude;
}

}  // namespace radarpr
