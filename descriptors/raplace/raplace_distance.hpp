#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "descriptors/descriptor.hpp"
#include "descriptors/raplace/circular_correlation.hpp"
#include "descriptors/raplace/correlation_screen.hpp"
#include "descriptors/screened_distances.hpp"

namespace radarpr {

// RaPlace's distance from its similarity C (descriptors.md §5 step 6). Not symmetric: the query's
// self-similarity sets the scale.
enum class RaplaceDistance {
  normalized,     // (C(Dq,Dq) - C(Dq,Di)) / C(Dq,Dq), the paper (default)
  raw_over_1000,  // (C(Dq,Dq) - C(Dq,Di)) / 1000, the public code's score (parity)
};

// The distance given C(Dq,Dq) (`self`) and C(Dq,Di) (`cross`). normalized with C(Dq,Dq) <= 0
// (an all-zero query, e.g. an empty scan - then C(Dq,Di) = 0 for every Di, and the formula is
// 0 / 0): 0 when Di is all zero too (the two are the same), else 1 (the distance of an
// uncorrelated value). raw_over_1000 needs no guard.
double raplace_distance_from(RaplaceDistance kind, double self, double cross,
                             bool database_all_zero);

// Distances of every query to every database value with the spectra along the shift axis and
// every C(Dq,Dq) computed once up front, so a pair costs one spectral product, the inverse sums
// and a max. Gives exactly what RaplaceDescriptor::distance gives (the same functions on the
// same numbers). Keeps no reference to its inputs; immutable, so thread-safe.
// Its scores (ScreenedDistances) are C(Dq, Di) in float from raplace::CorrelationScreen, so that
// an exhaustive search computes distance() only near the top.
class RaplacePreparedDistances final : public PreparedDistances, public ScreenedDistances {
 public:
  // `queries` and `database` may be the same vector: its spectra are then computed once.
  // Throws std::invalid_argument for a value of another shape than `correlation`'s.
  RaplacePreparedDistances(const raplace::CircularCorrelation& correlation, RaplaceDistance kind,
                           const std::vector<DescriptorValue>& queries,
                           const std::vector<DescriptorValue>& database);

  double distance(std::size_t query, std::size_t database_index) const override;
  void scores(const std::size_t* queries, std::size_t query_count, std::size_t begin,
              std::size_t end, float* out) const override;
  // Not finite for a normalized distance whose query is all zero (C(Dq,Dq) <= 0: the distance is
  // then 0 or 1, not ordered by C(Dq,Di)).
  double score_error(std::size_t query) const override;

 private:
  const std::vector<raplace::LineSpectra>& database_spectra() const {
    return shared_ ? query_spectra_ : database_spectra_;
  }

  raplace::CircularCorrelation correlation_;
  RaplaceDistance kind_;
  bool shared_ = false;
  std::vector<raplace::LineSpectra> query_spectra_;
  std::vector<raplace::LineSpectra> database_spectra_;  // empty when shared_
  std::vector<double> self_similarity_;                 // C(Dq,Dq) per query
  std::optional<raplace::CorrelationScreen> screen_;    // set by the constructor
};

}  // namespace radarpr
