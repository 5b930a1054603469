// Fuzz target: the polar PNG reader and the header check a sequence runs on every scan when it
// opens. Input: one byte choosing the options, then the file's bytes.
#include <cstdlib>
#include <stdexcept>

#include "datasets/png_header.hpp"
#include "datasets/polar_png.hpp"
#include "tests/fuzz/fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace radarpr;
  if (size < 1) return 0;
  const std::uint8_t choice = data[0];
  const auto path = fuzz::write_scratch_file("scan.png", fuzz::as_text(data + 1, size - 1));

  try {
    read_png_header(path);
  } catch (const std::exception& error) {
    fuzz::require_names(error, path.string());
  }

  PolarPngOptions options;
  options.range_resolution_m = 0.0438;
  switch (choice % 3) {
    case 1:
      options.layout = PolarPngLayout::oxford;
      break;
    case 2:
      options.layout = PolarPngLayout::mulran_native;
      break;
    default:
      break;  // detected from the shape
  }
  options.use_row_metadata = (choice & 0x4) == 0;
  try {
    const DecodedPolarPng decoded = read_polar_png(path, options);
    // A decoded scan must be what the reader promises: pixels, one row per azimuth.
    const PolarImage& image = decoded.image;
    if (image.power.empty() ||
        image.azimuths_rad.size() != static_cast<std::size_t>(image.azimuth_count())) {
      std::abort();
    }
  } catch (const std::exception& error) {
    fuzz::require_names(error, path.string());
  }
  return 0;
}
