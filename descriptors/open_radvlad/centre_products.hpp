#pragma once

#include <vector>

#include <opencv2/core/mat.hpp>

namespace radarpr {

// Which code centre_products runs: the fastest this processor has (AVX2 with FMA), or the one
// every build has (Eigen's product; for the tests, which compare the two).
enum class ProductPath { fastest, baseline };

// Every row's dot product with every centre in float, row-major (rows x centres): entry (a, c)
// is rows[a] . centres[c] within (d / 2 + 2) u |x| |c| of the exact value for rows that are
// mirror-symmetric, (d + 2) u |x| |c| otherwise (u = 2^-24, d the width), whichever order the
// terms are summed in. Azimuth spectra are magnitudes of the DFT of a real row, so x[k] ==
// x[d - k] exactly; then x.c = x[0] c[0] + the sum over 0 < k <= d / 2 of x[k] (c[k] + c[d - k])
// (the middle term once when d is even): half the products. Expects continuous CV_32FC1
// matrices of the same width >= 1.
std::vector<float> centre_products(const cv::Mat& rows, const cv::Mat& centres,
                                   ProductPath path = ProductPath::fastest);

}  // namespace radarpr
