# Optional libFuzzer build of the fuzz targets (tests/fuzz). Off, every fuzz target is a plain
# program that runs its input function over a corpus (any compiler); on (clang only), the whole
# tree gets libFuzzer's coverage instrumentation so that the fuzzers see into the libraries, and
# the targets link libFuzzer's driver. Usually combined with RADARPR_SANITIZE=address,undefined.
option(RADARPR_FUZZ "Build the fuzz targets with clang's libFuzzer" OFF)

if(RADARPR_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "RADARPR_FUZZ needs clang's libFuzzer; configure with "
                        "-DCMAKE_CXX_COMPILER=clang++ (the fuzz targets build as plain corpus "
                        "programs with any compiler when it is off)")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
