#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace radarpr::raplace {

// The axis along which RaPlace's similarity shifts D circularly (descriptors.md §5 step 5).
enum class ShiftAxis {
  theta,  // along the columns: a rotation of the sensor (the paper; rotation-invariant)
  rho,    // along the rows (rho frequencies), as the public code does (parity)
};

// The spectrum of one descriptor matrix along the shift axis, as CircularCorrelation uses it:
// for every harmonic m = 0 .. n/2 (the rest follow by Hermitian symmetry) and every line (row for
// theta, column for rho), the DFT coefficient; stored harmonic-major.
struct LineSpectra {
  std::vector<double> real;
  std::vector<double> imag;
  bool all_zero = true;  // every input value was 0
};

// What the correlation has computed, for tests and measurements that check where the work goes
// (a search computes each value's spectra once, and a pair costs one spectral product and one
// inverse transform). Spectra are counted for the whole process; the per-pair work, which must
// stay cheap, for the calling thread only.
struct CorrelationWork {
  std::size_t spectra = 0;             // spectra() calls, all threads
  std::size_t spectral_products = 0;   // sum over lines of conj(Fq) Fi, this thread
  std::size_t inverse_transforms = 0;  // all n shifts from one cross spectrum, this thread
};
CorrelationWork correlation_work();

struct CorrelationPeak {
  double value = 0.0;
  int shift = 0;  // in [0, n); the smallest among equal values
};

// C(Dq, Di) = max over s of sum over all elements of Dq_s * Di, where Dq_s is Dq circularly
// shifted by s along the axis: Dq_s[.., t] = Dq[.., (t - s) mod n] (so a peak at s means Di
// looks like Dq moved s steps towards larger indices). Computed through the DFT along the axis:
// the correlation's spectrum is sum over lines of conj(Fq) * Fi, and n inverse sums give every
// shift at once. n is only 18 (theta) or 20 (rho) at the defaults, so plain DFT sums with
// precomputed twiddles beat any FFT set-up; spectra are computed once per value and reused per
// pair (see RaplaceDescriptor::prepare_distances). Immutable: safe to share between threads.
class CircularCorrelation {
 public:
  // For rows x cols row-major matrices; throws std::invalid_argument unless both are >= 1.
  CircularCorrelation(int rows, int cols, ShiftAxis axis);

  int rows() const { return rows_; }
  int cols() const { return cols_; }
  int length() const { return length_; }  // n: the number of shifts

  // Throws std::invalid_argument when `values` does not hold rows x cols finite numbers.
  LineSpectra spectra(std::span<const float> values) const;
  CorrelationPeak max_correlation(const LineSpectra& query, const LineSpectra& database) const;

 private:
  int rows_ = 0;
  int cols_ = 0;
  ShiftAxis axis_ = ShiftAxis::theta;
  int length_ = 0;     // n, the shift axis's length
  int lines_ = 0;      // the other axis's length
  int harmonics_ = 0;  // n / 2 + 1
  // cos and sin of 2 pi (m t mod n) / n, index m * n + t.
  std::vector<double> cos_;
  std::vector<double> sin_;
};

}  // namespace radarpr::raplace
