#pragma once

#include <functional>
#include <span>
#include <string_view>
#include <vector>

#include "datasets/polar_image.hpp"
#include "descriptors/descriptor.hpp"
#include "descriptors/extraction_stages.hpp"
#include "descriptors/features/cen2018.hpp"
#include "descriptors/features/polar_features.hpp"
#include "descriptors/parameters.hpp"

namespace radarpr {

// Code shared by the ReFeree family (descriptors.md §2, §3).

// Lengths of `parts` contiguous blocks covering `count` items as evenly as possible: the first
// count % parts blocks are one item longer. Throws std::invalid_argument unless
// 1 <= parts <= count.
std::vector<int> split_evenly(int count, int parts, std::string_view what);

// Throws std::invalid_argument naming `descriptor` unless `scan.power` is non-empty.
void check_polar_scan(const PolarImage& scan, std::string_view descriptor);

// K_i = sum over the azimuths a of block i of per_azimuth(bins of a) / (|block i| * R), with
// the A azimuths split into `alpha` blocks by split_evenly. Result: alpha x 1.
DescriptorValue azimuth_block_profile(
    const PolarFeatures& features, int alpha,
    const std::function<double(std::span<const int>)>& per_azimuth, std::string_view descriptor);

// Throws std::invalid_argument naming `descriptor` unless both values have the same shape.
void check_same_shape(const DescriptorValue& a, const DescriptorValue& b,
                      std::string_view descriptor);
double l2_distance(const DescriptorValue& a, const DescriptorValue& b, std::string_view descriptor);

// The `alpha` parameter (number of azimuth blocks, default 50) of referee and referee_a.
ParameterSpec alpha_parameter_spec();
// `own` followed by the shared Cen 2018 parameters (cen2018_parameter_specs()).
std::vector<ParameterSpec> with_cen2018_parameters(std::vector<ParameterSpec> own);

// The two stages of every ReFeree extraction: Cen 2018 features of `scan`, then
// `from_features` (described by `what`) on features computed once up front.
std::vector<ExtractionStage> cen2018_then_descriptor_stages(
    const Cen2018Params& cen, const PolarImage& scan,
    std::function<DescriptorValue(const PolarFeatures&)> from_features, std::string what);

}  // namespace radarpr
