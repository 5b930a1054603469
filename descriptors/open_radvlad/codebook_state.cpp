#include "descriptors/open_radvlad/codebook_state.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace radarpr {
namespace {

constexpr std::string_view kFormatLine = "radarpr open_radvlad codebook 1\n";

}  // namespace

std::string encode_codebook_state(const cv::Mat& codebook) {
  const cv::Mat rows = codebook.isContinuous() ? codebook : codebook.clone();
  const std::int32_t shape[2] = {rows.rows, rows.cols};
  std::string bytes(kFormatLine);
  bytes.append(reinterpret_cast<const char*>(shape), sizeof shape);
  bytes.append(reinterpret_cast<const char*>(rows.ptr<float>()), rows.total() * sizeof(float));
  return bytes;
}

cv::Mat decode_codebook_state(std::string_view bytes, int clusters, int bin_dim) {
  if (bytes.substr(0, kFormatLine.size()) != kFormatLine) {
    throw std::invalid_argument("open_radvlad: not a saved codebook (no '" +
                                std::string(kFormatLine.substr(0, kFormatLine.size() - 1)) +
                                "' line)");
  }
  bytes.remove_prefix(kFormatLine.size());
  std::int32_t shape[2] = {0, 0};
  if (bytes.size() < sizeof shape) {
    throw std::invalid_argument("open_radvlad: the saved codebook ends before its shape");
  }
  std::memcpy(shape, bytes.data(), sizeof shape);
  bytes.remove_prefix(sizeof shape);
  if (shape[0] != clusters || shape[1] != bin_dim) {
    throw std::invalid_argument("open_radvlad: the saved codebook is " + std::to_string(shape[0]) +
                                " x " + std::to_string(shape[1]) + ", this descriptor's is " +
                                std::to_string(clusters) + " x " + std::to_string(bin_dim) +
                                " (clusters x bin_dim)");
  }
  const std::size_t elements =
      static_cast<std::size_t>(clusters) * static_cast<std::size_t>(bin_dim);
  if (bytes.size() != elements * sizeof(float)) {
    throw std::invalid_argument("open_radvlad: the saved codebook holds " +
                                std::to_string(bytes.size()) + " bytes of elements, " +
                                std::to_string(elements * sizeof(float)) + " expected");
  }
  cv::Mat codebook(clusters, bin_dim, CV_32FC1);
  std::memcpy(codebook.ptr<float>(), bytes.data(), bytes.size());
  for (std::size_t i = 0; i < elements; ++i) {
    if (!std::isfinite(codebook.ptr<float>()[i])) {
      throw std::invalid_argument("open_radvlad: the saved codebook has a non-finite element");
    }
  }
  return codebook;
}

}  // namespace radarpr
