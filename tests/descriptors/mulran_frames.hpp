#pragma once

// Real MulRan KAIST03 frames for descriptor tests (../shared/data/real/referee_mulran_kaist03,
// never copied into the project): 000000, 000001, 000002 and 000010.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "datasets/polar_png.hpp"

namespace radarpr::testing {

inline std::filesystem::path native_frame(const std::string& name) {
  return std::filesystem::path(RADARPR_SOURCE_DIR) /
         "../shared/data/real/referee_mulran_kaist03/native" / (name + ".png");
}

// MulRan's native polar PNG: 400 columns of azimuth x 3360 rows of range, 200 m / 3360 per bin.
inline PolarImage read_native(const std::string& name) {
  PolarPngOptions options;
  options.range_resolution_m = 200.0 / 3360.0;
  options.layout = PolarPngLayout::mulran_native;
  return read_polar_png(native_frame(name), options).image;
}

}  // namespace radarpr::testing

// Skips the test, saying which file is missing, unless every named frame is present.
#define SKIP_WITHOUT_FRAMES(...)                                           \
  for (const char* frame : {__VA_ARGS__}) {                                \
    if (!std::filesystem::exists(radarpr::testing::native_frame(frame))) { \
      GTEST_SKIP() << "MulRan KAIST03 sample frame absent: "               \
                   << radarpr::testing::native_frame(frame);               \
    }                                                                      \
  }
