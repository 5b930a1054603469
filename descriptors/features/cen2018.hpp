#pragma once

#include <optional>
#include <span>
#include <vector>

#include "datasets/byte_image.hpp"
#include "datasets/polar_image.hpp"
#include "descriptors/features/polar_features.hpp"

namespace radarpr {

// Cen & Newman 2018 radar point-feature extraction, as specified in descriptors.md §1. Every
// stage works along range, one azimuth row at a time.

enum class CenDetrend {
  row_mean,  // subtract the row's mean (default)
  median,    // subtract a running median of width kCenMedianWindow (the original Cen paper)
};
enum class CenKernel {
  gaussian,  // sigma bins, truncated at 3 sigma, normalised (default)
  box,       // kCenBoxLength taps of 1/kCenBoxLength (the ReFeree journal release)
};
enum class CenSigmaConvention {
  negative_rms,     // sigma_a = sqrt(mean of q^2 over the bins with q < 0) (default)
  negative_rms_x2,  // sqrt(2) times larger, the yeti C++ convention
};

inline constexpr int kCenBoxLength = 17;
inline constexpr int kCenMedianWindow = 200;

struct Cen2018Params {
  CenDetrend detrend = CenDetrend::row_mean;
  CenKernel kernel = CenKernel::gaussian;
  double sigma = 17.0;  // Gaussian standard deviation in range bins; unused by the box kernel
  CenSigmaConvention sigma_convention = CenSigmaConvention::negative_rms;
  double z_q = 6.0;         // the paper's value; every public code uses 3.0
  int min_range_bins = 58;  // a feature at bin r is kept only if r > min_range_bins
};

// The smoothing taps (odd length, centre in the middle, summing to 1). Gaussian: radius
// floor(3 sigma + 0.5) like scipy's gaussian_filter1d(truncate=3), so 103 taps for sigma = 17.
// Throws std::invalid_argument for a sigma that is not finite and positive.
std::vector<float> cen2018_kernel(const Cen2018Params& params);

// Features of a whole A x R scan of bytes. Throws std::invalid_argument on an empty image.
PolarFeatures extract_cen2018_features(const ByteImage& power, const Cen2018Params& params);
PolarFeatures extract_cen2018_features(const PolarImage& scan, const Cen2018Params& params);
// The same for float32 values: `values` holds the rows one after another, `range_bins` each (the
// result does not depend on the scale of the values, and bytes converted to float give the
// features of the bytes). Throws std::invalid_argument when `values` is empty or not a whole
// number of rows.
PolarFeatures extract_cen2018_features(std::span<const float> values, int range_bins,
                                       const Cen2018Params& params);

// The features of one azimuth row (its range bins, increasing): the same code path as the scan
// version, usable on constructed rows.
std::vector<int> cen2018_row_features(std::span<const float> row, const Cen2018Params& params);

// Every intermediate of one row, for tests and diagnostics.
struct Cen2018RowTrace {
  std::vector<double> detrended;  // q(r)
  std::vector<double> smoothed;   // p(r), border mode scipy 'reflect' (the edge sample repeated)
  std::optional<double> noise_sigma;  // sigma_a; empty when no bin of q is negative
  std::vector<double> response;       // y(r); all zero when noise_sigma is empty
  std::vector<int> features;          // as cen2018_row_features
};
Cen2018RowTrace cen2018_row_trace(std::span<const float> row, const Cen2018Params& params);

}  // namespace radarpr
