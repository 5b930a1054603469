#pragma once

#include <functional>
#include <string>
#include <vector>

#include "benchmarks/bench_case.hpp"
#include "datasets/polar_image.hpp"
#include "descriptors/descriptor.hpp"
#include "descriptors/descriptor_registry.hpp"

namespace radarpr::bench {

// One stage of a descriptor's extraction that can be timed on its own: run() does that stage's
// work once on the scan it was made for (earlier stages' outputs are computed up front).
struct TimedStage {
  Stage stage = Stage::descriptor;
  std::string what;  // what the stage covers, for the report
  std::function<void()> run;
};

// The stages `info` declares (DescriptorInfo::stages) for `descriptor`, an instance `info`
// created, on `scan`; none when it declares none (its extraction is then one stage). Throws
// std::invalid_argument naming the descriptor and where it was registered when a stage has an
// unknown name, no run function, or comes out of order.
std::vector<TimedStage> timed_stages(const DescriptorInfo& info, const Descriptor& descriptor,
                                     const PolarImage& scan);

}  // namespace radarpr::bench
