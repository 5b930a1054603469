#pragma once

#include "datasets/byte_image.hpp"
#include "descriptors/features/cen2018.hpp"

namespace radarpr::cen2018_detail {

// The code that tests a uint8 row detrended by its mean (cen2018.cpp): the baseline (SSE2, with
// AVX2 window products and response test where the processor has them), or AVX-512
// (cen2018_avx512.hpp), which extract_cen2018_features takes wherever the processor has it. Both
// give the features of the definition; the tests run each.
enum class RowPath { baseline, avx512 };

// avx512 where the processor has it, baseline otherwise.
RowPath fastest_row_path();

// extract_cen2018_features through the given path; throws std::invalid_argument for avx512 on a
// processor without it.
PolarFeatures extract_features_with(const ByteImage& power, const Cen2018Params& params,
                                    RowPath path);

}  // namespace radarpr::cen2018_detail
