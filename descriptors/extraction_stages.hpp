#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "datasets/polar_image.hpp"

namespace radarpr {

class Descriptor;

// The names an extraction stage may have, in the order the stages run. A descriptor's
// extraction is "preparation" (what it does to the polar image before its own work), then
// "features" (Cen 2018 point features), then "descriptor" (the rest); a stage it does not
// declare is part of the next declared one, and an undeclared "descriptor" stage is the whole
// extraction minus the declared ones.
inline constexpr std::string_view kPreparationStage = "preparation";
inline constexpr std::string_view kFeaturesStage = "features";
inline constexpr std::string_view kDescriptorStage = "descriptor";

// One stage of a descriptor's extraction that can be timed on its own (`radarpr bench`): run()
// does that stage's work once on the scan the stages were made for; what earlier stages produce
// is computed when the stages are made, not in run().
struct ExtractionStage {
  std::string name;  // kPreparationStage, kFeaturesStage or kDescriptorStage
  std::string what;  // what the stage covers, e.g. the function it calls, for the report
  std::function<void()> run;
};

// Declared by a descriptor next to its registration (DescriptorInfo::stages): the stages of
// `descriptor` (an instance that DescriptorInfo::create made, trained if trainable) on `scan`.
// `scan` outlives the stages.
using ExtractionStagesFunction = std::function<std::vector<ExtractionStage>(
    const Descriptor& descriptor, const PolarImage& scan)>;

}  // namespace radarpr
