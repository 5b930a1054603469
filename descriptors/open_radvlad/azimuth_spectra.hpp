#pragma once

#include <opencv2/core/mat.hpp>

#include "datasets/polar_image.hpp"
#include "descriptors/open_radvlad/area_resampling.hpp"

namespace radarpr {

// Steps 1-2 of Open-RadVLAD (descriptors.md §6): one unit-norm range spectrum per azimuth.
// Resampling of each azimuth's range bins to bin_dim: area averaging (radarpr) or Pillow's
// default bicubic resize of the float image, as the public code does
// (descriptors/resampling/pillow_resize.hpp).
enum class AzimuthResize { area, pillow_bicubic };

struct AzimuthSpectraParams {
  AzimuthResize resize = AzimuthResize::area;
  int min_bin = 60;   // bins r < min_bin are zeroed (the near-range ring and the sensor housing)
  int max_bin = 0;    // the scan is cropped to min(max_bin, R) bins; 0 = all R bins
  int bin_dim = 512;  // range bins after resampling = values per azimuth spectrum
};

// Throws std::invalid_argument naming the parameter unless min_bin >= 0, max_bin >= 0 and
// bin_dim >= 1.
void validate(const AzimuthSpectraParams& params);

// The A x bin_dim CV_32FC1 spectra of a scan: zero bins r < min_bin, crop to max_bin, resample
// to bin_dim (params.resize), then per azimuth x_a = |DFT of the row| (all bin_dim values)
// divided by its L2 norm (a zero row stays zero). Throws std::invalid_argument unless the scan is
// a non-empty CV_8UC1 image.
cv::Mat azimuth_spectra(const PolarImage& scan, const AzimuthSpectraParams& params);

}  // namespace radarpr
