#include "benchmarks/descriptor_stages.hpp"

#include <memory>

#include <benchmark/benchmark.h>
#include <opencv2/core/mat.hpp>

#include "descriptors/features/cen2018.hpp"
#include "descriptors/open_radvlad/azimuth_spectra.hpp"
#include "descriptors/open_radvlad/open_radvlad.hpp"
#include "descriptors/raplace/polar_to_cartesian.hpp"
#include "descriptors/raplace/raplace.hpp"
#include "descriptors/referee/referee.hpp"
#include "descriptors/referee/referee_a.hpp"
#include "descriptors/referee/referee_r.hpp"

namespace radarpr::bench {
namespace {

// Features, then `from_features` on features computed once up front.
template <typename FromFeatures>
std::vector<TimedStage> feature_stages(const Cen2018Params& cen, const PolarImage& scan,
                                       FromFeatures from_features, const char* what) {
  auto features = std::make_shared<const PolarFeatures>(extract_cen2018_features(scan, cen));
  return {
      {Stage::features, "Cen 2018 point features (extract_cen2018_features)",
       [cen, &scan] {
         PolarFeatures computed = extract_cen2018_features(scan, cen);
         benchmark::DoNotOptimize(computed);
       }},
      {Stage::descriptor, what,
       [features, from_features] {
         DescriptorValue value = from_features(*features);
         benchmark::DoNotOptimize(value.values.data());
       }},
  };
}

}  // namespace

std::vector<TimedStage> timed_stages(const Descriptor& descriptor, const PolarImage& scan) {
  if (const auto* referee = dynamic_cast<const RefereeDescriptor*>(&descriptor)) {
    const int alpha = referee->params().alpha;
    return feature_stages(
        referee->params().cen, scan,
        [alpha](const PolarFeatures& features) { return referee_from_features(features, alpha); },
        "the block profile (referee_from_features)");
  }
  if (const auto* referee_a = dynamic_cast<const RefereeADescriptor*>(&descriptor)) {
    const int alpha = referee_a->params().alpha;
    return feature_stages(
        referee_a->params().cen, scan,
        [alpha](const PolarFeatures& features) { return referee_a_from_features(features, alpha); },
        "the block profile (referee_a_from_features)");
  }
  if (const auto* referee_r = dynamic_cast<const RefereeRDescriptor*>(&descriptor)) {
    const RefereeRParams params = referee_r->params();
    return feature_stages(
        params.cen, scan,
        [params](const PolarFeatures& features) {
          return referee_r_from_features(features, params);
        },
        "the range-chunk counts (referee_r_from_features)");
  }
  if (const auto* raplace = dynamic_cast<const RaplaceDescriptor*>(&descriptor)) {
    const RaplaceParams params = raplace->params();
    // As RaplaceDescriptor::extract: 0 means the scan's whole range.
    const double range_m = params.cart_range_m > 0.0
                               ? params.cart_range_m
                               : scan.range_bin_count() * scan.range_resolution_m;
    return {{Stage::preparation, "the Cartesian image (raplace::polar_to_cartesian)",
             [params, range_m, &scan] {
               cv::Mat cartesian = raplace::polar_to_cartesian(scan, params.cart_size, range_m);
               benchmark::DoNotOptimize(cartesian.data);
             }}};
  }
  if (const auto* vlad = dynamic_cast<const OpenRadVladDescriptor*>(&descriptor)) {
    const AzimuthSpectraParams params = vlad->params().spectra;
    return {
        {Stage::preparation, "the per-azimuth range spectra (azimuth_spectra)", [params, &scan] {
           cv::Mat spectra = azimuth_spectra(scan, params);
           benchmark::DoNotOptimize(spectra.data);
         }}};
  }
  return {};
}

}  // namespace radarpr::bench
