#pragma once

#include <opencv2/core/mat.hpp>

namespace radarpr::raplace {

// radon_transform (radon_transform.hpp) of a square image, the same sums computed in another
// order so that each projection costs work per rho bin instead of per pixel.
//
// Segments. Walk one image column upwards (y grows by 1 per pixel): at angle theta its pixels
// project onto rho positions that grow by sin(theta) per pixel. For |sin(theta)| < 1 the pixels
// whose position falls into rho bin b form one run (a segment), and the linear split of every
// pixel of the run between bins b and b + 1 needs only two sums over the run, sum v and
// sum m v (m the pixel's index along the column): bin b receives sum v (1 - w) and bin b + 1
// sum v w, where w = position - b is linear in m. With prefix sums of v and m v down the column
// (that of m v accumulated in two doubles: its differences, nearly cancelled by m_first x sum v,
// must stay exact to about one rounding of the run's own sum; a difference of sums of v is as
// accurate as the pixel-by-pixel sums already) each run costs a few operations, and a column
// crosses only about n |sin(theta)| bins instead of n pixels.
//
// Other lines. A walk along any line of the pixel lattice moves rho by the same amount per
// pixel, dj cos(theta) - di sin(theta) for a step of (di, dj) in (row, column), and the lines of
// one direction cover every pixel once. Each angle walks the direction whose step is smallest and
// not negative: columns up to 18.4 degrees, lines of two rows down and one column right (or back)
// from 18.4 to 33.7 degrees (their step is zero at atan(1/2) = 26.6), diagonals beyond: about
// 0.15 bin updates per pixel and angle on average over 0..45 degrees, against one split per pixel
// and angle for the definition. Which pixels of a line are occupied (any lane non-zero) is looked
// up in a mask computed once.
//
// Symmetry. The walks cover theta <= 45 degrees. The other angles come from the same walks over
// turned and mirrored copies of the image: projecting image(T p) at theta is projecting the
// image at the angle of T n(theta) for an orthogonal T that maps the pixel grid onto itself, so
// the transpose gives 90 - theta, the quarter turn 90 + theta and the mirror 180 - theta. The
// four copies share every position, segment and bin, and are summed side by side.
//
// The result equals radon_transform_by_pixels's up to rounding (the same terms summed in another
// order, and cos and sin of the base angle standing for those of the turned angles): 2.0e-14 of
// the largest value on a real MulRan image (tests/descriptors/raplace_test.cpp), and the RaPlace
// descriptors (float) and distances of the synthetic paper table come out bit for bit the same.
// Expects a non-empty square CV_64FC1 image and rho_bins = radon_rho_bins(n, n); returns
// rho_bins x 180 CV_64FC1.
cv::Mat square_radon_by_segments(const cv::Mat& image, int rho_bins);

}  // namespace radarpr::raplace
