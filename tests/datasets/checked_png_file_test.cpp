// datasets/png_header's CheckedPngFile: a PNG read through a small buffer with every chunk checked
// before a byte of it is handed on, as read_polar_png feeds the decoder.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "datasets/png_codec.hpp"
#include "datasets/png_header.hpp"
#include "datasets/polar_png.hpp"
#include "tests/datasets/libpng_writer.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

fs::path temp_file(const std::string& name) {
  return fs::path(::testing::TempDir()) / ("radarpr_checked_png_" + name);
}

void write_file(const fs::path& path, const std::vector<std::uint8_t>& bytes) {
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()),
             static_cast<std::streamsize>(bytes.size()));
}

// Noise (nearly incompressible), range rows x azimuth columns, written by libpng with image data
// chunks of `chunk_bytes`: libpng's default is 8 KiB, larger than the reader's 128 KiB buffer
// takes the path that reads a chunk twice.
ByteImage noise(int rows, int cols) {
  ByteImage image(rows, cols);
  std::mt19937 random(5);
  for (std::size_t i = 0; i < image.size(); ++i)
    image.data()[i] = static_cast<std::uint8_t>(random());
  return image;
}

std::vector<std::uint8_t> png_with_chunks(const ByteImage& image, std::size_t chunk_bytes) {
  std::vector<const std::uint8_t*> rows;
  for (int r = 0; r < image.rows(); ++r) rows.push_back(image.row(r));
  return testing::libpng_encode(image.cols(), rows, {.idat_bytes = chunk_bytes});
}

// The file's bytes as the reader hands them on, in pieces of uneven sizes.
std::vector<std::uint8_t> read_all(CheckedPngFile& file, std::size_t count) {
  std::vector<std::uint8_t> out(count);
  std::size_t done = 0;
  for (std::size_t piece = 1; done < count; piece = piece * 7 % 20011 + 1) {
    const std::size_t part = std::min(piece, count - done);
    file.read(out.data() + done, part);
    done += part;
  }
  return out;
}

void expect_error(const std::function<void()>& action, const std::string& fragment) {
  try {
    action();
    ADD_FAILURE() << "no error, expected one containing '" << fragment << "'";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(fragment), std::string::npos) << error.what();
  }
}

TEST(CheckedPngFile, HandsOnTheFileAsItIsWhateverItsChunkSizes) {
  const ByteImage image = noise(700, 400);
  for (const std::size_t chunk_bytes : {std::size_t{8192}, std::size_t{300'000}}) {
    const std::vector<std::uint8_t> bytes = png_with_chunks(image, chunk_bytes);
    const std::size_t first_idat_length = (std::size_t{bytes[33]} << 24) |
                                          (std::size_t{bytes[34]} << 16) |
                                          (std::size_t{bytes[35]} << 8) | bytes[36];
    EXPECT_EQ(first_idat_length > (std::size_t{128} << 10), chunk_bytes > (std::size_t{128} << 10));
    const fs::path path = temp_file("noise.png");
    write_file(path, bytes);
    CheckedPngFile file(path);
    EXPECT_EQ(file.header().width, 400);
    EXPECT_EQ(file.header().height, 700);
    EXPECT_EQ(file.size(), bytes.size());
    EXPECT_EQ(read_all(file, bytes.size()), bytes) << "chunks of " << chunk_bytes;
    // Nothing is read after the IEND chunk.
    std::uint8_t more = 0;
    expect_error([&] { file.read(&more, 1); }, "after its IEND chunk");

    // The decode it feeds: the scan transposed to azimuth rows, pixel for pixel.
    PolarPngOptions options;
    options.range_resolution_m = 0.05;
    EXPECT_TRUE(read_polar_png(path, options).image.power == transposed(image));
    fs::remove(path);
  }
}

TEST(CheckedPngFile, ADamagedChunkIsRefusedBeforeAnyOfItsBytes) {
  for (const std::size_t chunk_bytes : {std::size_t{8192}, std::size_t{300'000}}) {
    std::vector<std::uint8_t> bytes = png_with_chunks(noise(700, 400), chunk_bytes);
    const std::size_t idat = 8 + 25;  // right after IHDR
    ASSERT_EQ(std::string(bytes.begin() + idat + 4, bytes.begin() + idat + 8), "IDAT");
    bytes[idat + 8 + 5000] ^= 0x10;
    const fs::path path = temp_file("damaged.png");
    write_file(path, bytes);
    CheckedPngFile file(path);
    std::vector<std::uint8_t> before(idat);
    file.read(before.data(), before.size());
    std::uint8_t first = 0;
    expect_error([&] { file.read(&first, 1); }, "its 'IDAT' chunk at byte 33 fails its CRC check");
    PolarPngOptions options;
    options.range_resolution_m = 0.05;
    expect_error([&] { read_polar_png(path, options); },
                 path.string() + ": corrupt PNG, its 'IDAT'");
    fs::remove(path);
  }
}

TEST(CheckedPngFile, ACutFileAndTrailingBytes) {
  const std::vector<std::uint8_t> bytes = png_with_chunks(noise(70, 40), 1000);
  const fs::path path = temp_file("cut.png");
  // Cut inside a chunk: its length runs past the end. Cut at a chunk's end: no IEND.
  write_file(path, {bytes.begin(), bytes.begin() + 1500});
  {
    CheckedPngFile file(path);
    expect_error([&] { read_all(file, bytes.size()); }, "but the file ends");
  }
  write_file(path, {bytes.begin(), bytes.end() - 12});
  {
    CheckedPngFile file(path);
    expect_error([&] { read_all(file, bytes.size()); }, "has no IEND chunk");
  }
  // Bytes after IEND are never read, so they do no harm (as in a whole-file check).
  std::vector<std::uint8_t> trailing = bytes;
  trailing.insert(trailing.end(), {1, 2, 3});
  write_file(path, trailing);
  {
    CheckedPngFile file(path);
    EXPECT_EQ(read_all(file, bytes.size()), bytes);
  }
  write_file(path, {bytes.begin(), bytes.begin() + 20});
  expect_error([&] { CheckedPngFile file(path); }, "too short for a PNG");
  expect_error([&] { CheckedPngFile file(temp_file("absent.png")); }, "absent.png: cannot be read");
  fs::remove(path);
}

}  // namespace
}  // namespace radarpr
