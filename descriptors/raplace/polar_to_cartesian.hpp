#pragma once

#include <opencv2/core/mat.hpp>

#include "datasets/polar_image.hpp"

namespace radarpr::raplace {

// RaPlace step 1 (descriptors.md §5): the polar scan resampled onto a square Cartesian grid by
// backward warping - every Cartesian pixel looks up its range and bearing in the scan.
//
// Frame and handedness. The image is cart_size x cart_size pixels of 2 * cart_range_m /
// cart_size metres; the sensor sits at the image centre (a pixel corner for even sizes, so that
// rotations by 90 degrees map the grid onto itself). Pixel (row i, column j) has its centre at
//   x = (j + 0.5 - cart_size / 2) * pixel,   y = (cart_size / 2 - i - 0.5) * pixel,
// x pointing right (increasing column), y pointing up (decreasing row). Its bearing
// atan2(y, x) is the azimuth it samples: azimuth 0 points right, azimuth pi/2 points up, i.e.
// azimuth grows COUNTER-CLOCKWISE in the image as displayed (row 0 at the top). For a sensor that
// spins counter-clockwise (MulRan) this is the top view; for a clockwise one (Oxford, Boreas) the
// image is that top view mirrored - the same for every scan of a sensor, so retrieval within one
// dataset is unaffected.
//
// Range. Bin r covers [r, r + 1) * resolution and is sampled at its centre (r + 0.5) *
// resolution (the Oxford SDK's convention); a pixel at range rho reads the fractional bin
// rho / resolution - 0.5, clamped at 0 near the sensor; bins r >= R read as 0, so the image fades
// to 0 between the centre of bin R-1 and that of the virtual bin R.
//
// Bearing. Row a lies at scan.azimuths_rad[a] (uniform 2 pi a / A when the list is empty); a pixel
// between the azimuths of rows a and a+1 is interpolated linearly in angle, and the gap after the
// last row wraps to row 0 (one turn later). Azimuths must increase (modulo 2 pi) through less
// than one turn.
//
// Both interpolations together are bilinear in (azimuth, range). Returns CV_32FC1 in the scan's
// units (0..255). Throws std::invalid_argument for an empty or non-CV_8UC1 scan, a range
// resolution <= 0, cart_size < 1, cart_range_m <= 0, or azimuths that are not finite, not A
// many, or span a full turn or more.
cv::Mat polar_to_cartesian(const PolarImage& scan, int cart_size, double cart_range_m);

}  // namespace radarpr::raplace
