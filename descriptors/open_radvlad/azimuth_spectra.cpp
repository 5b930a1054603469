#include "descriptors/open_radvlad/azimuth_spectra.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/core/hal/intrin.hpp>

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

// The area weights flattened, output bin j reading terms [first[j], first[j + 1]), for a uint8
// row whose columns below `zeroed` read as 0: their terms add 0.0 to a sum that starts at 0.0 and
// are left out, which changes no sum.
struct FlatAreaWeights {
  std::vector<int> first;
  std::vector<int> columns;
  std::vector<double> weights;
};

FlatAreaWeights flat_area_weights(int input_width, int width, int zeroed) {
  FlatAreaWeights flat;
  for (const std::vector<AreaWeight>& bin : area_weights(input_width, width)) {
    flat.first.push_back(static_cast<int>(flat.columns.size()));
    for (const AreaWeight& w : bin) {
      if (w.column < zeroed) continue;
      flat.columns.push_back(w.column);
      flat.weights.push_back(w.weight);
    }
  }
  flat.first.push_back(static_cast<int>(flat.columns.size()));
  return flat;
}

// area_resample_rows of the uint8 rows (columns below `zeroed` read as 0), without a float copy of
// the scan: the same double sums in the same order, a byte's value read from a table. Each sum
// is a short chain of dependent additions whose length varies with the bin, so four rows go
// through the terms together: four chains in flight and one loop exit per four sums.
cv::Mat area_resample_bytes(const cv::Mat& bytes, int zeroed, int width) {
  const FlatAreaWeights flat = flat_area_weights(bytes.cols, width, zeroed);
  double value_of[256];
  for (int v = 0; v < 256; ++v) value_of[v] = v;
  cv::Mat resampled(bytes.rows, width, CV_32FC1);
  const int* first = flat.first.data();
  const int* columns = flat.columns.data();
  const double* weights = flat.weights.data();
  int a = 0;
  for (; a + 4 <= bytes.rows; a += 4) {
    const unsigned char* in0 = bytes.ptr<unsigned char>(a);
    const unsigned char* in1 = bytes.ptr<unsigned char>(a + 1);
    const unsigned char* in2 = bytes.ptr<unsigned char>(a + 2);
    const unsigned char* in3 = bytes.ptr<unsigned char>(a + 3);
    for (int j = 0; j < width; ++j) {
      double sum0 = 0.0;
      double sum1 = 0.0;
      double sum2 = 0.0;
      double sum3 = 0.0;
      for (int t = first[j]; t < first[j + 1]; ++t) {
        const int column = columns[t];
        const double w = weights[t];
        sum0 += w * value_of[in0[column]];
        sum1 += w * value_of[in1[column]];
        sum2 += w * value_of[in2[column]];
        sum3 += w * value_of[in3[column]];
      }
      resampled.at<float>(a, j) = static_cast<float>(sum0);
      resampled.at<float>(a + 1, j) = static_cast<float>(sum1);
      resampled.at<float>(a + 2, j) = static_cast<float>(sum2);
      resampled.at<float>(a + 3, j) = static_cast<float>(sum3);
    }
  }
  for (; a < bytes.rows; ++a) {
    const unsigned char* in = bytes.ptr<unsigned char>(a);
    for (int j = 0; j < width; ++j) {
      double sum = 0.0;
      for (int t = first[j]; t < first[j + 1]; ++t) sum += weights[t] * value_of[in[columns[t]]];
      resampled.at<float>(a, j) = static_cast<float>(sum);
    }
  }
  return resampled;
}

// |z| of each complex value in double, rounded to float: sqrt is correctly rounded in SIMD as in
// scalar code, so two at a time gives the same values.
void magnitudes(const cv::Vec2f* complex, int count, float* out) {
  int k = 0;
#if CV_SIMD128_64F
  for (; k + 4 <= count; k += 4) {
    cv::v_float32x4 re;
    cv::v_float32x4 im;
    cv::v_load_deinterleave(reinterpret_cast<const float*>(complex + k), re, im);
    const cv::v_float64x2 re_low = cv::v_cvt_f64(re);
    const cv::v_float64x2 re_high = cv::v_cvt_f64_high(re);
    const cv::v_float64x2 im_low = cv::v_cvt_f64(im);
    const cv::v_float64x2 im_high = cv::v_cvt_f64_high(im);
    const cv::v_float64x2 low = cv::v_sqrt(re_low * re_low + im_low * im_low);
    const cv::v_float64x2 high = cv::v_sqrt(re_high * re_high + im_high * im_high);
    cv::v_store(out + k, cv::v_cvt_f32(low, high));
  }
#endif
  for (; k < count; ++k) {
    const double re = complex[k][0];
    const double im = complex[k][1];
    out[k] = static_cast<float>(std::sqrt(re * re + im * im));
  }
}

void normalise_row(float* row, int count, double squared) {
  if (squared == 0.0) return;  // an empty azimuth stays zero rather than NaN
  const double inverse_norm = 1.0 / std::sqrt(squared);
  for (int j = 0; j < count; ++j) row[j] = static_cast<float>(row[j] * inverse_norm);
}

// Each row's squared norm is summed in order j = 0, 1, ...: one chain of dependent additions per
// row, so four rows are summed side by side (the same sums, four times the throughput).
void normalise_rows(cv::Mat& rows) {
  int a = 0;
  for (; a + 4 <= rows.rows; a += 4) {
    float* row[4] = {rows.ptr<float>(a), rows.ptr<float>(a + 1), rows.ptr<float>(a + 2),
                     rows.ptr<float>(a + 3)};
    double squared[4] = {0.0, 0.0, 0.0, 0.0};
    for (int j = 0; j < rows.cols; ++j) {
      for (int i = 0; i < 4; ++i) squared[i] += static_cast<double>(row[i][j]) * row[i][j];
    }
    for (int i = 0; i < 4; ++i) normalise_row(row[i], rows.cols, squared[i]);
  }
  for (; a < rows.rows; ++a) {
    float* row = rows.ptr<float>(a);
    double squared = 0.0;
    for (int j = 0; j < rows.cols; ++j) squared += static_cast<double>(row[j]) * row[j];
    normalise_row(row, rows.cols, squared);
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
  const int zeroed = std::min(params.min_bin, cropped);
  cv::Mat resampled;
  if (params.resize == AzimuthResize::pillow_bicubic) {
    cv::Mat power;
    scan.power.colRange(0, cropped).convertTo(power, CV_32FC1);
    if (zeroed > 0) power.colRange(0, zeroed).setTo(0.0f);
    resampled = pillow_resize(power, power.rows, params.bin_dim);
  } else {
    resampled = area_resample_bytes(scan.power.colRange(0, cropped), zeroed, params.bin_dim);
  }
  cv::Mat spectrum;
  cv::dft(resampled, spectrum, cv::DFT_ROWS | cv::DFT_COMPLEX_OUTPUT);
  cv::Mat magnitude(spectrum.rows, params.bin_dim, CV_32FC1);
  for (int a = 0; a < spectrum.rows; ++a) {
    magnitudes(spectrum.ptr<cv::Vec2f>(a), params.bin_dim, magnitude.ptr<float>(a));
  }
  normalise_rows(magnitude);
  return magnitude;
}

}  // namespace radarpr
