#include "datasets/png_codec.hpp"

#include <algorithm>
#include <array>
#include <csetjmp>
#include <cstring>
#include <exception>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include <fmt/format.h>
#include <png.h>
#include <zlib.h>

namespace radarpr {
namespace {

// libpng reports errors through a callback that must not return: it stores the text and
// longjmps back to the setjmp of the call in progress. Everything that call touches afterwards
// lives in these state objects, created before setjmp (a longjmp skips the destructors of
// objects created after it).
struct ReadState {
  const PngByteSource* read = nullptr;
  PngRowSink* sink = nullptr;
  std::exception_ptr read_failure;  // what `read` threw, rethrown once libpng has let go
  std::string error;
  png_structp png = nullptr;
  png_infop info = nullptr;
  PngFormat format;
  std::vector<std::uint8_t> strip;  // the rows being decoded
  std::vector<png_bytep> rows;
  ~ReadState() { png_destroy_read_struct(&png, info ? &info : nullptr, nullptr); }
};

struct WriteState {
  std::vector<std::uint8_t> bytes;
  std::string error;
  png_structp png = nullptr;
  png_infop info = nullptr;
  std::vector<png_bytep> rows;
  ~WriteState() { png_destroy_write_struct(&png, info ? &info : nullptr); }
};

void store_error_and_jump(png_structp png, png_const_charp message) {
  *static_cast<std::string*>(png_get_error_ptr(png)) = message;
  png_longjmp(png, 1);
}

void ignore_warning(png_structp, png_const_charp) {}

// An exception must not unwind through libpng's C frames: it is kept, and libpng's error path
// (a longjmp) taken once the handler has finished.
void read_from_source(png_structp png, png_bytep out, png_size_t count) {
  auto& state = *static_cast<ReadState*>(png_get_io_ptr(png));
  try {
    (*state.read)(out, count);
  } catch (...) {
    state.read_failure = std::current_exception();
  }
  if (state.read_failure) png_error(png, "the bytes could not be read");
}

void write_to_memory(png_structp png, png_bytep data, png_size_t count) {
  auto& state = *static_cast<WriteState*>(png_get_io_ptr(png));
  state.bytes.insert(state.bytes.end(), data, data + count);
}

void flush_nothing(png_structp) {}

int channel_count(int colour_type, bool transparency) {
  switch (colour_type) {
    case PNG_COLOR_TYPE_GRAY:
      return 1;
    case PNG_COLOR_TYPE_GRAY_ALPHA:
      return 2;
    case PNG_COLOR_TYPE_PALETTE:
      return transparency ? 4 : 3;
    case PNG_COLOR_TYPE_RGB_ALPHA:
      return 4;
    default:
      return 3;
  }
}

// Rows decoded at a time: 16, the transposing block of a native scan, and 16 rows of the widest
// image accepted still fit in half a megabyte.
constexpr int kStripRows = 16;

// Collects the whole image, for decode_png.
class WholeImage final : public PngRowSink {
 public:
  ByteImage image;
  bool start(int width, int height) override {
    image = ByteImage::uninitialised(height, width);
    return true;
  }
  bool take_rows(int first, int count, const std::uint8_t* rows) override {
    std::memcpy(image.row(first), rows,
                static_cast<std::size_t>(count) * static_cast<std::size_t>(image.cols()));
    return true;
  }
};

// False with state.error set when libpng fails. Only greyscale of at most 8 bits is decoded.
// Nothing with a destructor is created after setjmp: a longjmp back would skip it.
bool decode_into(ReadState& state) {
  if (setjmp(png_jmpbuf(state.png))) return false;
  png_set_read_fn(state.png, &state, read_from_source);
  png_read_info(state.png, state.info);
  const png_uint_32 width = png_get_image_width(state.png, state.info);
  const png_uint_32 height = png_get_image_height(state.png, state.info);
  const int colour_type = png_get_color_type(state.png, state.info);
  state.format.bit_depth = png_get_bit_depth(state.png, state.info);
  state.format.channels =
      channel_count(colour_type, png_get_valid(state.png, state.info, PNG_INFO_tRNS) != 0);
  if (colour_type != PNG_COLOR_TYPE_GRAY || state.format.bit_depth > 8) return true;
  if (state.format.bit_depth < 8) png_set_expand_gray_1_2_4_to_8(state.png);
  const int passes = png_set_interlace_handling(state.png);
  png_read_update_info(state.png, state.info);
  state.format.decoded = true;
  if (!state.sink->start(static_cast<int>(width), static_cast<int>(height))) return true;
  // An interlaced image's passes each revisit every row: it is decoded whole, then handed on.
  const png_uint_32 strip_rows =
      passes > 1 ? height : std::min(height, static_cast<png_uint_32>(kStripRows));
  state.strip.resize(std::size_t{strip_rows} * width);
  state.rows.resize(strip_rows);
  for (png_uint_32 y = 0; y < strip_rows; ++y) state.rows[y] = state.strip.data() + y * width;
  if (passes > 1) {
    png_read_image(state.png, state.rows.data());
    if (!state.sink->take_rows(0, static_cast<int>(height), state.strip.data())) return true;
  } else {
    for (png_uint_32 first = 0; first < height; first += strip_rows) {
      const png_uint_32 count = std::min(strip_rows, height - first);
      png_read_rows(state.png, state.rows.data(), nullptr, count);
      if (!state.sink->take_rows(static_cast<int>(first), static_cast<int>(count),
                                 state.strip.data())) {
        return true;
      }
    }
  }
  png_read_end(state.png, nullptr);
  return true;
}

bool encode_into(WriteState& state, const ByteImage& image) {
  if (setjmp(png_jmpbuf(state.png))) return false;
  png_set_write_fn(state.png, &state, write_to_memory, flush_nothing);
  // OpenCV's defaults when no compression level is asked for.
  png_set_filter(state.png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
  png_set_compression_level(state.png, Z_BEST_SPEED);
  png_set_compression_strategy(state.png, Z_RLE);
  png_set_IHDR(state.png, state.info, static_cast<png_uint_32>(image.cols()),
               static_cast<png_uint_32>(image.rows()), 8, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(state.png, state.info);
  png_write_image(state.png, state.rows.data());
  png_write_end(state.png, state.info);
  return true;
}

}  // namespace

PngFormat decode_png_rows(const PngByteSource& read, PngRowSink& sink, const std::string& source,
                          bool checksums_verified) {
  ReadState state;
  state.read = &read;
  state.sink = &sink;
  std::array<std::uint8_t, 8> signature{};
  read(signature.data(), signature.size());
  if (png_sig_cmp(signature.data(), 0, signature.size()) != 0) {
    throw std::runtime_error(
        fmt::format("{}: could not decode the image (not a PNG: no PNG signature)", source));
  }
  state.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &state.error, store_error_and_jump,
                                     ignore_warning);
  if (state.png) state.info = png_create_info_struct(state.png);
  if (!state.png || !state.info) {
    throw std::runtime_error(fmt::format("{}: out of memory decoding the PNG", source));
  }
  png_set_sig_bytes(state.png, static_cast<int>(signature.size()));
  if (checksums_verified) {
    png_set_crc_action(state.png, PNG_CRC_QUIET_USE, PNG_CRC_QUIET_USE);
#ifdef PNG_IGNORE_ADLER32
    png_set_option(state.png, PNG_IGNORE_ADLER32, PNG_OPTION_ON);
#endif
  }
  if (!decode_into(state)) {
    if (state.read_failure) std::rethrow_exception(state.read_failure);
    throw std::runtime_error(
        fmt::format("{}: could not decode the image (corrupt PNG: {})", source, state.error));
  }
  return state.format;
}

PngPixels decode_png(std::span<const std::uint8_t> bytes, const std::string& source,
                     bool checksums_verified) {
  if (bytes.size() < 8) {
    throw std::runtime_error(
        fmt::format("{}: could not decode the image (not a PNG: no PNG signature)", source));
  }
  std::size_t offset = 0;
  const PngByteSource read = [&](std::uint8_t* out, std::size_t count) {
    if (count > bytes.size() - offset) {
      throw std::runtime_error(fmt::format(
          "{}: could not decode the image (corrupt PNG: the file ends early (truncated))", source));
    }
    std::memcpy(out, bytes.data() + offset, count);
    offset += count;
  };
  WholeImage sink;
  const PngFormat format = decode_png_rows(read, sink, source, checksums_verified);
  PngPixels pixels;
  pixels.bit_depth = format.bit_depth;
  pixels.channels = format.channels;
  if (format.decoded) pixels.image = std::move(sink.image);
  return pixels;
}

PngPixels read_png(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<std::uint8_t> bytes;
  if (in) {
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    in.seekg(0, std::ios::beg);
    if (size > 0) {
      bytes.resize(static_cast<std::size_t>(size));
      in.read(reinterpret_cast<char*>(bytes.data()), size);
    }
  }
  if (!in) throw std::runtime_error(fmt::format("{}: cannot be read", path.string()));
  return decode_png(bytes, path.string());
}

std::vector<std::uint8_t> encode_png(const ByteImage& image) {
  if (image.empty()) throw std::invalid_argument("encode_png: expected a non-empty image");
  WriteState state;
  state.rows.resize(static_cast<std::size_t>(image.rows()));
  for (int y = 0; y < image.rows(); ++y) {
    // libpng's row type is not const; it only reads the rows it writes out.
    state.rows[static_cast<std::size_t>(y)] = const_cast<png_bytep>(image.row(y));
  }
  state.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &state.error, store_error_and_jump,
                                      ignore_warning);
  if (state.png) state.info = png_create_info_struct(state.png);
  if (!state.png || !state.info || !encode_into(state, image)) {
    throw std::runtime_error(
        fmt::format("encode_png: {}", state.error.empty() ? "out of memory" : state.error));
  }
  return std::move(state.bytes);
}

}  // namespace radarpr
