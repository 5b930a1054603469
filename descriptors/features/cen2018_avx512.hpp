#pragma once

#include <cstddef>
#include <cstdint>

#include "descriptors/features/cen2018_row_passes.hpp"

namespace radarpr::cen2018_detail {

// The Cen 2018 test of a uint8 row (cen2018.cpp) with AVX-512 (F, BW, VL and VNNI), where the
// processor has it (checked once at run time): 64 bytes per step for the row's passes, and the
// candidates decided 16 at a time in registers - their fixed-point window products, q, p and the
// float response test - without per-candidate arrays. Every integer sum is exact, and the float
// test is that of classify_responses with the same error margin (the compiler may fuse its
// multiply-adds: one rounding instead of two, within the same bound), so every verdict agrees with
// the exact response and the features are the same.

bool has_avx512();

// byte_row_mean, 64 bytes per step. Call only where has_avx512().
NegativePart byte_row_mean_avx512(const unsigned char* x, int count, float& mean);

// byte_candidates, 64 bytes per step; `bins` has room for count + 64 (the last candidate is
// repeated in the 16 entries after it, for decide_candidates_avx512). Also writes the candidates
// that are not sure as bits, band_words[0 .. count / 64] (bit r % 64 of word r / 64), for
// decide_candidates_avx512. Call only where has_avx512().
std::size_t byte_candidates_avx512(const unsigned char* x, int count, int least, int sure,
                                   int* bins, std::uint64_t* passing, std::uint64_t* band_words);

// The float response test of candidate bins of a uint8 row detrended by its mean.
struct CandidateTest {
  const unsigned char* bytes = nullptr;  // the row
  int count = 0;                         // its length
  float mean = 0.0f;                     // q = float(byte) - mean
  // The fixed-point taps (length a multiple of 16) and the windows: bins in [radius, last_inside]
  // read bytes + bin - radius, bins below radius left_edge + bin, the others
  // right_edge + bin - right_origin (cen2018.cpp builds the edges).
  const std::int16_t* taps = nullptr;
  std::size_t length = 0;
  int radius = 0;
  int last_inside = 0;
  const unsigned char* left_edge = nullptr;
  const unsigned char* right_edge = nullptr;
  int right_origin = 0;
  double offset = 0.0;  // p = float((sum - offset) * scale)
  double scale = 1.0;
  double sigma = 1.0;  // as classify_responses
  double threshold = 0.0;
  double p_error = 0.0;
  // Work space for q and p at the candidates, room for n + 32 values each.
  float* detrended = nullptr;
  float* smoothed = nullptr;
};

// For the candidate bins bins[0 .. n) that byte_candidates_avx512 listed (band_words: the same
// bins as bits): sets bit b of `passing` for each bin b that the float test passes
// (classify_responses with the fixed-point p), writes those it leaves undecided to `undecided`
// (room for n + 16) and returns how many. `chunk_passes` is work space for n / 16 + 9 values.
// Call only where has_avx512().
std::size_t decide_candidates_avx512(const CandidateTest& test, const int* bins, std::size_t n,
                                     const std::uint64_t* band_words, std::uint16_t* chunk_passes,
                                     std::uint64_t* passing, int* undecided);

}  // namespace radarpr::cen2018_detail
