#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "datasets/byte_image.hpp"

namespace radarpr {

// A decoded PNG. Radar PNGs are 8-bit greyscale: those (and 1-, 2- and 4-bit greyscale, widened
// to 8 bits) come with their pixels; any other format only says what it is, for the error.
struct PngPixels {
  ByteImage image;    // empty unless the PNG is greyscale of at most 8 bits
  int bit_depth = 0;  // bits per sample as stored
  int channels = 0;   // 1 grey, 2 grey + alpha, 3 colour (or palette), 4 colour + alpha
};

// PNG decoding and encoding through libpng itself rather than OpenCV's imgcodecs, which would
// load about 120 shared libraries (GDAL, HDF5, codecs of every format) into every radarpr start.
//
// Throws std::runtime_error "<source>: could not decode the image (<why>)" when the bytes are not a
// complete, valid PNG.
//
// `checksums_verified`: the caller has checked every chunk's CRC (CheckedPngFile), so libpng does
// not compute them again, nor the image stream's Adler-32 inside the data the CRCs cover: on a
// MulRan scan the two made up about a quarter of the decode.
PngPixels decode_png(std::span<const std::uint8_t> bytes, const std::string& source,
                     bool checksums_verified = false);

// Takes a streamed decode's pixels a strip of rows at a time, so that no whole copy of the PNG's
// image need exist: a MulRan native scan is transposed strip by strip straight into its azimuth
// rows, where a whole decoded image and then its transposed copy touched 2.7 MB of fresh memory
// per scan (its page faults were a large part of a one-scan `radarpr extract`).
class PngRowSink {
 public:
  virtual ~PngRowSink() = default;
  // The image is `width` x `height` 8-bit greyscale (narrower greyscale widened). False stops the
  // decode (the sink keeps why).
  virtual bool start(int width, int height) = 0;
  // Rows [first, first + count) of the image, `width` bytes each, back to back; every row comes
  // once, in order. False stops the decode (the sink keeps why).
  virtual bool take_rows(int first, int count, const std::uint8_t* rows) = 0;
};

// Where a streamed decode gets the PNG's bytes: fills `out` with the next `count` bytes, or throws
// (std::runtime_error naming the file and the fault); the exception ends the decode unchanged.
using PngByteSource = std::function<void(std::uint8_t* out, std::size_t count)>;

// What a streamed decode found: the format as stored (see PngPixels), and whether its pixels
// went to the sink (greyscale of at most 8 bits) or were not decoded (any other format).
struct PngFormat {
  int bit_depth = 0;
  int channels = 0;
  bool decoded = false;
};

// decode_png from a stream of bytes into a sink. Throws std::runtime_error "<source>: could not
// decode the image (<why>)" when the bytes are not a valid PNG; what `read` throws passes through.
// A sink that stops the decode gets no more rows, and the format is returned as it is.
PngFormat decode_png_rows(const PngByteSource& read, PngRowSink& sink, const std::string& source,
                          bool checksums_verified = false);

// The same on a file. Throws std::runtime_error naming the file when it cannot be read.
PngPixels read_png(const std::filesystem::path& path);

// Encodes an image as an 8-bit greyscale PNG with the settings OpenCV's encoder uses by default
// (SUB filter, the fastest zlib level, RLE strategy), so the bytes are those cv::imencode(".png")
// wrote before. Throws std::invalid_argument for an empty image.
std::vector<std::uint8_t> encode_png(const ByteImage& image);

}  // namespace radarpr
