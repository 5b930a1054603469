#include "descriptors/features/cen2018.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace radarpr {
namespace {

// scipy.ndimage's 'reflect' mode repeats the edge sample (d c b a | a b c d | d c b a), which is
// OpenCV's BORDER_REFLECT, not BORDER_REFLECT_101 (d c b | a b c d | c b a).
constexpr int kReflectBorder = cv::BORDER_REFLECT;

void check_params(const Cen2018Params& params) {
  if (!std::isfinite(params.sigma) || params.sigma <= 0.0) {
    throw std::invalid_argument("cen2018: sigma must be finite and > 0, got " +
                                std::to_string(params.sigma));
  }
  if (!std::isfinite(params.z_q)) {
    throw std::invalid_argument("cen2018: z_q must be finite");
  }
}

// Subtracts from x the running median of the window [r - W/2, r + W/2 - 1] (reflected at the
// ends); W is even, so the median is the mean of the two middle values (numpy's convention).
// The window is kept sorted; sliding it replaces one value by another, which only shifts the
// values lying between the two.
void subtract_running_median(const float* x, int count, float* q) {
  constexpr int half = kCenMedianWindow / 2;
  std::vector<float> padded;  // padded[i] = x[i - half], reflected
  padded.reserve(static_cast<std::size_t>(count + 2 * half));
  for (int i = -half; i < count + half; ++i) {
    padded.push_back(x[cv::borderInterpolate(i, count, kReflectBorder)]);
  }
  std::vector<float> window(padded.begin(), padded.begin() + kCenMedianWindow);
  std::sort(window.begin(), window.end());
  for (int r = 0; r < count; ++r) {
    const double median = 0.5 * (static_cast<double>(window[half - 1]) + window[half]);
    q[r] = static_cast<float>(x[r] - median);
    if (r + 1 == count) break;
    // The window moves from [r - W/2, r + W/2) to [r + 1 - W/2, r + 1 + W/2).
    const float outgoing = padded[r];
    const float incoming = padded[r + kCenMedianWindow];
    const auto out = std::lower_bound(window.begin(), window.end(), outgoing);
    if (incoming > outgoing) {
      const auto in = std::upper_bound(out, window.end(), incoming);
      std::move(out + 1, in, out);
      *(in - 1) = incoming;
    } else {
      const auto in = std::upper_bound(window.begin(), out, incoming);
      std::move_backward(in, out, out + 1);
      *in = incoming;
    }
  }
}

void subtract_row_mean(const unsigned char* x, int count, float* q) {
  std::int64_t sum = 0;  // exact, and vectorisable unlike a floating-point sum
  for (int r = 0; r < count; ++r) sum += x[r];
  const auto mean = static_cast<float>(static_cast<double>(sum) / count);
  for (int r = 0; r < count; ++r) q[r] = static_cast<float>(x[r]) - mean;
}

void subtract_row_mean(const float* x, int count, float* q) {
  double sum = 0.0;
  for (int r = 0; r < count; ++r) sum += x[r];
  const auto mean = static_cast<float>(sum / count);
  for (int r = 0; r < count; ++r) q[r] = x[r] - mean;
}

// q = P - trend, row by row, in float32 (uint8 rows are read directly, without a converted copy).
void detrend_rows(const cv::Mat& power, CenDetrend detrend, cv::Mat& q) {
  q.create(power.size(), CV_32F);
  std::vector<float> values;
  for (int a = 0; a < power.rows; ++a) {
    float* out = q.ptr<float>(a);
    if (detrend == CenDetrend::row_mean) {
      if (power.type() == CV_8UC1) {
        subtract_row_mean(power.ptr<unsigned char>(a), power.cols, out);
      } else {
        subtract_row_mean(power.ptr<float>(a), power.cols, out);
      }
      continue;
    }
    values.resize(static_cast<std::size_t>(power.cols));
    for (int r = 0; r < power.cols; ++r) {
      values[r] = power.type() == CV_8UC1 ? power.at<unsigned char>(a, r) : power.at<float>(a, r);
    }
    subtract_running_median(values.data(), power.cols, out);
  }
}

// Both kernels go through filter2D: its SIMD row filter beats a hand-written running sum even
// for the 17-tap box.
void smooth_rows(const cv::Mat& q, const std::vector<float>& taps, cv::Mat& p) {
  const cv::Mat kernel(1, static_cast<int>(taps.size()), CV_32F, const_cast<float*>(taps.data()));
  // A 1 x K kernel only looks along range; the taps are symmetric, so correlation = convolution.
  cv::filter2D(q, p, CV_32F, kernel, cv::Point(-1, -1), 0.0, kReflectBorder);
}

// sigma_a from the negative part min(q, 0) of the row; OpenCV's vectorised min, count and norm
// (accumulated in double) are several times faster than a scalar loop around a 50/50 branch.
std::optional<double> noise_sigma(const float* q, int count, CenSigmaConvention convention,
                                  cv::Mat& negative_part) {
  const cv::Mat row(1, count, CV_32F, const_cast<float*>(q));
  cv::min(row, 0.0, negative_part);
  const int negatives = cv::countNonZero(negative_part);
  if (negatives == 0) return std::nullopt;
  const double factor = convention == CenSigmaConvention::negative_rms_x2 ? 2.0 : 1.0;
  return std::sqrt(factor * cv::norm(negative_part, cv::NORM_L2SQR) / negatives);
}

// Reused buffers of one row's response computation.
struct ResponseScratch {
  cv::Mat negative_part;                // min(q, 0)
  std::vector<unsigned char> may_pass;  // per bin: 1 when |q| + |p| exceeds the skip bound
  std::vector<int> bins;                // the bins whose response is computed
  std::vector<double> exponent;         // two Gaussian exponents per bin, then their exponentials
  std::vector<double> response;         // y at those bins
};

// y(r) = q (1 - G(q - p)) + p (G(q - p) - G(p)), G(x) = exp(-x^2 / (2 sigma^2)), at
// scratch.bins. The exponentials go through cv::exp in one batch: it is vectorised, five times
// faster than std::exp per bin, and within 1e-12 relative of it.
void compute_responses(const float* q, const float* p, double sigma, ResponseScratch& scratch) {
  const double inverse_two_sigma_squared = 1.0 / (2.0 * sigma * sigma);
  const std::size_t count = scratch.bins.size();
  scratch.exponent.resize(2 * count);
  for (std::size_t i = 0; i < count; ++i) {
    const double qv = q[scratch.bins[i]];
    const double pv = p[scratch.bins[i]];
    scratch.exponent[2 * i] = -(qv - pv) * (qv - pv) * inverse_two_sigma_squared;
    scratch.exponent[2 * i + 1] = -pv * pv * inverse_two_sigma_squared;
  }
  scratch.response.resize(count);
  if (count == 0) return;
  cv::Mat exponents(1, static_cast<int>(2 * count), CV_64F, scratch.exponent.data());
  cv::exp(exponents, exponents);
  for (std::size_t i = 0; i < count; ++i) {
    const double qv = q[scratch.bins[i]];
    const double pv = p[scratch.bins[i]];
    const double g_difference = scratch.exponent[2 * i];
    const double g_smoothed = scratch.exponent[2 * i + 1];
    scratch.response[i] = qv * (1.0 - g_difference) + pv * (g_difference - g_smoothed);
  }
}

// Appends the features of one row to `features`.
void row_features(const float* q, const float* p, int count, const Cen2018Params& params,
                  ResponseScratch& scratch, std::vector<int>& features) {
  const std::optional<double> sigma =
      noise_sigma(q, count, params.sigma_convention, scratch.negative_part);
  if (!sigma) return;  // no negative bin: sigma_a undefined, no features
  const double threshold = params.z_q * *sigma;
  // |y| <= |q| + |p| because both Gaussians lie in (0, 1]: bins under that bound cannot pass,
  // which spares the exponentials on ~90% of the bins. The 1e-5 margin covers float rounding of
  // |q| + |p|, so no bin that could pass is ever skipped.
  const auto skip_bound = static_cast<float>(threshold * (1.0 - 1e-5));
  scratch.may_pass.resize(static_cast<std::size_t>(count));
  unsigned char* may_pass = scratch.may_pass.data();
  for (int r = 0; r < count; ++r) {  // vectorised: no branch, one byte per bin
    may_pass[r] = std::abs(q[r]) + std::abs(p[r]) > skip_bound ? 1 : 0;
  }
  scratch.bins.clear();
  int r = 0;
  for (; r + 8 <= count; r += 8) {  // skip 8 bins at a time where none may pass
    std::uint64_t word;
    std::memcpy(&word, may_pass + r, sizeof word);
    if (word == 0) continue;
    for (int i = r; i < r + 8; ++i) {
      if (may_pass[i] != 0) scratch.bins.push_back(i);
    }
  }
  for (; r < count; ++r) {
    if (may_pass[r] != 0) scratch.bins.push_back(r);
  }
  compute_responses(q, p, *sigma, scratch);

  // Runs of consecutive candidate bins [start, start + length) -> one feature each.
  auto emit = [&](int start, int length) {
    const int bin = start + length / 2;
    if (bin > params.min_range_bins) features.push_back(bin);
  };
  int run_start = -1;
  int run_end = -1;  // one past the run's last bin
  for (std::size_t i = 0; i < scratch.bins.size(); ++i) {
    if (!(scratch.response[i] > threshold)) continue;
    const int bin = scratch.bins[i];
    if (bin != run_end) {
      if (run_start >= 0) emit(run_start, run_end - run_start);
      run_start = bin;
    }
    run_end = bin + 1;
  }
  if (run_start >= 0) emit(run_start, run_end - run_start);
}

void check_power(const cv::Mat& power) {
  if (power.empty() || (power.type() != CV_8UC1 && power.type() != CV_32FC1)) {
    throw std::invalid_argument(
        "cen2018: expected a non-empty CV_8UC1 or CV_32FC1 A x R image, got " +
        std::to_string(power.rows) + " x " + std::to_string(power.cols) + " of type " +
        cv::typeToString(power.type()));
  }
}

cv::Mat row_as_image(std::span<const float> row) {
  if (row.empty()) throw std::invalid_argument("cen2018: empty row");
  return cv::Mat(1, static_cast<int>(row.size()), CV_32F, const_cast<float*>(row.data()));
}

}  // namespace

std::vector<float> cen2018_kernel(const Cen2018Params& params) {
  check_params(params);
  if (params.kernel == CenKernel::box) {
    return std::vector<float>(kCenBoxLength, 1.0f / kCenBoxLength);
  }
  const int radius = static_cast<int>(std::floor(3.0 * params.sigma + 0.5));
  std::vector<double> weights;
  double total = 0.0;
  for (int i = -radius; i <= radius; ++i) {
    weights.push_back(std::exp(-0.5 * i * i / (params.sigma * params.sigma)));
    total += weights.back();
  }
  std::vector<float> taps;
  for (const double w : weights) taps.push_back(static_cast<float>(w / total));
  return taps;
}

PolarFeatures extract_cen2018_features(const cv::Mat& power, const Cen2018Params& params) {
  check_power(power);
  const std::vector<float> taps = cen2018_kernel(params);
  PolarFeatures features(0, power.cols);
  // Blocks of rows keep q and p small enough to stay in cache between the stages and reuse
  // their memory, instead of two fresh 5 MB images per scan.
  constexpr int kBlockRows = 32;
  cv::Mat q;
  cv::Mat p;
  ResponseScratch scratch;
  std::vector<int> bins;
  for (int first = 0; first < power.rows; first += kBlockRows) {
    const int rows = std::min(kBlockRows, power.rows - first);
    detrend_rows(power.rowRange(first, first + rows), params.detrend, q);
    smooth_rows(q, taps, p);
    for (int a = 0; a < rows; ++a) {
      bins.clear();
      row_features(q.ptr<float>(a), p.ptr<float>(a), power.cols, params, scratch, bins);
      features.add_azimuth(bins);
    }
  }
  return features;
}

PolarFeatures extract_cen2018_features(const PolarImage& scan, const Cen2018Params& params) {
  return extract_cen2018_features(scan.power, params);
}

std::vector<int> cen2018_row_features(std::span<const float> row, const Cen2018Params& params) {
  const PolarFeatures features = extract_cen2018_features(row_as_image(row), params);
  const auto bins = features.azimuth(0);
  return {bins.begin(), bins.end()};
}

Cen2018RowTrace cen2018_row_trace(std::span<const float> row, const Cen2018Params& params) {
  const cv::Mat image = row_as_image(row);
  const std::vector<float> taps = cen2018_kernel(params);
  cv::Mat q;
  cv::Mat p;
  detrend_rows(image, params.detrend, q);
  smooth_rows(q, taps, p);
  const int count = image.cols;
  Cen2018RowTrace trace;
  trace.detrended.assign(q.ptr<float>(0), q.ptr<float>(0) + count);
  trace.smoothed.assign(p.ptr<float>(0), p.ptr<float>(0) + count);
  ResponseScratch scratch;
  trace.noise_sigma =
      noise_sigma(q.ptr<float>(0), count, params.sigma_convention, scratch.negative_part);
  trace.response.assign(static_cast<std::size_t>(count), 0.0);
  if (trace.noise_sigma) {
    for (int r = 0; r < count; ++r) scratch.bins.push_back(r);
    compute_responses(q.ptr<float>(0), p.ptr<float>(0), *trace.noise_sigma, scratch);
    trace.response = scratch.response;
  }
  row_features(q.ptr<float>(0), p.ptr<float>(0), count, params, scratch, trace.features);
  return trace;
}

}  // namespace radarpr
