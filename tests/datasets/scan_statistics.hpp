// Statistics of polar radar scans that the descriptors depend on, to compare synthetic scans
// with real ones (the credibility test and the README's table).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "datasets/polar_image.hpp"
#include "descriptors/features/cen2018.hpp"

namespace radarpr::test {

// Range bands of the mean range profile, metres.
inline constexpr std::array<double, 5> kProfileBandEdgesM = {5.0, 20.0, 50.0, 100.0, 150.0};

struct ScanStatistics {
  // Intensity histogram, summarised: quantiles of every pixel within 150 m.
  double median = 0.0;
  double p90 = 0.0;
  double p99 = 0.0;
  double bright_fraction = 0.0;  // pixels >= 80 (strong returns)
  // Mean range profile: mean intensity in [5, 20), [20, 50), [50, 100), [100, 150) m.
  std::array<double, kProfileBandEdgesM.size() - 1> profile{};
  // Cen 2018 features per azimuth (box kernel, z_q = 3, the public code's setting under which
  // descriptors.md quotes about 9 per azimuth on real scans).
  double features_per_azimuth = 0.0;
  // Median over azimuths of the farthest feature's range (metres; azimuths without any: 0).
  double farthest_feature_m = 0.0;
};

inline Cen2018Params credibility_cen_params() {
  Cen2018Params params;
  params.kernel = CenKernel::box;
  params.z_q = 3.0;
  return params;
}

// Cen 2018 features per azimuth (the credibility setting) within `max_range_m` of the sensor:
// the scan cropped there, so that scans of different reach compare.
inline double features_per_azimuth_within(const PolarImage& scan, double max_range_m) {
  PolarImage cropped = scan;
  const int bins =
      std::min(scan.range_bin_count(), static_cast<int>(max_range_m / scan.range_resolution_m));
  cropped.power = scan.power.column_range(0, bins);
  const PolarFeatures features = extract_cen2018_features(cropped, credibility_cen_params());
  return static_cast<double>(features.feature_count()) / features.azimuth_count();
}

inline double quantile_of(const std::array<double, 256>& histogram, double total, double q) {
  double seen = 0.0;
  for (std::size_t v = 0; v < histogram.size(); ++v) {
    seen += histogram[v];
    if (seen >= q * total) return static_cast<double>(v);
  }
  return 255.0;
}

inline ScanStatistics scan_statistics(const PolarImage& scan) {
  ScanStatistics stats;
  const double resolution = scan.range_resolution_m;
  const int bins =
      std::min(scan.range_bin_count(), static_cast<int>(kProfileBandEdgesM.back() / resolution));
  std::array<double, 256> histogram{};
  std::array<double, kProfileBandEdgesM.size() - 1> band_sum{};
  std::array<double, kProfileBandEdgesM.size() - 1> band_count{};
  for (int a = 0; a < scan.azimuth_count(); ++a) {
    const auto* row = scan.power.row(a);
    for (int r = 0; r < bins; ++r) {
      histogram[row[r]] += 1.0;
      const double range = (r + 0.5) * resolution;
      for (std::size_t b = 0; b + 1 < kProfileBandEdgesM.size(); ++b) {
        if (range >= kProfileBandEdgesM[b] && range < kProfileBandEdgesM[b + 1]) {
          band_sum[b] += row[r];
          band_count[b] += 1.0;
        }
      }
    }
  }
  const double total = static_cast<double>(scan.azimuth_count()) * bins;
  stats.median = quantile_of(histogram, total, 0.5);
  stats.p90 = quantile_of(histogram, total, 0.9);
  stats.p99 = quantile_of(histogram, total, 0.99);
  double bright = 0.0;
  for (std::size_t v = 80; v < histogram.size(); ++v) bright += histogram[v];
  stats.bright_fraction = bright / total;
  for (std::size_t b = 0; b < band_sum.size(); ++b) {
    stats.profile[b] = band_count[b] > 0.0 ? band_sum[b] / band_count[b] : 0.0;
  }

  const PolarFeatures features = extract_cen2018_features(scan, credibility_cen_params());
  std::vector<double> farthest;
  for (int a = 0; a < features.azimuth_count(); ++a) {
    const auto bins_of_a = features.azimuth(a);
    farthest.push_back(bins_of_a.empty() ? 0.0 : (bins_of_a.back() + 0.5) * resolution);
  }
  stats.features_per_azimuth =
      static_cast<double>(features.feature_count()) / features.azimuth_count();
  std::nth_element(farthest.begin(), farthest.begin() + static_cast<long>(farthest.size() / 2),
                   farthest.end());
  stats.farthest_feature_m = farthest[farthest.size() / 2];
  return stats;
}

}  // namespace radarpr::test
