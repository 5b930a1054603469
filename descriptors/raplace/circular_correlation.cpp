#include "descriptors/raplace/circular_correlation.hpp"

#include <array>
#include <atomic>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace radarpr::raplace {
namespace {

std::atomic<std::size_t> spectra_computed{0};
thread_local std::size_t spectral_products = 0;
thread_local std::size_t inverse_transforms = 0;

}  // namespace

CorrelationWork correlation_work() {
  return {spectra_computed.load(), spectral_products, inverse_transforms};
}

CircularCorrelation::CircularCorrelation(int rows, int cols, ShiftAxis axis)
    : rows_(rows), cols_(cols), axis_(axis) {
  if (rows < 1 || cols < 1) {
    throw std::invalid_argument("raplace: the correlation needs a matrix of >= 1 x 1 values, got " +
                                std::to_string(rows) + " x " + std::to_string(cols));
  }
  length_ = axis == ShiftAxis::theta ? cols : rows;
  lines_ = axis == ShiftAxis::theta ? rows : cols;
  harmonics_ = length_ / 2 + 1;
  const auto table_size = static_cast<std::size_t>(harmonics_) * static_cast<std::size_t>(length_);
  cos_.resize(table_size);
  sin_.resize(table_size);
  for (int m = 0; m < harmonics_; ++m) {
    for (int t = 0; t < length_; ++t) {
      // Reducing m t mod n first keeps the angle small and the table exactly periodic.
      const double angle = 2.0 * std::numbers::pi * ((m * t) % length_) / length_;
      const auto index = static_cast<std::size_t>(m * length_ + t);
      cos_[index] = std::cos(angle);
      sin_[index] = std::sin(angle);
    }
  }
}

LineSpectra CircularCorrelation::spectra(std::span<const float> values) const {
  const auto expected = static_cast<std::size_t>(rows_) * static_cast<std::size_t>(cols_);
  if (values.size() != expected) {
    throw std::invalid_argument("raplace: expected a " + std::to_string(rows_) + " x " +
                                std::to_string(cols_) + " descriptor (" + std::to_string(expected) +
                                " values), got " + std::to_string(values.size()) + " values");
  }
  spectra_computed.fetch_add(1, std::memory_order_relaxed);
  LineSpectra result;
  const auto size = static_cast<std::size_t>(harmonics_) * static_cast<std::size_t>(lines_);
  result.real.assign(size, 0.0);
  result.imag.assign(size, 0.0);
  // Element t of line l: along a row for theta, down a column for rho.
  const int line_stride = axis_ == ShiftAxis::theta ? cols_ : 1;
  const int step = axis_ == ShiftAxis::theta ? 1 : cols_;
  for (int l = 0; l < lines_; ++l) {
    for (int t = 0; t < length_; ++t) {
      const double x = values[static_cast<std::size_t>(l * line_stride + t * step)];
      if (!std::isfinite(x)) {
        throw std::invalid_argument("raplace: descriptor value " +
                                    std::to_string(l * line_stride + t * step) + " is not finite");
      }
      if (x == 0.0) continue;
      result.all_zero = false;
      for (int m = 0; m < harmonics_; ++m) {
        // F[m] = sum_t x[t] exp(-2 pi i m t / n)
        const auto twiddle = static_cast<std::size_t>(m * length_ + t);
        const auto out = static_cast<std::size_t>(m * lines_ + l);
        result.real[out] += x * cos_[twiddle];
        result.imag[out] -= x * sin_[twiddle];
      }
    }
  }
  return result;
}

CorrelationPeak CircularCorrelation::max_correlation(const LineSpectra& query,
                                                     const LineSpectra& database) const {
  const auto size = static_cast<std::size_t>(harmonics_) * static_cast<std::size_t>(lines_);
  if (query.real.size() != size || database.real.size() != size || query.imag.size() != size ||
      database.imag.size() != size) {
    throw std::invalid_argument("raplace: spectra of " + std::to_string(query.real.size()) +
                                " and " + std::to_string(database.real.size()) +
                                " coefficients where " + std::to_string(size) +
                                " were expected (values of another descriptor shape?)");
  }
  // The correlation's spectrum R[m] = sum over lines of conj(Fq[m]) * Fi[m]. On the stack for
  // the usual sizes: this runs once per pair, and a heap allocation would cost as much as the sums.
  constexpr int kStackHarmonics = 128;
  std::array<double, 2 * kStackHarmonics> stack_buffer;
  std::vector<double> heap_buffer;
  double* cross_real = stack_buffer.data();
  if (harmonics_ > kStackHarmonics) {
    heap_buffer.resize(2 * static_cast<std::size_t>(harmonics_));
    cross_real = heap_buffer.data();
  }
  double* cross_imag = cross_real + harmonics_;
  ++spectral_products;
  for (int m = 0; m < harmonics_; ++m) {
    double re = 0.0;
    double im = 0.0;
    const auto first = static_cast<std::size_t>(m * lines_);
    for (std::size_t k = first; k < first + static_cast<std::size_t>(lines_); ++k) {
      re += query.real[k] * database.real[k] + query.imag[k] * database.imag[k];
      im += query.real[k] * database.imag[k] - query.imag[k] * database.real[k];
    }
    cross_real[m] = re;
    cross_imag[m] = im;
  }
  // corr[s] = (1/n) sum over all n harmonics of R[m] exp(2 pi i m s / n); the harmonics above
  // n/2 are the conjugates of those below, so the ones strictly between 0 and n/2 count twice.
  ++inverse_transforms;
  const bool has_nyquist = length_ % 2 == 0;
  const int last_paired = has_nyquist ? harmonics_ - 2 : harmonics_ - 1;
  CorrelationPeak peak;
  for (int s = 0; s < length_; ++s) {
    double sum = cross_real[0];
    for (int m = 1; m <= last_paired; ++m) {
      const auto twiddle = static_cast<std::size_t>(m * length_ + s);
      sum += 2.0 * (cross_real[m] * cos_[twiddle] - cross_imag[m] * sin_[twiddle]);
    }
    if (has_nyquist && length_ > 1) {
      sum += (s % 2 == 0 ? 1.0 : -1.0) * cross_real[harmonics_ - 1];
    }
    const double value = sum / length_;
    if (s == 0 || value > peak.value) peak = {value, s};
  }
  return peak;
}

}  // namespace radarpr::raplace
