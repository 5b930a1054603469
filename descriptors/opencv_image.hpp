#pragma once

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>

#include <opencv2/core.hpp>

#include "datasets/byte_image.hpp"

namespace radarpr {

// The bridge between scans (ByteImage, radarpr's own, so that reading them loads no OpenCV) and
// the descriptors whose algorithms are OpenCV's (RaPlace, Open-RadVLAD, Radar Scan Context, the
// resampling kernels): a scan reaches them through a view, never a copy.

// A CV_8UC1 header over `image`'s pixels, sharing them: no copy, no ownership, valid while `image`
// lives and is not moved from. cv::Mat has no read-only flavour, so the view is writable in type
// only: OpenCV code must not write through it (that would change the caller's scan, which is
// const), nor hand it to a function that reallocates its argument. An empty image gives an empty
// header of the same size.
inline cv::Mat opencv_view(const ByteImage& image) {
  if (image.empty()) return cv::Mat(image.rows(), image.cols(), CV_8UC1);
  // const_cast only to fit cv::Mat's constructor: see above, nothing writes through it.
  return cv::Mat(image.rows(), image.cols(), CV_8UC1, const_cast<std::uint8_t*>(image.data()));
}

// A copy of an 8-bit single-channel cv::Mat (continuous or not) as a ByteImage. Throws
// std::invalid_argument saying what it got for any other type or a matrix that is not 2-D.
inline ByteImage to_byte_image(const cv::Mat& mat) {
  if (mat.type() != CV_8UC1 || mat.dims > 2) {
    throw std::invalid_argument(
        "to_byte_image: expected a 2-D 8-bit single-channel image (CV_8UC1), got a " +
        std::to_string(mat.dims) + "-D " + cv::typeToString(mat.type()));
  }
  ByteImage image = ByteImage::uninitialised(mat.rows, mat.cols);
  for (int r = 0; r < image.rows(); ++r) {
    const std::uint8_t* source = mat.ptr<std::uint8_t>(r);
    std::copy(source, source + image.cols(), image.row(r));
  }
  return image;
}

}  // namespace radarpr
