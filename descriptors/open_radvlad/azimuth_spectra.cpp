#include "descriptors/open_radvlad/azimuth_spectra.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/core/hal/intrin.hpp>

#include "datasets/cpu_features.hpp"
#include "descriptors/open_radvlad/area_resampling.hpp"
#include "descriptors/opencv_image.hpp"
#include "descriptors/resampling/pillow_resize.hpp"

#if defined(__x86_64__)
#include <immintrin.h>
#define RADARPR_SPECTRA_X86 1
#endif

namespace radarpr {
namespace {

// |z| of each complex value in double, rounded to float: sqrt is correctly rounded in SIMD as in
// scalar code, so two or four at a time give the same values.
void magnitudes_baseline(const cv::Vec2f* complex, int count, float* out) {
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

#if RADARPR_SPECTRA_X86
// Four square roots per instruction instead of two (the divider's throughput per value doubles);
// no FMA, so re * re + im * im rounds as above.
__attribute__((target("avx2"))) void magnitudes_avx2(const cv::Vec2f* complex, int count,
                                                     float* out) {
  int k = 0;
  for (; k + 4 <= count; k += 4) {
    const __m256 pairs = _mm256_loadu_ps(reinterpret_cast<const float*>(complex + k));
    // re0 im0 re1 im1 | re2 im2 re3 im3 -> re0 re1 re2 re3 and im0 im1 im2 im3
    const __m256 ordered =
        _mm256_permutevar8x32_ps(pairs, _mm256_setr_epi32(0, 2, 4, 6, 1, 3, 5, 7));
    const __m256d re = _mm256_cvtps_pd(_mm256_castps256_ps128(ordered));
    const __m256d im = _mm256_cvtps_pd(_mm256_extractf128_ps(ordered, 1));
    const __m256d squared = _mm256_add_pd(_mm256_mul_pd(re, re), _mm256_mul_pd(im, im));
    _mm_storeu_ps(out + k, _mm256_cvtpd_ps(_mm256_sqrt_pd(squared)));
  }
  magnitudes_baseline(complex + k, count - k, out + k);
}
#endif

void magnitudes(const cv::Vec2f* complex, int count, float* out) {
#if RADARPR_SPECTRA_X86
  static const bool avx2 = cpu_features().avx2;
  if (avx2) return magnitudes_avx2(complex, count, out);
#endif
  magnitudes_baseline(complex, count, out);
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

cv::Mat azimuth_spectra(const PolarImage& scan, const AzimuthSpectraParams& params) {
  validate(params);
  if (scan.power.empty()) {
    throw std::invalid_argument("open_radvlad: expected a non-empty A x R polar image, got " +
                                std::to_string(scan.power.rows()) + " x " +
                                std::to_string(scan.power.cols()));
  }
  // OpenCV's algorithms below only read the scan's pixels (opencv_image.hpp).
  const cv::Mat power_bytes = opencv_view(scan.power);
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
    power_bytes.colRange(0, cropped).convertTo(power, CV_32FC1);
    if (zeroed > 0) power.colRange(0, zeroed).setTo(0.0f);
    resampled = pillow_resize(power, power.rows, params.bin_dim);
  } else {
    resampled = area_resample_bytes(power_bytes.colRange(0, cropped), zeroed, params.bin_dim);
  }
  // The real rows' DFTs in OpenCV's packed form (CCS: X_0, then re and im of X_1 .. X_{(D-1)/2},
  // then X_{D/2} when D is even): the same values as DFT_COMPLEX_OUTPUT, which only adds the
  // conjugates X_{D-k} of X_k, whose magnitudes are the same.
  cv::Mat spectrum;
  cv::dft(resampled, spectrum, cv::DFT_ROWS);
  const int dims = params.bin_dim;
  const int pairs = (dims - 1) / 2;
  cv::Mat magnitude(spectrum.rows, dims, CV_32FC1);
  for (int a = 0; a < spectrum.rows; ++a) {
    const float* packed = spectrum.ptr<float>(a);
    float* out = magnitude.ptr<float>(a);
    const cv::Vec2f ends[2] = {{packed[0], 0.0f}, {packed[dims - 1], 0.0f}};
    magnitudes(ends, 1, out);
    magnitudes(reinterpret_cast<const cv::Vec2f*>(packed + 1), pairs, out + 1);
    if (dims % 2 == 0 && dims > 1) magnitudes(ends + 1, 1, out + dims / 2);
    for (int k = 1; k <= pairs; ++k) out[dims - k] = out[k];
  }
  normalise_rows(magnitude);
  return magnitude;
}

}  // namespace radarpr
