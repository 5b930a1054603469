#include "descriptors/open_radvlad/codebook_file.hpp"

#include <bit>
#include <cmath>
#include <cstddef>
#include <span>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "datasets/npy_file.hpp"
#include "datasets/sha256.hpp"

namespace radarpr {
namespace {

// The values as a contiguous row-major float span (a copy when the matrix is a strided view).
std::vector<float> values_of(const cv::Mat& codebook) {
  if (codebook.empty() || codebook.type() != CV_32FC1) {
    throw std::invalid_argument("a codebook must be a non-empty CV_32FC1 matrix");
  }
  const cv::Mat contiguous = codebook.isContinuous() ? codebook : codebook.clone();
  const auto* first = contiguous.ptr<float>(0);
  return {first, first + contiguous.total()};
}

}  // namespace

cv::Mat read_codebook(const std::filesystem::path& path, int clusters, int bin_dim) {
  const std::string expected = fmt::format(
      "a {} x {} float32 array (clusters x bin_dim), as save_codebook writes", clusters, bin_dim);
  std::vector<float> values;
  try {
    const NpyFile file = NpyFile::open(path);
    const std::vector<std::size_t> want = {static_cast<std::size_t>(clusters),
                                           static_cast<std::size_t>(bin_dim)};
    if (file.shape() != want) {
      std::string shape;
      for (const std::size_t extent : file.shape())
        shape += (shape.empty() ? "" : " x ") + std::to_string(extent);
      throw std::invalid_argument(fmt::format("{}: the codebook has shape ({}); expected {}",
                                              path.string(), shape, expected));
    }
    if (file.dtype() != NpyDtype::float32 && file.dtype() != NpyDtype::float64) {
      throw std::invalid_argument(fmt::format("{}: the codebook holds {}; expected {}",
                                              path.string(), to_string(file.dtype()), expected));
    }
    values = file.as_floats();
  } catch (const NpyError& error) {
    throw std::invalid_argument(
        fmt::format("open_radvlad codebook: {} (expected {})", error.what(), expected));
  }
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) {
      throw std::invalid_argument(
          fmt::format("{}: codebook value {} (row {}, column {}) is not "
                      "finite",
                      path.string(), i, i / bin_dim, i % bin_dim));
    }
  }
  return cv::Mat(clusters, bin_dim, CV_32FC1, values.data()).clone();
}

void write_codebook(const std::filesystem::path& path, const cv::Mat& codebook) {
  const std::vector<float> values = values_of(codebook);
  try {
    write_npy(path,
              {static_cast<std::size_t>(codebook.rows), static_cast<std::size_t>(codebook.cols)},
              std::span<const float>(values));
  } catch (const NpyError& error) {
    throw std::invalid_argument(
        fmt::format("open_radvlad: cannot save the codebook: {}", error.what()));
  }
}

std::string codebook_sha256(const cv::Mat& codebook) {
  static_assert(std::endian::native == std::endian::little,
                "the codebook hash is defined over little-endian float32 bytes");
  const std::vector<float> values = values_of(codebook);
  return sha256_hex(std::as_bytes(std::span<const float>(values)));
}

}  // namespace radarpr
