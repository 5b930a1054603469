#pragma once

#include <vector>

#include <opencv2/core/mat.hpp>

namespace radarpr {

// One output sample of a separable 1-D resampling: the input indices it reads (0-based, inside
// [0, input length)) and their weights, summed in this order.
struct ResamplingTaps {
  std::vector<int> indices;
  std::vector<double> weights;
};

// The taps of every output sample of one axis.
using ResamplingAxis = std::vector<ResamplingTaps>;

// Resamples the rows (axis = along each row, i.e. the columns change) or the columns (the rows
// change) of a single-channel CV_64F matrix with `taps`, summing in double. Returns CV_64F.
// Throws std::invalid_argument for another type or a tap index outside the matrix.
cv::Mat resample_along_rows(const cv::Mat& image, const ResamplingAxis& taps);
cv::Mat resample_along_columns(const cv::Mat& image, const ResamplingAxis& taps);

}  // namespace radarpr
