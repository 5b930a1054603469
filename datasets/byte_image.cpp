#include "datasets/byte_image.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>

namespace radarpr {

namespace {

void check_size(int rows, int cols) {
  if (rows < 0 || cols < 0) {
    throw std::invalid_argument("an image needs a size of at least 0 x 0, not " +
                                std::to_string(rows) + " x " + std::to_string(cols));
  }
}

}  // namespace

std::unique_ptr<std::uint8_t[], ByteImage::AlignedDelete> ByteImage::allocate(std::size_t count) {
  if (count == 0) return {};
  return std::unique_ptr<std::uint8_t[], AlignedDelete>(
      static_cast<std::uint8_t*>(::operator new[](count, std::align_val_t{kAlignment})));
}

ByteImage::ByteImage(int rows, int cols, std::uint8_t fill) : ByteImage(uninitialised(rows, cols)) {
  if (!empty()) std::memset(data(), fill, size());
}

ByteImage ByteImage::uninitialised(int rows, int cols) {
  check_size(rows, cols);
  ByteImage image;
  image.rows_ = rows;
  image.cols_ = cols;
  image.pixels_ = allocate(image.size());
  return image;
}

ByteImage::ByteImage(const ByteImage& other) : ByteImage(uninitialised(other.rows_, other.cols_)) {
  if (!empty()) std::memcpy(data(), other.data(), size());
}

ByteImage& ByteImage::operator=(const ByteImage& other) {
  if (this != &other) *this = ByteImage(other);
  return *this;
}

ByteImage::ByteImage(ByteImage&& other) noexcept
    : rows_(std::exchange(other.rows_, 0)),
      cols_(std::exchange(other.cols_, 0)),
      pixels_(std::move(other.pixels_)) {}

ByteImage& ByteImage::operator=(ByteImage&& other) noexcept {
  rows_ = std::exchange(other.rows_, 0);
  cols_ = std::exchange(other.cols_, 0);
  pixels_ = std::move(other.pixels_);
  return *this;
}

ByteImage ByteImage::row_range(int first, int count) const {
  if (first < 0 || count < 0 || first > rows_ - count) {
    throw std::out_of_range("rows " + std::to_string(first) + " to " +
                            std::to_string(first + count) + " of an image with " +
                            std::to_string(rows_) + " rows");
  }
  ByteImage part = uninitialised(count, cols_);
  if (!part.empty()) std::memcpy(part.data(), row(first), part.size());
  return part;
}

ByteImage ByteImage::column_range(int first, int count) const {
  if (first < 0 || count < 0 || first > cols_ - count) {
    throw std::out_of_range("columns " + std::to_string(first) + " to " +
                            std::to_string(first + count) + " of an image with " +
                            std::to_string(cols_) + " columns");
  }
  ByteImage part = uninitialised(rows_, count);
  if (part.empty()) return part;
  for (int r = 0; r < rows_; ++r)
    std::memcpy(part.row(r), row(r) + first, static_cast<std::size_t>(count));
  return part;
}

bool operator==(const ByteImage& a, const ByteImage& b) {
  if (a.rows_ != b.rows_ || a.cols_ != b.cols_) return false;
  return a.empty() || std::equal(a.data(), a.data() + a.size(), b.data());
}

}  // namespace radarpr
