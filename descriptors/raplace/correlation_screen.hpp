#pragma once

#include <cstddef>
#include <vector>

#include "descriptors/raplace/circular_correlation.hpp"

namespace radarpr::raplace {

// CircularCorrelation's best-shift correlation C(q, j) for one query against many database values
// at once, in float, with a bound on the error, to screen an exhaustive search (the exact values
// then come from CircularCorrelation for the few pairs near the top).
//
// The same two steps as max_correlation: the cross spectrum R[m] = sum over lines of
// conj(Fq[m]) Fj[m], then every shift s from sum over m of w(s, m) R[m]; here for eight database
// values side by side in one 8-float vector (AVX2 and FMA where the processor has them), with the
// database spectra stored eight values at a time, so that the work per pair is a few hundred
// fused multiply-adds and the spectra of a block stream from cache.
//
// Error. Rounding the spectra and cosines to float and the float sums of 2 x lines terms per
// harmonic and 2 x harmonics terms per shift change each correlation by at most
// u (2 lines + 2 harmonics + 4) (4 / n) sum_m |Fq[m]| |Fj[m]| (u = 2^-24, n shifts, |F[m]| the
// norm over lines), itself at most that factor times |Fq| |Fj|. error() returns four times that
// for the largest database norm: a few 1e-5 of C(q, q) for z-scored values at RaPlace's defaults;
// infinite (no bound) for norms of 1e15 or more, where float sums could overflow.
class CorrelationScreen {
 public:
  // `database` may be the same vector as `queries` (single session): its float copy then serves
  // both. Spectra must come from `correlation`.
  CorrelationScreen(const CircularCorrelation& correlation, const std::vector<LineSpectra>& queries,
                    const std::vector<LineSpectra>& database);

  // Queries handled per call: each load of database spectra serves all of them.
  static constexpr std::size_t kQueries = 4;
  // out[i * (end - begin) + j - begin] ~ max_correlation(queries[query[i]], database[j]).value
  // for i < count <= kQueries and j in [begin, end); begin a multiple of 8.
  void max_correlations(const std::size_t* query, std::size_t count, std::size_t begin,
                        std::size_t end, float* out) const;
  double error(std::size_t query) const { return errors_[query]; }

 private:
  int lines_ = 0;
  int harmonics_ = 0;
  int length_ = 0;
  std::size_t features_ = 0;  // floats per value: harmonics x lines x (real, imaginary)
  // Per shift s and harmonic m the weights of Re R[m] and Im R[m]: s-major, 2 x harmonics each.
  std::vector<float> shift_weights_;
  std::vector<float> database_blocks_;  // blocks of 8 values, feature-major, zero-padded
  std::vector<float> query_features_;   // one value after another; empty when shared
  bool shared_ = false;
  std::vector<double> errors_;  // per query
};

}  // namespace radarpr::raplace
