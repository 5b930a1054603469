#pragma once

#include <string>
#include <string_view>

#include <opencv2/core/mat.hpp>

namespace radarpr {

// Open-RadVLAD's learnt state as bytes (Descriptor::save_training): a text line naming the
// format, the codebook's row and column counts as two int32, then its float32 elements row-major,
// all in this machine's byte order (a plan's units run on one cluster).
std::string encode_codebook_state(const cv::Mat& codebook);

// The codebook `bytes` hold: clusters x bin_dim CV_32FC1 of finite elements. Throws
// std::invalid_argument naming what is wrong: another format, another shape than
// clusters x bin_dim, a length that does not match, a non-finite element.
cv::Mat decode_codebook_state(std::string_view bytes, int clusters, int bin_dim);

}  // namespace radarpr
