#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>

namespace radarpr {

// An 8-bit greyscale image, rows x cols, stored row after row with no padding (row r starts at
// data() + r * cols()). It is radarpr's own so that reading a scan and the descriptors that need
// no image library (Cen 2018 and the ReFeree family) do not load one: a program linked to OpenCV
// pays for loading it on every start (docs/cli.md).
//
// A value type: copies are deep (unlike cv::Mat's shared ones), moves are cheap. The pixels are
// 64-byte aligned, like OpenCV's, so that vector loads of a row's start never split a cache line
// (except a borrowed image's, which are where their owner put them).
class ByteImage {
 public:
  ByteImage() = default;
  // rows x cols pixels, all `fill`. Throws std::invalid_argument for a negative size.
  ByteImage(int rows, int cols, std::uint8_t fill = 0);
  // rows x cols pixels left undefined, for a producer that writes every one of them (a decoder).
  static ByteImage uninitialised(int rows, int cols);
  // The rows x cols pixels at `pixels` (row after row, no padding) without a copy, for a buffer
  // radarpr does not own (a numpy array handed to a descriptor): the caller keeps it alive and
  // unchanged while this image (or what it is moved into) lives, and only reads it through the
  // image. Copies of a borrowed image are deep and own their pixels. Throws
  // std::invalid_argument for a negative size.
  static ByteImage borrow(const std::uint8_t* pixels, int rows, int cols);
  // False for a borrowed image.
  bool owns_pixels() const { return pixels_.get_deleter().owned; }

  ByteImage(const ByteImage& other);
  ByteImage& operator=(const ByteImage& other);
  ByteImage(ByteImage&& other) noexcept;
  ByteImage& operator=(ByteImage&& other) noexcept;
  ~ByteImage() = default;

  int rows() const { return rows_; }
  int cols() const { return cols_; }
  bool empty() const { return rows_ == 0 || cols_ == 0; }
  std::size_t size() const {
    return static_cast<std::size_t>(rows_) * static_cast<std::size_t>(cols_);
  }

  std::uint8_t* data() { return pixels_.get(); }
  const std::uint8_t* data() const { return pixels_.get(); }
  std::uint8_t* row(int r) {
    return data() + static_cast<std::size_t>(r) * static_cast<std::size_t>(cols_);
  }
  const std::uint8_t* row(int r) const {
    return data() + static_cast<std::size_t>(r) * static_cast<std::size_t>(cols_);
  }
  std::uint8_t& operator()(int r, int c) { return row(r)[c]; }
  std::uint8_t operator()(int r, int c) const { return row(r)[c]; }

  // The rows [first, first + count) as an image of their own (a copy).
  ByteImage row_range(int first, int count) const;
  // The columns [first, first + count) of every row as an image of their own (a copy).
  ByteImage column_range(int first, int count) const;

  // Same size and the same pixels.
  friend bool operator==(const ByteImage& a, const ByteImage& b);

 private:
  struct AlignedDelete {
    // Constructors rather than a member initialiser: the enclosing class is incomplete where
    // unique_ptr asks whether this is default-constructible.
    AlignedDelete() noexcept : owned(true) {}
    explicit AlignedDelete(bool owns) noexcept : owned(owns) {}
    bool owned;
    void operator()(std::uint8_t* pixels) const {
      if (owned) ::operator delete[](pixels, std::align_val_t{kAlignment});
    }
  };
  static constexpr std::size_t kAlignment = 64;
  static std::unique_ptr<std::uint8_t[], AlignedDelete> allocate(std::size_t count);

  int rows_ = 0;
  int cols_ = 0;
  std::unique_ptr<std::uint8_t[], AlignedDelete> pixels_;
};

// The image with rows and columns swapped: out(c, r) == image(r, c).
ByteImage transposed(const ByteImage& image);

// Writes the `rows` x `cols` pixels at `pixels` (row after row, no padding) transposed into `out`
// from its column `first_col` on: out(c, first_col + r) = pixels[r * cols + c]. For an image
// arriving a strip of rows at a time (a streamed PNG decode), transposed without a whole copy.
// Throws std::invalid_argument unless `out` has `cols` rows and first_col + rows columns at least.
void transpose_into(const std::uint8_t* pixels, int rows, int cols, ByteImage& out, int first_col);

}  // namespace radarpr
