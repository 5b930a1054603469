#include "datasets/byte_image.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

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

ByteImage ByteImage::borrow(const std::uint8_t* pixels, int rows, int cols) {
  check_size(rows, cols);
  ByteImage image;
  image.rows_ = rows;
  image.cols_ = cols;
  // The pointer is stored non-const only because the owning case needs it so; a borrowed image
  // is read through const access alone (see the header).
  image.pixels_ = std::unique_ptr<std::uint8_t[], AlignedDelete>(const_cast<std::uint8_t*>(pixels),
                                                                 AlignedDelete(false));
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

namespace {

#if defined(__SSE2__)
// Transposes the 16 x 16 block at `in` (rows `in_stride` bytes apart) into `out` (rows
// `out_stride` apart) with SSE2 (every x86-64 has it): four rounds of interleaving pairs of
// registers, bytes, then 2-, 4- and 8-byte groups, turn 16 rows into 16 columns. The scalar loop
// took 2.3x as long as cv::transpose on a MulRan native scan (3360 x 400), which every decode of
// one transposes.
void transpose_block16(const std::uint8_t* in, std::size_t in_stride, std::uint8_t* out,
                       std::size_t out_stride) {
  __m128i a[16];
  for (std::size_t i = 0; i < 16; ++i) {
    a[i] = _mm_loadu_si128(reinterpret_cast<const __m128i*>(in + i * in_stride));
  }
  __m128i b[16];
  for (int i = 0; i < 8; ++i) {
    b[2 * i] = _mm_unpacklo_epi8(a[2 * i], a[2 * i + 1]);
    b[2 * i + 1] = _mm_unpackhi_epi8(a[2 * i], a[2 * i + 1]);
  }
  // c[4 g + k]: columns 4k .. 4k + 3 of rows 4g .. 4g + 3, a column's 4 bytes together.
  __m128i c[16];
  for (int g = 0; g < 4; ++g) {
    const __m128i* pair = b + 4 * g;
    c[4 * g + 0] = _mm_unpacklo_epi16(pair[0], pair[2]);
    c[4 * g + 1] = _mm_unpackhi_epi16(pair[0], pair[2]);
    c[4 * g + 2] = _mm_unpacklo_epi16(pair[1], pair[3]);
    c[4 * g + 3] = _mm_unpackhi_epi16(pair[1], pair[3]);
  }
  // d[8 h + k]: columns 2k, 2k + 1 of rows 8h .. 8h + 7.
  __m128i d[16];
  for (int h = 0; h < 2; ++h) {
    for (int k = 0; k < 4; ++k) {
      d[8 * h + 2 * k] = _mm_unpacklo_epi32(c[8 * h + k], c[8 * h + 4 + k]);
      d[8 * h + 2 * k + 1] = _mm_unpackhi_epi32(c[8 * h + k], c[8 * h + 4 + k]);
    }
  }
  for (std::size_t k = 0; k < 8; ++k) {
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out + 2 * k * out_stride),
                     _mm_unpacklo_epi64(d[k], d[k + 8]));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out + (2 * k + 1) * out_stride),
                     _mm_unpackhi_epi64(d[k], d[k + 8]));
  }
}
#endif

}  // namespace

ByteImage transposed(const ByteImage& image) {
  ByteImage out = ByteImage::uninitialised(image.cols(), image.rows());
  transpose_into(image.data(), image.rows(), image.cols(), out, 0);
  return out;
}

void transpose_into(const std::uint8_t* pixels, int rows, int cols, ByteImage& out, int first_col) {
  if (rows < 0 || cols < 0 || out.rows() != cols || first_col < 0 ||
      first_col > out.cols() - rows) {
    throw std::invalid_argument(
        "cannot transpose " + std::to_string(rows) + " x " + std::to_string(cols) +
        " pixels into columns " + std::to_string(first_col) + " on of a " +
        std::to_string(out.rows()) + " x " + std::to_string(out.cols()) + " image");
  }
  const auto in_stride = static_cast<std::size_t>(cols);
  const auto out_stride = static_cast<std::size_t>(out.cols());
  auto in_at = [&](int r, int c) {
    return pixels + static_cast<std::size_t>(r) * in_stride + static_cast<std::size_t>(c);
  };
  int whole_rows = 0;
  int whole_cols = 0;
#if defined(__SSE2__)
  whole_rows = rows - rows % 16;
  whole_cols = cols - cols % 16;
  for (int r = 0; r < whole_rows; r += 16) {
    for (int c = 0; c < whole_cols; c += 16) {
      transpose_block16(in_at(r, c), in_stride, out.row(c) + first_col + r, out_stride);
    }
  }
#endif
  // What the blocks leave: the last columns of every row, then the last rows (all of it without
  // SSE2), in row strips so that the rows read stay in cache.
  for (int r = 0; r < rows; ++r) {
    const int first = r < whole_rows ? whole_cols : 0;
    for (int c = first; c < cols; ++c) out(c, first_col + r) = *in_at(r, c);
  }
}

bool operator==(const ByteImage& a, const ByteImage& b) {
  if (a.rows_ != b.rows_ || a.cols_ != b.cols_) return false;
  return a.empty() || std::equal(a.data(), a.data() + a.size(), b.data());
}

}  // namespace radarpr
