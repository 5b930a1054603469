#pragma once

#include <cstdint>
#include <filesystem>
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
// `checksums_verified`: the caller has checked every chunk's CRC (check_png_bytes), so libpng does
// not compute them again, nor the image stream's Adler-32 inside the data the CRCs cover: on a
// MulRan scan the two made up about a quarter of the decode.
PngPixels decode_png(std::span<const std::uint8_t> bytes, const std::string& source,
                     bool checksums_verified = false);

// The same on a file. Throws std::runtime_error naming the file when it cannot be read.
PngPixels read_png(const std::filesystem::path& path);

// Encodes an image as an 8-bit greyscale PNG with the settings OpenCV's encoder uses by default
// (SUB filter, the fastest zlib level, RLE strategy), so the bytes are those cv::imencode(".png")
// wrote before. Throws std::invalid_argument for an empty image.
std::vector<std::uint8_t> encode_png(const ByteImage& image);

}  // namespace radarpr
