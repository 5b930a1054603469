#include "datasets/byte_image.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

namespace radarpr {
namespace {

ByteImage counting_image(int rows, int cols) {
  ByteImage image(rows, cols);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) image(r, c) = static_cast<std::uint8_t>(r * 16 + c);
  }
  return image;
}

TEST(ByteImage, StoresRowsOneAfterAnotherWithoutPadding) {
  const ByteImage image = counting_image(3, 5);
  EXPECT_EQ(image.rows(), 3);
  EXPECT_EQ(image.cols(), 5);
  EXPECT_EQ(image.size(), 15u);
  EXPECT_EQ(image.row(2), image.data() + 10);
  EXPECT_EQ(image.data()[7], 16 + 2);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(image.data()) % 64, 0u);
}

TEST(ByteImage, FillsEveryPixel) {
  const ByteImage image(4, 6, 9);
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 6; ++c) EXPECT_EQ(image(r, c), 9);
  }
}

TEST(ByteImage, CopiesAreDeepAndMovesLeaveAnEmptyImage) {
  ByteImage original = counting_image(2, 3);
  ByteImage copy = original;
  copy(0, 0) = 200;
  EXPECT_EQ(original(0, 0), 0);
  EXPECT_FALSE(copy == original);
  copy = original;
  EXPECT_TRUE(copy == original);

  ByteImage moved = std::move(original);
  EXPECT_TRUE(moved == copy);
  EXPECT_TRUE(original.empty());  // NOLINT(bugprone-use-after-move): the state is specified
  EXPECT_EQ(original.rows(), 0);
}

TEST(ByteImage, CutsRowAndColumnRanges) {
  const ByteImage image = counting_image(4, 5);
  const ByteImage rows = image.row_range(1, 2);
  ASSERT_EQ(rows.rows(), 2);
  ASSERT_EQ(rows.cols(), 5);
  EXPECT_EQ(rows(0, 3), image(1, 3));
  EXPECT_EQ(rows(1, 4), image(2, 4));

  const ByteImage columns = image.column_range(2, 3);
  ASSERT_EQ(columns.rows(), 4);
  ASSERT_EQ(columns.cols(), 3);
  EXPECT_EQ(columns(3, 0), image(3, 2));
  EXPECT_EQ(columns(1, 2), image(1, 4));

  EXPECT_TRUE(image.row_range(4, 0).empty());
  EXPECT_THROW(image.row_range(3, 2), std::out_of_range);
  EXPECT_THROW(image.column_range(-1, 2), std::out_of_range);
  EXPECT_THROW(image.column_range(1, 5), std::out_of_range);
}

TEST(ByteImage, RejectsANegativeSizeAndComparesSizes) {
  EXPECT_THROW(ByteImage(-1, 3), std::invalid_argument);
  EXPECT_TRUE(ByteImage() == ByteImage(0, 0));
  EXPECT_FALSE(ByteImage() == ByteImage(0, 7));
  EXPECT_FALSE(ByteImage(2, 3) == ByteImage(3, 2));
  EXPECT_TRUE(ByteImage().empty());
}

TEST(ByteImage, ABorrowedImageReadsTheBufferAndItsCopiesOwnTheirs) {
  std::vector<std::uint8_t> buffer{1, 2, 3, 4, 5, 6};
  {
    const ByteImage borrowed = ByteImage::borrow(buffer.data(), 2, 3);
    EXPECT_FALSE(borrowed.owns_pixels());
    EXPECT_EQ(borrowed.data(), buffer.data());  // no copy
    EXPECT_EQ(borrowed(1, 2), 6);
    ByteImage copy = borrowed;
    EXPECT_TRUE(copy.owns_pixels());
    EXPECT_NE(copy.data(), buffer.data());
    EXPECT_TRUE(copy == borrowed);
    copy(0, 0) = 9;
    EXPECT_EQ(buffer[0], 1);  // the copy is deep
    ByteImage moved = ByteImage::borrow(buffer.data(), 3, 2);
    moved = std::move(copy);  // lets go of the borrowed buffer without freeing it
    EXPECT_TRUE(moved.owns_pixels());
  }
  // The borrowed images are gone and the buffer is intact (a free of it would fail under ASan).
  EXPECT_EQ(buffer, (std::vector<std::uint8_t>{1, 2, 3, 4, 5, 6}));
  EXPECT_THROW(ByteImage::borrow(buffer.data(), -1, 2), std::invalid_argument);
}

// Sizes around the 16-pixel blocks the transpose works in, and a MulRan native scan's.
TEST(ByteImage, TransposedSwapsRowsAndColumns) {
  for (const auto& [rows, cols] : {std::pair{1, 1}, std::pair{3, 70}, std::pair{33, 31},
                                   std::pair{64, 65}, std::pair{3360, 400}}) {
    ByteImage image(rows, cols);
    for (int r = 0; r < rows; ++r) {
      for (int c = 0; c < cols; ++c) image(r, c) = static_cast<std::uint8_t>(r * 7 + c * 13);
    }
    const ByteImage flipped = transposed(image);
    ASSERT_EQ(flipped.rows(), cols);
    ASSERT_EQ(flipped.cols(), rows);
    bool same = true;
    for (int r = 0; r < rows; ++r) {
      for (int c = 0; c < cols; ++c) same = same && flipped(c, r) == image(r, c);
    }
    EXPECT_TRUE(same) << rows << " x " << cols;
    EXPECT_TRUE(transposed(flipped) == image) << rows << " x " << cols;
  }
  EXPECT_TRUE(transposed(ByteImage()).empty());
}

// A streamed decode hands a native scan over in strips of rows: transposed strip by strip into
// place, the image is the one transposed whole.
TEST(ByteImage, TransposeIntoPlacesStripsOfRows) {
  ByteImage image(101, 37);
  for (int r = 0; r < image.rows(); ++r) {
    for (int c = 0; c < image.cols(); ++c) image(r, c) = static_cast<std::uint8_t>(r * 5 + c * 11);
  }
  for (const int strip : {1, 16, 40, 101}) {
    ByteImage out = ByteImage::uninitialised(image.cols(), image.rows());
    for (int first = 0; first < image.rows(); first += strip) {
      transpose_into(image.row(first), std::min(strip, image.rows() - first), image.cols(), out,
                     first);
    }
    EXPECT_TRUE(out == transposed(image)) << "strips of " << strip;
  }
  ByteImage out(37, 100);
  EXPECT_THROW(transpose_into(image.data(), 101, 37, out, 0), std::invalid_argument);
  EXPECT_THROW(transpose_into(image.data(), 10, 37, out, 91), std::invalid_argument);
  EXPECT_THROW(transpose_into(image.data(), 10, 36, out, 0), std::invalid_argument);
}

}  // namespace
}  // namespace radarpr
