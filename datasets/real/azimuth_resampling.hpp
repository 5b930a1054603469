#pragma once

#include "datasets/byte_image.hpp"

namespace radarpr {

// Resamples an azimuth-major image (row = azimuth) to `azimuths` rows, for sources that drop rows
// and whose encoder bytes cannot be trusted (OORD): the n rows present are taken as evenly spread
// over one revolution (row i at angle 2 pi i / n). Output row a samples input position a n / A,
// linearly between the two neighbouring rows, the last row wrapping to the first, rounded to the
// nearest integer (ties to even), the same bytes cv::addWeighted gave before. Returns a copy when
// n == A. Throws std::invalid_argument for an empty image or azimuths < 1.
ByteImage resample_azimuth_rows(const ByteImage& power, int azimuths);

}  // namespace radarpr
