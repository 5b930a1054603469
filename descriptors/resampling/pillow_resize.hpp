#pragma once

#include <opencv2/core/mat.hpp>

#include "descriptors/resampling/separable_resampling.hpp"

namespace radarpr {

// Pillow-style Image.resize with its default bicubic filter on a 32-bit float ("F") image,
// written from Pillow's documented definition, for descriptor presets that reproduce Python code
// using Pillow:
//
// - kernel: cubic convolution with a = -0.5, support 2;
// - output sample x (0-based) is centred at input coordinate (x + 0.5) x scale, scale = input /
//   output; when shrinking the support is stretched by the scale (anti-aliasing) and the kernel
//   argument divided by it;
// - inputs from trunc(centre - support + 0.5) to trunc(centre + support + 0.5), clipped to the
//   image (no padding: the border samples are simply missing), weighted by
//   kernel((input + 0.5 - centre) / max(scale, 1)) and divided by the sum of those weights;
// - the horizontal pass runs first, then the vertical one; an axis whose size does not change is
//   left as it is. Sums are in double, each pass's result rounded to float.
//
// The taps of one axis. Throws std::invalid_argument unless both lengths are >= 1.
ResamplingAxis pillow_bicubic_axis(int input_length, int output_length);

// image.resize((cols, rows)) of a CV_32FC1 image, CV_32FC1 result. Throws std::invalid_argument
// for another type, an empty image, or a size < 1.
cv::Mat pillow_resize(const cv::Mat& image, int rows, int cols);

}  // namespace radarpr
