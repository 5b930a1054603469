// The least a process can do to read one radar scan on this machine: start, load libpng, decode
// a PNG's rows into memory, exit. `radarpr bench` times it beside `radarpr extract` (start-up
// rows, startup_benchmarks.hpp) so that the whole-process figures have a floor to be read
// against, as the extraction rows have their plain pass.
//
// Deliberately minimal, and no substitute for datasets/png_codec.hpp: no validation beyond what
// libpng does, no metadata, no C++ runtime (built without exceptions and linked as needed, so
// that libstdc++ is not loaded). Checksums are not verified, as radarpr's own decoder does not
// verify them either when told the file is trusted.
//
// usage: radarpr_png_decode_floor [FILE.png]   (no file: start and exit, nothing else)

#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <cstdlib>

namespace {

// libpng reports fatal errors by longjmp to the point png_jmpbuf was set.
int decode(std::FILE* file) {
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png != nullptr ? png_create_info_struct(png) : nullptr;
  if (png == nullptr || info == nullptr) return 2;
  // volatile: it changes after setjmp and is read again after a longjmp.
  unsigned char* volatile pixels = nullptr;
  if (setjmp(png_jmpbuf(png))) {
    std::free(pixels);
    png_destroy_read_struct(&png, &info, nullptr);
    return 3;
  }
  png_set_crc_action(png, PNG_CRC_QUIET_USE, PNG_CRC_QUIET_USE);
#ifdef PNG_IGNORE_ADLER32
  png_set_option(png, PNG_IGNORE_ADLER32, PNG_OPTION_ON);
#endif
  png_init_io(png, file);
  png_read_info(png, info);
  const png_size_t row_bytes = png_get_rowbytes(png, info);
  const png_uint_32 rows = png_get_image_height(png, info);
  pixels = static_cast<unsigned char*>(std::malloc(row_bytes * rows));
  if (pixels == nullptr) png_error(png, "out of memory");
  for (png_uint_32 r = 0; r < rows; ++r) png_read_row(png, pixels + r * row_bytes, nullptr);
  png_read_end(png, nullptr);
  std::free(pixels);
  png_destroy_read_struct(&png, &info, nullptr);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return 0;
  std::FILE* file = std::fopen(argv[1], "rb");
  if (file == nullptr) {
    std::fprintf(stderr, "%s: cannot open\n", argv[1]);
    return 1;
  }
  const int status = decode(file);
  std::fclose(file);
  if (status != 0) std::fprintf(stderr, "%s: not a PNG libpng could decode\n", argv[1]);
  return status;
}
