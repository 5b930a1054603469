#pragma once

#include <cstddef>
#include <cstdint>

#include <opencv2/core/mat.hpp>

#include "descriptors/descriptor.hpp"
#include "descriptors/open_radvlad/azimuth_spectra.hpp"

namespace radarpr {

// The rows Open-RadVLAD's k-means learns its codebook from: azimuth spectra of training scans.
struct TrainingRows {
  cv::Mat rows;                // N x bin_dim CV_32FC1
  std::size_t scans_used = 0;  // scans loaded (all of them, or the sample the cap needed)
};

// max_rows == 0: every row of every scan, in scan order (the spec's "all azimuth rows").
// Otherwise the scans are visited in a seeded random order and taken whole until max_rows rows
// are gathered, the last one giving a seeded random subset of its rows: a uniform sample of scans
// (so of places along the route) that loads only the scans the cap needs. When all the scans hold
// at most max_rows rows, every row is taken (in the visiting order).
// Scans are loaded one at a time (TrainingScans::load). Throws std::invalid_argument naming
// scans.description() when there is no scan or a scan is not a non-empty CV_8UC1 image.
TrainingRows collect_training_rows(const TrainingScans& scans, const AzimuthSpectraParams& params,
                                   std::size_t max_rows, std::uint64_t seed);

}  // namespace radarpr
