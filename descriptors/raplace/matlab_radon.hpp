#pragma once

#include <opencv2/core/mat.hpp>

namespace radarpr::raplace {

// The Radon transform as MATLAB's radon(I, 0:179) defines it, for the RaPlace preset that
// reproduces the public MATLAB code (generateRadon.m), written from that definition:
//
// - the centre is pixel (floor((M - 1) / 2), floor((N - 1) / 2)) (0-based row, column) of the
//   M x N image - for an even size half a pixel off the geometric centre;
// - every pixel is split into 2 x 2 sub-pixels at offsets +-1/4 pixel, each carrying a quarter of
//   its value; a sub-pixel at (x, y) from the centre (x right, y up) projects onto
//   rho = x cos(theta) + y sin(theta) and is shared linearly between the two integer rho bins
//   around it;
// - the rho bins are the integers -L .. L, L = ceil(|(M, N) - floor(((M, N) - 1) / 2) - 1|) + 1
//   (399 rows for 280 x 280): result row k is rho = k - L;
// - column t is theta = t degrees, t = 0 .. 179.
//
// Returns (2 L + 1) x 180 CV_64FC1. Throws std::invalid_argument unless `image` is a non-empty
// single-channel CV_8U, CV_32F or CV_64F matrix.
cv::Mat matlab_radon(const cv::Mat& image);

// 2 L + 1 for an image of `rows` x `cols` (399 for 280 x 280).
int matlab_radon_rho_bins(int rows, int cols);

}  // namespace radarpr::raplace
