// datasets/png_codec: libpng in place of OpenCV's imgcodecs. The reference for every expectation
// is OpenCV itself (cv::imencode / cv::imread(IMREAD_UNCHANGED)), which radarpr used before:
// decoded pixels and encoded bytes must not change.
#include "datasets/png_codec.hpp"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "descriptors/opencv_image.hpp"
#include "tests/datasets/libpng_writer.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

// A radar-like image: mostly dark, bright streaks, and an Oxford-layout metadata block.
cv::Mat radar_like(int rows, int cols, unsigned seed) {
  cv::Mat image(rows, cols, CV_8UC1);
  cv::RNG rng(seed);
  rng.fill(image, cv::RNG::NORMAL, 12, 8);
  for (int r = 0; r < rows; r += 7) image.row(r).colRange(cols / 3, cols / 2).setTo(200);
  return image;
}

std::vector<std::uint8_t> opencv_png(const cv::Mat& image) {
  std::vector<std::uint8_t> bytes;
  EXPECT_TRUE(cv::imencode(".png", image, bytes));
  return bytes;
}

bool same_pixels(const ByteImage& ours, const cv::Mat& reference) {
  const cv::Mat a = opencv_view(ours);
  return a.size() == reference.size() && a.type() == reference.type() &&
         cv::norm(a, reference, cv::NORM_INF) == 0;
}

fs::path temp_file(const std::string& name) {
  return fs::path(::testing::TempDir()) / ("radarpr_png_codec_" + name);
}

TEST(PngCodec, EncodesTheBytesOpenCvWrote) {
  for (const cv::Mat& image :
       {radar_like(400, 3371, 1), radar_like(120, 431, 2), cv::Mat(3, 5, CV_8UC1, cv::Scalar(0))}) {
    EXPECT_EQ(encode_png(to_byte_image(image)), opencv_png(image))
        << image.rows << " x " << image.cols;
  }
  // A view into a wider image (rows not contiguous) becomes an image of the view only.
  const cv::Mat wide = radar_like(50, 300, 3);
  const cv::Mat view = wide.colRange(20, 120);
  EXPECT_EQ(encode_png(to_byte_image(view)), opencv_png(view.clone()));
}

TEST(PngCodec, DecodesWhatItEncodesAndWhatOpenCvWrote) {
  const cv::Mat image = radar_like(400, 1691, 4);
  const PngPixels ours = decode_png(encode_png(to_byte_image(image)), "ours");
  EXPECT_TRUE(same_pixels(ours.image, image));
  EXPECT_EQ(ours.bit_depth, 8);
  EXPECT_EQ(ours.channels, 1);

  // Written by OpenCV with other settings (highest compression): the same pixels.
  std::vector<std::uint8_t> bytes;
  ASSERT_TRUE(cv::imencode(".png", image, bytes, {cv::IMWRITE_PNG_COMPRESSION, 9}));
  EXPECT_TRUE(same_pixels(decode_png(bytes, "opencv").image, image));
}

TEST(PngCodec, ReadsAFileLikeImread) {
  const fs::path path = temp_file("file.png");
  const cv::Mat image = radar_like(64, 75, 5);
  ASSERT_TRUE(cv::imwrite(path.string(), image));
  EXPECT_TRUE(same_pixels(read_png(path).image, cv::imread(path.string(), cv::IMREAD_UNCHANGED)));
  fs::remove(path);
}

TEST(PngCodec, RealRadarPngsDecodeAsImreadDoes) {
  const fs::path root = fs::path(RADARPR_SOURCE_DIR) / ".." / "shared" / "data" / "real";
  if (!fs::is_directory(root)) GTEST_SKIP() << root << " absent: no real PNG to compare";
  int compared = 0;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (entry.path().extension() != ".png" || compared >= 6) continue;
    const cv::Mat reference = cv::imread(entry.path().string(), cv::IMREAD_UNCHANGED);
    const PngPixels ours = read_png(entry.path());
    if (reference.type() == CV_8UC1) {
      EXPECT_TRUE(same_pixels(ours.image, reference)) << entry.path();
      ++compared;
    }
  }
  EXPECT_GT(compared, 0) << "no 8-bit greyscale PNG under " << root;
}

TEST(PngCodec, OtherFormatsSayWhatTheyAreWithoutPixels) {
  std::vector<std::uint8_t> bytes;
  ASSERT_TRUE(cv::imencode(".png", cv::Mat(4, 6, CV_16UC1, cv::Scalar(1000)), bytes));
  PngPixels pixels = decode_png(bytes, "sixteen");
  EXPECT_TRUE(pixels.image.empty());
  EXPECT_EQ(pixels.bit_depth, 16);
  EXPECT_EQ(pixels.channels, 1);

  ASSERT_TRUE(cv::imencode(".png", cv::Mat(4, 6, CV_8UC3, cv::Scalar(1, 2, 3)), bytes));
  pixels = decode_png(bytes, "colour");
  EXPECT_TRUE(pixels.image.empty());
  EXPECT_EQ(pixels.channels, 3);

  ASSERT_TRUE(cv::imencode(".png", cv::Mat(4, 6, CV_8UC4, cv::Scalar(1, 2, 3, 4)), bytes));
  EXPECT_EQ(decode_png(bytes, "alpha").channels, 4);
}

TEST(PngCodec, BilevelGreyIsWidenedAsImreadDoes) {
  // OpenCV writes a 1-bit greyscale PNG when asked for a bilevel image.
  cv::Mat image(8, 16, CV_8UC1, cv::Scalar(0));
  image.colRange(0, 8).setTo(255);
  std::vector<std::uint8_t> bytes;
  ASSERT_TRUE(cv::imencode(".png", image, bytes, {cv::IMWRITE_PNG_BILEVEL, 1}));
  const PngPixels pixels = decode_png(bytes, "bilevel");
  EXPECT_EQ(pixels.bit_depth, 1);
  EXPECT_TRUE(same_pixels(pixels.image, cv::imdecode(bytes, cv::IMREAD_UNCHANGED)));
}

void expect_runtime_error(const std::function<void()>& action, const std::string& text) {
  try {
    action();
    ADD_FAILURE() << "no error, expected one containing '" << text << "'";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(text), std::string::npos) << error.what();
  }
}

// Records the strips a streamed decode hands over.
class StripRecorder final : public PngRowSink {
 public:
  ByteImage image;
  std::vector<int> firsts;
  int stop_after = -1;  // strips taken before the decode is stopped; -1: never
  bool start(int width, int height) override {
    image = ByteImage(height, width);
    return stop_after != 0;
  }
  bool take_rows(int first, int count, const std::uint8_t* rows) override {
    firsts.push_back(first);
    std::copy(rows, rows + static_cast<std::size_t>(count) * image.cols(), image.row(first));
    return stop_after < 0 || static_cast<int>(firsts.size()) < stop_after;
  }
};

PngByteSource memory_source(const std::vector<std::uint8_t>& bytes, std::size_t& offset) {
  return [&bytes, &offset](std::uint8_t* out, std::size_t count) {
    if (count > bytes.size() - offset) throw std::runtime_error("past the end");
    std::copy(bytes.begin() + static_cast<std::ptrdiff_t>(offset),
              bytes.begin() + static_cast<std::ptrdiff_t>(offset + count), out);
    offset += count;
  };
}

TEST(PngCodec, StreamedDecodeHandsOverStripsOfRowsInOrder) {
  const cv::Mat image = radar_like(3360 / 10, 400 / 10, 7);
  const std::vector<std::uint8_t> bytes = opencv_png(image);
  std::size_t offset = 0;
  StripRecorder sink;
  const PngFormat format = decode_png_rows(memory_source(bytes, offset), sink, "strips");
  EXPECT_TRUE(format.decoded);
  EXPECT_EQ(format.bit_depth, 8);
  EXPECT_TRUE(same_pixels(sink.image, image));
  ASSERT_EQ(sink.firsts.size(), 21u);  // 336 rows in strips of 16
  EXPECT_EQ(sink.firsts.back(), 320);
  EXPECT_EQ(offset, bytes.size()) << "read to the end (IEND)";

  // A sink that stops the decode gets no more rows, and no error comes of it.
  offset = 0;
  StripRecorder stopping;
  stopping.stop_after = 2;
  EXPECT_TRUE(decode_png_rows(memory_source(bytes, offset), stopping, "stop").decoded);
  EXPECT_EQ(stopping.firsts.size(), 2u);

  // What the source throws ends the decode unchanged.
  const std::vector<std::uint8_t> half(bytes.begin(), bytes.begin() + bytes.size() / 2);
  offset = 0;
  StripRecorder cut;
  expect_runtime_error([&] { decode_png_rows(memory_source(half, offset), cut, "half"); },
                       "past the end");
}

// Adam7, written with libpng itself (OpenCV's encoder never interlaces): every pass revisits the
// rows, so the decode hands the image over whole, with the same pixels as imdecode.
std::vector<std::uint8_t> interlaced_png(const cv::Mat& image) {
  std::vector<const std::uint8_t*> rows;
  for (int r = 0; r < image.rows; ++r) rows.push_back(image.ptr(r));
  return testing::libpng_encode(image.cols, rows, {.adam7 = true});
}

TEST(PngCodec, AnInterlacedImageIsDecodedWhole) {
  const cv::Mat image = radar_like(45, 37, 8);
  const std::vector<std::uint8_t> bytes = interlaced_png(image);
  ASSERT_EQ(bytes[8 + 8 + 12], 1) << "the IHDR says Adam7";
  std::size_t offset = 0;
  StripRecorder sink;
  EXPECT_TRUE(decode_png_rows(memory_source(bytes, offset), sink, "adam7").decoded);
  EXPECT_EQ(sink.firsts, std::vector<int>{0});
  EXPECT_TRUE(same_pixels(sink.image, image));
  EXPECT_TRUE(
      same_pixels(decode_png(bytes, "adam7").image, cv::imdecode(bytes, cv::IMREAD_UNCHANGED)));
}

TEST(PngCodec, BrokenInputIsAnErrorNamingTheSource) {
  const std::vector<std::uint8_t> good = encode_png(to_byte_image(radar_like(40, 60, 6)));
  const std::vector<std::uint8_t> truncated(good.begin(), good.begin() + good.size() / 2);
  expect_runtime_error([&] { decode_png(truncated, "half.png"); },
                       "half.png: could not decode the image (corrupt PNG");

  std::vector<std::uint8_t> flipped = good;
  flipped[flipped.size() / 2] ^= 0xFF;  // inside the image data: a CRC or inflate error
  expect_runtime_error([&] { decode_png(flipped, "flipped.png"); },
                       "flipped.png: could not decode the image (corrupt PNG");

  const std::string text = "not an image";
  expect_runtime_error(
      [&] {
        decode_png({reinterpret_cast<const std::uint8_t*>(text.data()), text.size()}, "t");
      },
      "t: could not decode the image (not a PNG");
  expect_runtime_error([&] { read_png(temp_file("missing.png")); }, "missing.png: cannot be read");
  EXPECT_THROW(encode_png(ByteImage()), std::invalid_argument);
  EXPECT_THROW(encode_png(ByteImage(0, 5)), std::invalid_argument);
}

}  // namespace
}  // namespace radarpr
