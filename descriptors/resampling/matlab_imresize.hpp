#pragma once

#include <opencv2/core/mat.hpp>

#include "descriptors/resampling/separable_resampling.hpp"

namespace radarpr {

// MATLAB-style imresize with its default method (bicubic, anti-aliasing on), written from the
// documented definition, for descriptor presets that reproduce code written for MATLAB:
//
// - kernel: the cubic convolution kernel with a = -0.5 (Keys), support [-2, 2];
// - output sample i (1-based) sits at input coordinate u = i / scale + (1 - 1 / scale) / 2;
// - when shrinking (scale < 1) the kernel is stretched by 1 / scale (anti-aliasing), so each
//   output reads ceil(4 / scale) + 2 candidate inputs from floor(u - 2 / scale) on;
// - the weights of every output are divided by their sum (renormalised), so a constant image
//   stays constant even at the borders;
// - indices outside the image are mirrored (symmetric padding, the edge sample repeated:
//   ..., 2, 1, 1, 2, ..., n, n, n-1, ...), and candidates whose weight is zero for every output
//   are dropped;
// - the axes are resized one after the other, the one with the smaller scale first; a CV_8U image
//   is rounded to the nearest integer (halves away from zero) and clipped to 0..255 after each
//   axis, as MATLAB keeps the input class between the passes.
//
// The taps of one axis: `output_length` outputs from `input_length` inputs at `scale` (MATLAB
// uses output / input when given a size, the given factor when given a scale). Throws
// std::invalid_argument unless both lengths are >= 1 and scale is finite and > 0.
ResamplingAxis matlab_imresize_axis(int input_length, int output_length, double scale);

// imresize(image, [rows cols]): the scale of each axis is output / input. `image` is a
// single-channel CV_8U, CV_32F or CV_64F matrix; the result has its type (CV_32F is computed in
// double and rounded to float once per axis). Throws std::invalid_argument for another type, an
// empty image, or a size < 1.
cv::Mat matlab_imresize(const cv::Mat& image, int rows, int cols);

// imresize(image, scale): the output is ceil(scale x rows) x ceil(scale x cols) and the kernel
// uses `scale` itself (not the rounded size ratio), as MATLAB does. Same types and throws; also
// throws unless scale is finite and > 0.
cv::Mat matlab_imresize_scale(const cv::Mat& image, double scale);

}  // namespace radarpr
