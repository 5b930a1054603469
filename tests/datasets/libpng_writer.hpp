#pragma once

// PNGs written with libpng itself, for decoder tests that need what radarpr's own encoder never
// writes: Adam7 interlacing, or IDAT chunks of a chosen size.
#include <png.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace radarpr::testing {

struct LibpngLayout {
  bool adam7 = false;          // interlaced: every pass revisits the rows
  std::size_t idat_bytes = 0;  // the most image data per IDAT chunk; 0: libpng's default (8 KiB)
};

// An 8-bit greyscale PNG of `rows` (each `cols` bytes, top to bottom).
inline std::vector<std::uint8_t> libpng_encode(int cols,
                                               const std::vector<const std::uint8_t*>& rows,
                                               LibpngLayout layout = {}) {
  std::vector<std::uint8_t> bytes;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  png_set_write_fn(
      png, &bytes,
      [](png_structp writer, png_bytep data, png_size_t count) {
        auto& out = *static_cast<std::vector<std::uint8_t>*>(png_get_io_ptr(writer));
        out.insert(out.end(), data, data + count);
      },
      [](png_structp) {});
  if (layout.idat_bytes != 0) png_set_compression_buffer_size(png, layout.idat_bytes);
  png_set_IHDR(png, info, static_cast<png_uint_32>(cols), static_cast<png_uint_32>(rows.size()), 8,
               PNG_COLOR_TYPE_GRAY, layout.adam7 ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  std::vector<png_bytep> row_pointers;
  for (const std::uint8_t* row : rows) row_pointers.push_back(const_cast<png_bytep>(row));
  png_set_rows(png, info, row_pointers.data());
  png_write_png(png, info, PNG_TRANSFORM_IDENTITY, nullptr);
  png_destroy_write_struct(&png, &info);
  return bytes;
}

}  // namespace radarpr::testing
