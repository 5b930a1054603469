#pragma once

#include <vector>

#include <opencv2/core/mat.hpp>

namespace radarpr::raplace {

// RaPlace steps 3 and 4 (descriptors.md §5): from the sinogram to the descriptor matrix D.
// All matrices are CV_64FC1 with rows = rho (or rho frequency), columns = theta.

// S / max(S). An all-zero (or all non-positive) sinogram is returned unchanged: no division by
// zero, no NaN.
cv::Mat normalize_by_max(const cv::Mat& sinogram);

// The sinogram shrunk to rows x cols by cv::INTER_AREA: every output cell is the area-weighted
// mean of the input cells it covers - the anti-aliased shrink (what MATLAB's imresize achieves
// with its anti-aliasing kernel) and exact block means when the factor is an integer, so theta
// column c of a 180 -> 18 shrink is the mean of theta = 10c .. 10c + 9 degrees (OpenCV keeps
// the weights in float: relative error ~1e-8, the same for every column). Throws
// std::invalid_argument unless 1 <= rows <= sinogram rows and 1 <= cols <= sinogram cols.
cv::Mat shrink_sinogram(const cv::Mat& sinogram, int rows, int cols);

// |DFT along rho| of every theta column, keeping the first floor(rows / 2) frequencies 0 ..
// floor(rows / 2) - 1 (MATLAB's 1:fix(end/2); 40 rows -> 20). |DFT| forgets where along rho the
// structure lies (translation-robust) and maps a column and its rho-mirror to the same values,
// which is what makes the theta axis circular (S(rho, theta + 180) = S(-rho, theta)). Throws
// std::invalid_argument for fewer than 2 rows.
cv::Mat rho_spectrum_magnitude(const cv::Mat& sinogram);

// (D - mean) / std over all elements, std with the n - 1 denominator (MATLAB's std, as the public
// code uses; the normalized distance does not depend on this choice, raw_over_1000 does).
// Row-major float32 values. A constant D (std <= 1e-12 x max |D|, e.g. all zero) or a single
// element gives all zeros, never NaN.
std::vector<float> z_score(const cv::Mat& matrix);

}  // namespace radarpr::raplace
