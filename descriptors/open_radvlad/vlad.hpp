#pragma once

#include <vector>

#include <opencv2/core/mat.hpp>

namespace radarpr {

// Step 4 of Open-RadVLAD (descriptors.md §6). `rows` (N x d) and `centres` (k x d) are CV_32FC1
// with the same d; both functions throw std::invalid_argument otherwise.

// Index of the nearest centre (squared L2; ties -> the lower index) of every row. Each row is
// compared on its own with the same arithmetic, so a row's centre does not depend on where it
// sits: a circular shift of the azimuths only permutes the assignments.
std::vector<int> nearest_centres(const cv::Mat& rows, const cv::Mat& centres);

// V_k = sum of (x - c_k) over the rows x assigned to c_k (accumulated in double), flattened
// cluster-major (V_0 first, k * d values), then v <- sign(v) sqrt(|v|) and v <- v / ||v||; an
// all-zero V stays zero. Orderless: the rows' order changes only the rounding of the sums.
std::vector<float> vlad_vector(const cv::Mat& rows, const cv::Mat& centres);

}  // namespace radarpr
