#pragma once

#include <opencv2/core/mat.hpp>

namespace radarpr {

// Resamples an azimuth-major CV_8UC1 image (row = azimuth) to `azimuths` rows, for sources that
// drop rows and whose encoder bytes cannot be trusted (OORD): the n rows present are taken as
// evenly spread over one revolution (row i at angle 2 pi i / n). Output row a samples input
// position a n / A, linearly between the two neighbouring rows, the last row wrapping to the
// first, rounded to the nearest integer (OpenCV rounding). Returns a copy when n == A. Throws
// std::invalid_argument for an empty image, a wrong type, or azimuths < 1.
cv::Mat resample_azimuth_rows(const cv::Mat& power, int azimuths);

}  // namespace radarpr
