#include "descriptors/features/cen2018.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "descriptors/features/cen2018_avx512.hpp"
#include "descriptors/features/cen2018_paths.hpp"
#include "descriptors/features/cen2018_responses.hpp"
#include "descriptors/features/cen2018_row_passes.hpp"

namespace radarpr {
namespace {

using cen2018_detail::bins_above;
using cen2018_detail::byte_candidates;
using cen2018_detail::byte_candidates_avx512;
using cen2018_detail::byte_row_mean;
using cen2018_detail::byte_row_mean_avx512;
using cen2018_detail::CandidateTest;
using cen2018_detail::classify_responses;
using cen2018_detail::decide_candidates_avx512;
using cen2018_detail::dot_product;
using cen2018_detail::negative_part;
using cen2018_detail::NegativePart;
using cen2018_detail::RowPath;
using cen2018_detail::subtract_byte_row_mean;
using cen2018_detail::Verdict;
using cen2018_detail::window_dot_products;

// The sample that index i of a row of `count` samples reads beyond the row's ends: scipy.ndimage's
// 'reflect' mode repeats the edge sample (d c b a | a b c d | d c b a), unlike a mirror about it
// (d c b | a b c d | c b a); an index still outside after one reflection (a row shorter than the
// kernel) is reflected again.
int reflected_index(int i, int count) {
  if (count == 1) return 0;
  while (i < 0 || i >= count) i = i < 0 ? -i - 1 : 2 * count - 1 - i;
  return i;
}

// The rows an extraction reads, row a at a * cols: bytes (a scan) or float32 values (rows
// given as floats); exactly one of the two is set.
struct ImageRows {
  const unsigned char* bytes = nullptr;
  const float* values = nullptr;
  int rows = 0;
  int cols = 0;
  const unsigned char* byte_row(int a) const {
    return bytes + static_cast<std::size_t>(a) * static_cast<std::size_t>(cols);
  }
  const float* value_row(int a) const {
    return values + static_cast<std::size_t>(a) * static_cast<std::size_t>(cols);
  }
};

// max |x exp(-x^2 / (2 sigma^2))| = sigma exp(-1/2), at x = sigma; per unit sigma, rounded up.
constexpr double kOneOverRootE = 0.60653065971263343;

// The smallest q a bin needs for y > threshold to be possible. y = q - d G(d) - p G(p) with
// d = q - p, and each x G(x) lies within sigma / sqrt(e) of 0, so y <= q + 2 sigma / sqrt(e).
// For q >= 0 one of the two terms is <= 0 (p <= q/2 makes d >= 0, p >= q/2 makes p >= 0), so
// y <= q + sigma / sqrt(e); when the threshold is at least 2 sigma / sqrt(e), no bin with q < 0
// can pass. About 1.7% of MulRan bins lie above it at z_q = 6 (1% pass).
double candidate_bound(double threshold, double sigma) {
  if (threshold >= 2.0 * kOneOverRootE * sigma) return threshold - kOneOverRootE * sigma;
  return threshold - 2.0 * kOneOverRootE * sigma;
}

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
    padded.push_back(x[reflected_index(i, count)]);
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

void subtract_row_mean(const float* x, int count, float* q) {
  double sum = 0.0;
  for (int r = 0; r < count; ++r) sum += x[r];
  const auto mean = static_cast<float>(sum / count);
  for (int r = 0; r < count; ++r) q[r] = x[r] - mean;
}

// The smoothing taps, and a fixed-point copy of them for the candidate test of uint8 rows:
// fixed[k] = round(taps[k] 2^shift), zero-padded to a multiple of 16, the largest shift that
// keeps every tap in 16 bits.
struct Smoothing {
  std::vector<float> taps;
  int radius = 0;
  std::vector<std::int16_t> fixed;
  double fixed_scale = 1.0;  // 2^-shift
  double fixed_sum = 0.0;    // sum of fixed
  double fixed_error = 0.0;  // sum over k of |fixed[k] 2^-shift - taps[k]|
};

Smoothing smoothing_of(const Cen2018Params& params) {
  Smoothing smoothing;
  smoothing.taps = cen2018_kernel(params);
  smoothing.radius = static_cast<int>(smoothing.taps.size() / 2);
  const float largest = *std::max_element(smoothing.taps.begin(), smoothing.taps.end());
  int shift = 0;
  // The integer sums stay below 255 * 2^22 * sum(taps) < 2^31.
  while (shift < 22 && std::ldexp(static_cast<double>(largest), shift + 1) < 32767.0) ++shift;
  smoothing.fixed_scale = std::ldexp(1.0, -shift);
  smoothing.fixed.assign((smoothing.taps.size() + 15) / 16 * 16, 0);
  for (std::size_t k = 0; k < smoothing.taps.size(); ++k) {
    const double fixed = std::round(std::ldexp(static_cast<double>(smoothing.taps[k]), shift));
    smoothing.fixed[k] = static_cast<std::int16_t>(fixed);
    smoothing.fixed_sum += fixed;
    smoothing.fixed_error += std::abs(fixed * smoothing.fixed_scale - smoothing.taps[k]);
  }
  return smoothing;
}

// Work buffers of one row, reused from row to row.
struct RowScratch {
  std::vector<float> padded;  // q with `radius` reflected samples on either side
  std::vector<float> values;  // the row as float, for the running median
  // Candidate bins, the only ones where p and y are computed: bins[0 .. bin_count), with room
  // for a row's count + 64 (the candidate passes write whole steps).
  std::vector<int> bins;
  std::size_t bin_count = 0;
  std::vector<std::uint64_t> passing;       // one bit per bin of the row: y > threshold
  std::vector<float> detrended;             // q at those bins
  std::vector<float> smoothed;              // p at those bins
  std::vector<Verdict> verdicts;            // y > threshold at those bins, from the float test
  std::vector<int> undecided;               // the bins the float test left open (AVX-512 path)
  std::vector<int> run_starts;              // the runs of passing bins: first bins
  std::vector<int> run_ends;                // and one past their last
  std::vector<std::uint64_t> band;          // the candidates as bits (AVX-512 path)
  std::vector<std::uint16_t> chunk_passes;  // work space of decide_candidates_avx512
  std::vector<float> exact_detrended;       // q at the bins the float test left open
  std::vector<float> exact_smoothed;        // p there, exact
  std::vector<float> window;                // one smoothing window of q, read from the bytes
  // The bytes of a row's ends with their reflection, for the fixed-point windows there: indices
  // [-radius, radius + length) and [count - length, count + length).
  std::vector<unsigned char> left_edge;
  std::vector<unsigned char> right_edge;
  std::vector<const unsigned char*> windows;  // the candidates' fixed-point windows
  std::vector<std::int32_t> sums;             // their integer products with the taps
  std::vector<double> exponent;  // two Gaussian exponents per bin, then their exponentials
  std::vector<double> response;  // y at those bins
};

// The detrended row and the statistics of its negative part.
struct DetrendedRow {
  // q[-radius] .. q[count - 1 + radius] are readable; null for a uint8 row smoothed by the box,
  // which is read from its bytes only.
  const float* q = nullptr;
  NegativePart negative;
  // A uint8 row detrended by its mean: q[r] = float(bytes[r]) - mean, so the candidate test can
  // run on the bytes. Null otherwise.
  const unsigned char* bytes = nullptr;
  float mean = 0.0f;
};

// The least byte value v with float(v) - mean > bound (256 when none): q = float(x) - mean is
// non-decreasing in x, so q > bound exactly where x >= that value. It lies within a rounding of
// mean + bound: the search starts there and steps to it (a step or two, instead of a binary
// search whose branches cannot be predicted).
int least_byte_above(float mean, float bound) {
  const auto passes = [mean, bound](int v) { return static_cast<float>(v) - mean > bound; };
  const double guess = std::ceil(static_cast<double>(mean) + static_cast<double>(bound));
  int v = std::isnan(guess) ? 256 : static_cast<int>(std::clamp(guess, 0.0, 256.0));
  while (v > 0 && passes(v - 1)) --v;
  while (v < 256 && !passes(v)) ++v;
  return v;
}

// q = P - trend of row `a`, in float32, written into scratch.padded between `radius` reflected
// samples on either side (the smoothing's border, scipy 'reflect'). uint8 rows are read
// directly, without a converted copy of the image.
DetrendedRow detrended_row(const ImageRows& image, int a, CenDetrend detrend, int radius,
                           bool bytes_suffice, RowPath path, RowScratch& scratch) {
  const int count = image.cols;
  scratch.padded.resize(static_cast<std::size_t>(count + 2 * radius));
  float* q = scratch.padded.data() + radius;
  DetrendedRow row{q, {}};
  if (detrend == CenDetrend::row_mean && image.bytes != nullptr) {
    row.bytes = image.byte_row(a);
    if (bytes_suffice) {
      row.q = nullptr;
      row.negative = path == RowPath::avx512 ? byte_row_mean_avx512(row.bytes, count, row.mean)
                                             : byte_row_mean(row.bytes, count, row.mean);
      return row;
    }
    row.negative = subtract_byte_row_mean(row.bytes, count, q, row.mean);
  } else {
    if (detrend == CenDetrend::row_mean) {
      subtract_row_mean(image.value_row(a), count, q);
    } else if (image.bytes != nullptr) {
      const unsigned char* bytes = image.byte_row(a);
      scratch.values.assign(bytes, bytes + count);
      subtract_running_median(scratch.values.data(), count, q);
    } else {
      subtract_running_median(image.value_row(a), count, q);
    }
    row.negative = negative_part(q, count);
  }
  if (radius <= count) {
    for (int i = 1; i <= radius; ++i) {
      q[-i] = q[i - 1];
      q[count - 1 + i] = q[count - i];
    }
  } else {  // the border reflects more than once
    for (int i = 1; i <= radius; ++i) {
      q[-i] = q[reflected_index(-i, count)];
      q[count - 1 + i] = q[reflected_index(count - 1 + i, count)];
    }
  }
  return row;
}

// p at one bin: the taps against q[r - radius .. r + radius], i.e. `window` = q + r - radius.
// Computed only at candidate bins, this replaces a full-row convolution (103 taps x 3360 bins per
// row for the Gaussian).
float smoothed_at(const float* window, const std::vector<float>& taps) {
  return dot_product(taps.data(), window, taps.size());
}

// sigma_a; empty when no bin of q is negative.
std::optional<double> noise_sigma(const NegativePart& part, CenSigmaConvention convention) {
  if (part.count == 0) return std::nullopt;
  const double factor = convention == CenSigmaConvention::negative_rms_x2 ? 2.0 : 1.0;
  return std::sqrt(factor * part.sum_of_squares / part.count);
}

// y(r) = q (1 - G(q - p)) + p (G(q - p) - G(p)), G(x) = exp(-x^2 / (2 sigma^2)), for `count`
// bins of q values `q` and p values `p`, into scratch.response. The extraction needs it only at
// the few bins the float test leaves open (classify_responses), so the exponentials are plain
// std::exp (within an ulp), without an image library's batch version.
void compute_responses(const float* q, const float* p, std::size_t count, double sigma,
                       RowScratch& scratch) {
  const double inverse_two_sigma_squared = 1.0 / (2.0 * sigma * sigma);
  scratch.response.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const double qv = q[i];
    const double pv = p[i];
    const double g_difference = std::exp(-(qv - pv) * (qv - pv) * inverse_two_sigma_squared);
    const double g_smoothed = std::exp(-pv * pv * inverse_two_sigma_squared);
    scratch.response[i] = qv * (1.0 - g_difference) + pv * (g_difference - g_smoothed);
  }
}

// q at bins [bin - radius, bin + radius] of a uint8 row detrended by its mean, reflected at the
// ends like scratch.padded: the same float values as that window of q.
const float* byte_window(const DetrendedRow& row, int count, int bin, int radius,
                         RowScratch& scratch) {
  scratch.window.resize(static_cast<std::size_t>(2 * radius + 1));
  for (int k = -radius; k <= radius; ++k) {
    const int r = bin + k >= 0 && bin + k < count ? bin + k : reflected_index(bin + k, count);
    scratch.window[static_cast<std::size_t>(k + radius)] =
        static_cast<float>(row.bytes[r]) - row.mean;
  }
  return scratch.window.data();
}

// The windows of the fixed-point products of a uint8 row (smooth_candidates): bins in [radius,
// last_inside] read row.bytes + bin - radius in place; the others read the row's reflected ends,
// scratch.left_edge + bin (indices [-radius, radius + length)) and
// scratch.right_edge + bin - right_origin (indices [count - length, count + length)).
struct FixedWindows {
  int last_inside = 0;
  int right_origin = 0;
};

FixedWindows fixed_windows(int count, const Smoothing& smoothing) {
  const int span = static_cast<int>(smoothing.fixed.size());
  return {count - span + smoothing.radius, smoothing.radius + count - span};
}

// The row's bytes at indices [first, first + size), reflected where outside [0, count): the part
// inside copied, the parts outside (at most one reflection away unless the row is short) read
// backwards.
void reflected_bytes(const unsigned char* bytes, int count, int first, int size,
                     std::vector<unsigned char>& edge) {
  edge.resize(static_cast<std::size_t>(size));
  const auto out = [&edge, first](int r) -> unsigned char& {
    return edge[static_cast<std::size_t>(r - first)];
  };
  const int end = first + size;
  if (first < -count || end > 2 * count) {  // more than one reflection
    for (int r = first; r < end; ++r) out(r) = bytes[reflected_index(r, count)];
    return;
  }
  for (int r = first; r < std::min(end, 0); ++r) out(r) = bytes[-r - 1];
  const int inside_first = std::max(first, 0);
  const int inside_end = std::min(end, count);
  if (inside_first < inside_end) {
    std::copy(bytes + inside_first, bytes + inside_end, &out(inside_first));
  }
  for (int r = std::max(first, count); r < end; ++r) out(r) = bytes[2 * count - r - 1];
}

void fill_left_edge(const DetrendedRow& row, int count, const Smoothing& smoothing,
                    RowScratch& scratch) {
  const int radius = smoothing.radius;
  const int span = static_cast<int>(smoothing.fixed.size());
  reflected_bytes(row.bytes, count, -radius, 2 * radius + span, scratch.left_edge);
}

void fill_right_edge(const DetrendedRow& row, int count, const Smoothing& smoothing,
                     RowScratch& scratch) {
  const int span = static_cast<int>(smoothing.fixed.size());
  reflected_bytes(row.bytes, count, count - span, 2 * span, scratch.right_edge);
}

// How far the fixed-point p of a uint8 row may lie from the float p of smoothed_at
// (smooth_candidates).
double fixed_point_p_error(const DetrendedRow& row, const Smoothing& smoothing) {
  constexpr double kUnit = 0x1p-24;
  const double taps = static_cast<double>(smoothing.taps.size());
  return (smoothing.fixed_error + (taps + 11.0) * kUnit) *
         (static_cast<double>(row.negative.largest_magnitude) + 1.0);
}

// p at the candidate bins (scratch.smoothed) and q there (scratch.detrended). Returns how far the
// p values may lie from those of smoothed_at: 0 when they are those values. A uint8 row takes p
// from the fixed-point taps in exact integer arithmetic, (D - mean sum(fixed)) 2^-shift in double:
// that lies within fixed_error * largest |q| of sum t q, and the float dot product of smoothed_at
// within (L + 10) u largest |q| of that (u = 2^-24, sum t = 1); rounding to float adds u |p|.
double smooth_candidates(const DetrendedRow& row, int count, const Smoothing& smoothing,
                         RowScratch& scratch) {
  const int radius = smoothing.radius;
  const std::size_t n = scratch.bin_count;
  scratch.detrended.resize(n);
  scratch.smoothed.resize(n);
  if (row.q != nullptr) {
    for (std::size_t i = 0; i < n; ++i) {
      scratch.detrended[i] = row.q[scratch.bins[i]];
      scratch.smoothed[i] = smoothed_at(row.q + scratch.bins[i] - radius, smoothing.taps);
    }
    return 0.0;
  }
  const std::size_t length = smoothing.fixed.size();
  const double offset = static_cast<double>(row.mean) * smoothing.fixed_sum;
  const FixedWindows windows = fixed_windows(count, smoothing);
  const int last_inside = windows.last_inside;
  bool left_ready = false;
  bool right_ready = false;
  scratch.windows.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const int bin = scratch.bins[i];
    scratch.detrended[i] = static_cast<float>(row.bytes[bin]) - row.mean;
    const unsigned char* window = nullptr;
    if (bin >= radius && bin <= last_inside) {
      window = row.bytes + (bin - radius);
    } else if (bin < radius) {
      if (!left_ready) fill_left_edge(row, count, smoothing, scratch);
      left_ready = true;
      window = scratch.left_edge.data() + bin;
    } else {
      if (!right_ready) fill_right_edge(row, count, smoothing, scratch);
      right_ready = true;
      window = scratch.right_edge.data() + (bin - windows.right_origin);
    }
    scratch.windows[i] = window;
  }
  scratch.sums.resize(n);
  window_dot_products(smoothing.fixed.data(), length, scratch.windows.data(), n,
                      scratch.sums.data());
  for (std::size_t i = 0; i < n; ++i) {
    scratch.smoothed[i] =
        static_cast<float>((static_cast<double>(scratch.sums[i]) - offset) * smoothing.fixed_scale);
  }
  return fixed_point_p_error(row, smoothing);
}

// The bins of a row that pass (y > threshold) among the candidates scratch.bins[0 .. bin_count),
// set in scratch.passing: p and a float test at every candidate, the exact response where the
// float test leaves the verdict open.
void decide_baseline(const DetrendedRow& row, int count, const Smoothing& smoothing, double sigma,
                     double threshold, RowScratch& scratch) {
  const double p_error = smooth_candidates(row, count, smoothing, scratch);
  const std::vector<float>& taps = smoothing.taps;

  // The float test decides most bins; the rest get p exactly and y in double (compute_responses).
  const std::size_t n = scratch.bin_count;
  scratch.verdicts.resize(n);
  classify_responses(scratch.detrended.data(), scratch.smoothed.data(), n, sigma, threshold,
                     p_error, scratch.verdicts.data());
  scratch.exact_detrended.clear();
  scratch.exact_smoothed.clear();
  const int radius = smoothing.radius;
  for (std::size_t i = 0; i < n; ++i) {
    if (scratch.verdicts[i] != Verdict::undecided) continue;
    scratch.exact_detrended.push_back(scratch.detrended[i]);
    scratch.exact_smoothed.push_back(
        p_error == 0.0
            ? scratch.smoothed[i]
            : smoothed_at(byte_window(row, count, scratch.bins[i], radius, scratch), taps));
  }
  compute_responses(scratch.exact_detrended.data(), scratch.exact_smoothed.data(),
                    scratch.exact_detrended.size(), sigma, scratch);

  // The passing candidates as bits (gathered in a register per 64-bin word).
  std::size_t exact = 0;
  std::size_t word = 0;
  std::uint64_t word_bits = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Verdict verdict = scratch.verdicts[i];
    const bool undecided = verdict == Verdict::undecided;
    const bool passes =
        undecided ? scratch.response[exact] > threshold : verdict == Verdict::passes;
    exact += undecided ? 1 : 0;
    const auto bin = static_cast<unsigned>(scratch.bins[i]);
    if (bin / 64 != word) {
      scratch.passing[word] |= word_bits;
      word = bin / 64;
      word_bits = 0;
    }
    word_bits |= static_cast<std::uint64_t>(passes) << (bin % 64);
  }
  scratch.passing[word] |= word_bits;
}

// decide_baseline for a uint8 row read from its bytes only, with AVX-512: the float test runs on
// the candidates in registers (decide_candidates_avx512), the exact response on the bins it
// leaves open.
void decide_avx512(const DetrendedRow& row, int count, const Smoothing& smoothing, double sigma,
                   double threshold, RowScratch& scratch) {
  const std::size_t n = scratch.bin_count;
  if (n == 0) return;
  const FixedWindows windows = fixed_windows(count, smoothing);
  const int* bins = scratch.bins.data();
  if (bins[0] < smoothing.radius) fill_left_edge(row, count, smoothing, scratch);
  if (bins[n - 1] > windows.last_inside) fill_right_edge(row, count, smoothing, scratch);
  CandidateTest test;
  test.bytes = row.bytes;
  test.count = count;
  test.mean = row.mean;
  test.taps = smoothing.fixed.data();
  test.length = smoothing.fixed.size();
  test.radius = smoothing.radius;
  test.last_inside = windows.last_inside;
  test.left_edge = scratch.left_edge.data();
  test.right_edge = scratch.right_edge.data();
  test.right_origin = windows.right_origin;
  test.offset = static_cast<double>(row.mean) * smoothing.fixed_sum;
  test.scale = smoothing.fixed_scale;
  test.sigma = sigma;
  test.threshold = threshold;
  test.p_error = fixed_point_p_error(row, smoothing);
  if (scratch.detrended.size() < n + 32) scratch.detrended.resize(n + 32);
  if (scratch.smoothed.size() < n + 32) scratch.smoothed.resize(n + 32);
  test.detrended = scratch.detrended.data();
  test.smoothed = scratch.smoothed.data();
  if (scratch.undecided.size() < n + 16) scratch.undecided.resize(n + 16);
  if (scratch.chunk_passes.size() < n / 16 + 9) scratch.chunk_passes.resize(n / 16 + 9);
  const std::size_t open =
      decide_candidates_avx512(test, bins, n, scratch.band.data(), scratch.chunk_passes.data(),
                               scratch.passing.data(), scratch.undecided.data());
  if (open == 0) return;
  scratch.exact_detrended.resize(open);
  scratch.exact_smoothed.resize(open);
  for (std::size_t i = 0; i < open; ++i) {
    const int bin = scratch.undecided[i];
    scratch.exact_detrended[i] = static_cast<float>(row.bytes[bin]) - row.mean;
    scratch.exact_smoothed[i] =
        smoothed_at(byte_window(row, count, bin, smoothing.radius, scratch), smoothing.taps);
  }
  compute_responses(scratch.exact_detrended.data(), scratch.exact_smoothed.data(), open, sigma,
                    scratch);
  for (std::size_t i = 0; i < open; ++i) {
    const auto bin = static_cast<unsigned>(scratch.undecided[i]);
    scratch.passing[bin / 64] |= static_cast<std::uint64_t>(scratch.response[i] > threshold)
                                 << (bin % 64);
  }
}

// The runs of consecutive set bits [start, end) of passing[0 .. words) -> one feature each, at
// start + (end - start) / 2, appended to `features` where beyond min_range_bins. A run starts at
// a set bit whose lower neighbour is clear and ends at one whose upper neighbour is clear; starts
// and ends alternate along the row, so the k-th start and the k-th end bound the k-th run. They
// are listed first (a loop per kind, without a branch between kinds), then paired.
void append_run_middles(const std::uint64_t* passing, std::size_t words, int min_range_bins,
                        RowScratch& scratch, std::vector<int>& features) {
  std::size_t runs = 0;
  std::size_t ends_found = 0;
  for (std::size_t w = 0; w < words; ++w) {
    const std::uint64_t bits = passing[w];
    if (bits == 0) continue;
    const std::uint64_t previous = w > 0 ? passing[w - 1] >> 63 : 0;
    const std::uint64_t next = w + 1 < words ? passing[w + 1] << 63 : 0;
    const int base = static_cast<int>(w * 64);
    if (scratch.run_starts.size() < runs + 64) {
      scratch.run_starts.resize(runs + 64 + words * 8);
      scratch.run_ends.resize(runs + 64 + words * 8);
    }
    for (std::uint64_t starts = bits & ~(bits << 1 | previous); starts != 0; starts &= starts - 1) {
      scratch.run_starts[runs++] = base + std::countr_zero(starts);
    }
    for (std::uint64_t ends = bits & ~(bits >> 1 | next); ends != 0; ends &= ends - 1) {
      scratch.run_ends[ends_found++] = base + std::countr_zero(ends) + 1;
    }
  }
  const std::size_t first = features.size();
  features.resize(first + runs);
  std::size_t kept = first;
  for (std::size_t k = 0; k < runs; ++k) {
    const int start = scratch.run_starts[k];
    const int bin = start + (scratch.run_ends[k] - start) / 2;
    features[kept] = bin;
    kept += bin > min_range_bins ? 1 : 0;
  }
  features.resize(kept);
}

// Appends the features of one row to `features`; `row` has taps.size() / 2 reflected samples
// readable on either side (or is read from its bytes).
void row_features(const DetrendedRow& row, int count, const Smoothing& smoothing,
                  const Cen2018Params& params, RowPath path, RowScratch& scratch,
                  std::vector<int>& features) {
  const NegativePart& negative = row.negative;
  const std::optional<double> sigma = noise_sigma(negative, params.sigma_convention);
  if (!sigma) return;  // no negative bin: sigma_a undefined, no features
  const double threshold = params.z_q * *sigma;
  // p and y are computed only where y > threshold is possible (candidate_bound). The margin
  // covers the rounding of y (exponentials within 1e-12 relative, |p| <= max |q|), so no bin that
  // could pass is skipped.
  const double rounding = 1e-6 * (static_cast<double>(negative.largest_magnitude) + *sigma);
  const double bound = candidate_bound(threshold, *sigma) - rounding;
  const float float_bound =
      std::nextafter(static_cast<float>(bound), -std::numeric_limits<float>::infinity());
  if (scratch.bins.size() < static_cast<std::size_t>(count) + 64) {
    scratch.bins.resize(static_cast<std::size_t>(count) + 64);
  }
  const std::size_t words = static_cast<std::size_t>(count) / 64 + 1;
  scratch.passing.assign(words, 0);  // the passing bins, one bit each
  // AVX-512 for a row read from its bytes only (not for the trace, which has q).
  const bool wide = path == RowPath::avx512 && row.bytes != nullptr && row.q == nullptr;
  if (row.bytes != nullptr) {
    // Every |x G(x)| <= sigma / sqrt(e), so y >= q - 2 sigma / sqrt(e): a bin above that passes
    // whatever p is, and needs neither p nor y.
    const double sure = threshold + 2.0 * kOneOverRootE * *sigma + rounding;
    const float float_sure =
        std::nextafter(static_cast<float>(sure), std::numeric_limits<float>::infinity());
    const int least = least_byte_above(row.mean, float_bound);
    const int sure_byte = least_byte_above(row.mean, float_sure);
    if (wide) scratch.band.resize(words);
    scratch.bin_count =
        wide ? byte_candidates_avx512(row.bytes, count, least, sure_byte, scratch.bins.data(),
                                      scratch.passing.data(), scratch.band.data())
             : byte_candidates(row.bytes, count, least, sure_byte, scratch.bins.data(),
                               scratch.passing.data());
  } else {
    scratch.bin_count = bins_above(row.q, count, float_bound, scratch.bins.data());
  }
  if (wide) {
    decide_avx512(row, count, smoothing, *sigma, threshold, scratch);
  } else {
    decide_baseline(row, count, smoothing, *sigma, threshold, scratch);
  }
  append_run_middles(scratch.passing.data(), words, params.min_range_bins, scratch, features);
}

ImageRows byte_rows(const ByteImage& power) {
  if (power.empty()) {
    throw std::invalid_argument("cen2018: expected a non-empty A x R image, got " +
                                std::to_string(power.rows()) + " x " +
                                std::to_string(power.cols()));
  }
  return {power.data(), nullptr, power.rows(), power.cols()};
}

ImageRows float_rows(std::span<const float> values, int range_bins) {
  if (values.empty() || range_bins <= 0 ||
      values.size() % static_cast<std::size_t>(range_bins) != 0 ||
      values.size() / static_cast<std::size_t>(range_bins) >
          static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    throw std::invalid_argument("cen2018: expected a non-empty A x R image of float rows, got " +
                                std::to_string(values.size()) + " values in rows of " +
                                std::to_string(range_bins));
  }
  return {nullptr, values.data(),
          static_cast<int>(values.size() / static_cast<std::size_t>(range_bins)), range_bins};
}

ImageRows row_as_image(std::span<const float> row) {
  if (row.empty()) throw std::invalid_argument("cen2018: empty row");
  if (row.size() > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    throw std::invalid_argument("cen2018: a row of " + std::to_string(row.size()) +
                                " bins is too long");
  }
  return float_rows(row, static_cast<int>(row.size()));
}

PolarFeatures features_of(const ImageRows& image, const Cen2018Params& params, RowPath path) {
  // A feature at bin r is kept only if r > min_range_bins: with no bin beyond it, every scan
  // gives no feature and the descriptor is the same for every scan (found by tie-breaking).
  if (params.min_range_bins >= image.cols - 1) {
    throw std::invalid_argument(
        "cen2018: min_range_bins = " + std::to_string(params.min_range_bins) +
        " leaves no range bin of a scan with " + std::to_string(image.cols) + " (at most " +
        std::to_string(image.cols - 2) + " for these scans)");
  }
  const Smoothing smoothing = smoothing_of(params);
  PolarFeatures features(0, image.cols);
  RowScratch scratch;
  std::vector<int> bins;
  for (int a = 0; a < image.rows; ++a) {
    // A uint8 row is read from its bytes only: p from the fixed-point taps, no float row.
    const DetrendedRow row = detrended_row(image, a, params.detrend, smoothing.radius,
                                           /*bytes_suffice=*/true, path, scratch);
    bins.clear();
    row_features(row, image.cols, smoothing, params, path, scratch, bins);
    features.add_azimuth(bins);
  }
  return features;
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

namespace cen2018_detail {

RowPath fastest_row_path() {
  return has_avx512() ? RowPath::avx512 : RowPath::baseline;
}

PolarFeatures extract_features_with(const ByteImage& power, const Cen2018Params& params,
                                    RowPath path) {
  if (path == RowPath::avx512 && !has_avx512()) {
    throw std::invalid_argument("cen2018: the AVX-512 path needs a processor with AVX-512");
  }
  return features_of(byte_rows(power), params, path);
}

}  // namespace cen2018_detail

PolarFeatures extract_cen2018_features(const ByteImage& power, const Cen2018Params& params) {
  return cen2018_detail::extract_features_with(power, params, cen2018_detail::fastest_row_path());
}

PolarFeatures extract_cen2018_features(const PolarImage& scan, const Cen2018Params& params) {
  return extract_cen2018_features(scan.power, params);
}

PolarFeatures extract_cen2018_features(std::span<const float> values, int range_bins,
                                       const Cen2018Params& params) {
  return features_of(float_rows(values, range_bins), params, cen2018_detail::fastest_row_path());
}

std::vector<int> cen2018_row_features(std::span<const float> row, const Cen2018Params& params) {
  const PolarFeatures features =
      features_of(row_as_image(row), params, cen2018_detail::fastest_row_path());
  const auto bins = features.azimuth(0);
  return {bins.begin(), bins.end()};
}

Cen2018RowTrace cen2018_row_trace(std::span<const float> row, const Cen2018Params& params) {
  const ImageRows image = row_as_image(row);
  const Smoothing smoothing = smoothing_of(params);
  const std::vector<float>& taps = smoothing.taps;
  const int radius = smoothing.radius;
  RowScratch scratch;
  const DetrendedRow detrended = detrended_row(image, 0, params.detrend, radius,
                                               /*bytes_suffice=*/false, RowPath::baseline, scratch);
  const float* q = detrended.q;
  const int count = image.cols;
  Cen2018RowTrace trace;
  trace.detrended.assign(q, q + count);
  for (int r = 0; r < count; ++r) trace.smoothed.push_back(smoothed_at(q + r - radius, taps));
  trace.noise_sigma = noise_sigma(detrended.negative, params.sigma_convention);
  trace.response.assign(static_cast<std::size_t>(count), 0.0);
  if (trace.noise_sigma) {
    scratch.smoothed.assign(trace.smoothed.begin(), trace.smoothed.end());
    compute_responses(q, scratch.smoothed.data(), static_cast<std::size_t>(count),
                      *trace.noise_sigma, scratch);
    trace.response = scratch.response;
  }
  row_features(detrended, count, smoothing, params, RowPath::baseline, scratch, trace.features);
  return trace;
}

}  // namespace radarpr
