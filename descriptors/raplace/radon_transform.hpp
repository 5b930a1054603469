#pragma once

#include <opencv2/core/mat.hpp>

namespace radarpr::raplace {

// Number of projection angles of RaPlace's sinogram: theta = 0, 1, ..., 179 degrees.
inline constexpr int kRadonAngles = 180;

// ceil(sqrt(width^2 + height^2)), the image diagonal in pixels, computed exactly in integers
// (396 for 280 x 280). Every pixel centre projects inside a sinogram of this many rho bins.
int radon_rho_bins(int width, int height);

// RaPlace step 2 (descriptors.md §5): the Radon transform S(rho, theta) = sum of the image along
// the line x cos(theta) + y sin(theta) = rho, for theta = 0..179 degrees.
//
// Geometry (the frame of polar_to_cartesian): pixel (row i, column j) sits at
// x = j - (width - 1) / 2, y = (height - 1) / 2 - i (pixels; x right, y up); theta is measured
// counter-clockwise from +x. Result row k is rho = k - (n_rho - 1) / 2 with
// n_rho = radon_rho_bins(width, height), so rho = 0 (the image centre) is the middle of the rows;
// column t is theta = t degrees. Result: n_rho x 180, CV_64FC1.
//
// Discretisation (pixel-driven): each pixel is a point mass at its centre, split between the two
// rho bins around its projection in proportion to proximity (linear interpolation), so every
// column sums to the image's total and a single pixel traces a sampled sinusoid.
// Throws std::invalid_argument unless `image` is a non-empty single-channel CV_32F or CV_64F
// matrix.
// A square image (RaPlace's) is summed run by run (segment_radon.hpp: about 10x faster, equal up
// to rounding); any other shape by radon_transform_by_pixels.
cv::Mat radon_transform(const cv::Mat& image);

// The same transform summed pixel by pixel, each pixel split between its two bins in turn: the
// definition as written above, for images of any shape and as the tests' reference.
cv::Mat radon_transform_by_pixels(const cv::Mat& image);

}  // namespace radarpr::raplace
