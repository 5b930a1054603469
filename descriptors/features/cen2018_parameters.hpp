#pragma once

#include <vector>

#include "descriptors/features/cen2018.hpp"
#include "descriptors/parameters.hpp"

namespace radarpr {

// The Cen 2018 parameters every descriptor built on those features exposes under the same names:
// detrend (row_mean|median), kernel (gaussian|box), sigma (17), sigma_convention
// (negative_rms|negative_rms_x2), z_q (6), min_range_bins (58). Defaults follow Cen2018Params.
std::vector<ParameterSpec> cen2018_parameter_specs();

// Reads those parameters from resolved values; throws ParameterError on an unknown choice.
Cen2018Params cen2018_params_from(const ParameterValues& values);

}  // namespace radarpr
