#pragma once

#include <functional>
#include <string>
#include <vector>

#include "benchmarks/bench_case.hpp"
#include "datasets/polar_image.hpp"
#include "descriptors/descriptor.hpp"

namespace radarpr::bench {

// One stage of a descriptor's extraction that can be timed on its own: run() does that stage's
// work once on the scan it was made for (earlier stages' outputs are computed up front).
struct TimedStage {
  Stage stage = Stage::descriptor;
  std::string what;  // what the stage covers, for the report
  std::function<void()> run;
};

// The stages of `descriptor` that its public functions expose, for `scan`:
// - ReFeree family (referee, referee_a, referee_r): Cen 2018 features, then *_from_features;
// - raplace: preparation = the Cartesian image (polar_to_cartesian);
// - open_radvlad (trained): preparation = the per-azimuth spectra (azimuth_spectra);
// - anything else (radar_scan_context, plugins): none - its extraction is one stage, reported as
//   "descriptor".
// A descriptor stage that is not listed is the whole extraction minus the listed stages.
std::vector<TimedStage> timed_stages(const Descriptor& descriptor, const PolarImage& scan);

}  // namespace radarpr::bench
