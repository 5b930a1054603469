#pragma once

#include <opencv2/core/mat.hpp>

namespace radarpr {

// Resamples every row of a CV_32FC1 matrix to `width` columns by area averaging: output bin j is
// the mean of the row, read as a step function, over input columns [j W / width, (j+1) W / width).
// Shrinking, this is OpenCV's INTER_AREA; enlarging, it blends neighbouring bins (a box filter)
// instead of OpenCV's bilinear. Rows never mix, so a circular shift of the rows shifts the result.
// Each bin is a double sum over its input columns in increasing order, rounded to float.
cv::Mat area_resample_rows(const cv::Mat& rows, int width);

// Which code area_resample_bytes runs: the fastest this processor has, or the one every build
// has (x86-64's baseline instructions; for the tests, which compare the two).
enum class ResamplingPath { fastest, baseline };

// area_resample_rows of a CV_8UC1 matrix whose columns below `zeroed` read as 0, without a float
// copy: bit for bit the same values (the same double products and sums, in the same order).
// Throws std::invalid_argument unless `bytes` is a non-empty CV_8UC1 matrix, width >= 1 and
// 0 <= zeroed.
cv::Mat area_resample_bytes(const cv::Mat& bytes, int zeroed, int width,
                            ResamplingPath path = ResamplingPath::fastest);

}  // namespace radarpr
