// The AVX-512 passes over a uint8 row (cen2018_avx512.hpp) against the baseline ones: exact
// integer sums, so the same values, on rows of every length around the 64-byte steps and with
// bytes across the whole range. Skipped on processors without AVX-512.
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "descriptors/features/cen2018_avx512.hpp"
#include "descriptors/features/cen2018_row_passes.hpp"

namespace radarpr {
namespace {

std::vector<unsigned char> random_row(int count, unsigned spread, std::uint32_t seed) {
  std::vector<unsigned char> row(static_cast<std::size_t>(count));
  for (auto& byte : row) {
    seed = seed * 1664525u + 1013904223u;
    byte = static_cast<unsigned char>((seed >> 8) % spread + (seed >> 4 & 1u) * (256u - spread));
  }
  return row;
}

TEST(Cen2018Avx512, RowMeanAndNegativePartAreThoseOfTheBaseline) {
  if (!cen2018_detail::has_avx512()) GTEST_SKIP() << "no AVX-512 on this processor";
  for (const int count : {1, 63, 64, 65, 127, 3360, 3768, 70001}) {
    for (const unsigned spread : {1u, 40u, 128u, 256u}) {
      const std::vector<unsigned char> row =
          random_row(count, spread, static_cast<std::uint32_t>(count) * 31u + spread);
      float mean = 0.0f;
      float wide_mean = 0.0f;
      const cen2018_detail::NegativePart part =
          cen2018_detail::byte_row_mean(row.data(), count, mean);
      const cen2018_detail::NegativePart wide =
          cen2018_detail::byte_row_mean_avx512(row.data(), count, wide_mean);
      EXPECT_EQ(wide_mean, mean) << count << " " << spread;
      EXPECT_EQ(wide.count, part.count) << count << " " << spread;
      EXPECT_EQ(wide.sum_of_squares, part.sum_of_squares) << count << " " << spread;
      EXPECT_EQ(wide.largest_magnitude, part.largest_magnitude) << count << " " << spread;
    }
  }
}

TEST(Cen2018Avx512, CandidatesAndSureBinsAreThoseOfTheBaseline) {
  if (!cen2018_detail::has_avx512()) GTEST_SKIP() << "no AVX-512 on this processor";
  for (const int count : {1, 63, 64, 65, 200, 3360, 3768}) {
    const std::vector<unsigned char> row =
        random_row(count, 256u, static_cast<std::uint32_t>(count) + 5u);
    for (const auto& [least, sure] : std::vector<std::pair<int, int>>{
             {0, 256}, {100, 200}, {200, 201}, {255, 256}, {256, 256}, {30, 30}}) {
      const std::size_t words = static_cast<std::size_t>(count) / 64 + 1;
      std::vector<int> bins(static_cast<std::size_t>(count) + 64);
      std::vector<int> wide_bins(static_cast<std::size_t>(count) + 64);
      std::vector<std::uint64_t> passing(words, 0);
      std::vector<std::uint64_t> wide_passing(words, 0);
      std::vector<std::uint64_t> band(words, ~std::uint64_t{0});
      const std::size_t n = cen2018_detail::byte_candidates(row.data(), count, least, sure,
                                                            bins.data(), passing.data());
      const std::size_t wide_n = cen2018_detail::byte_candidates_avx512(
          row.data(), count, least, sure, wide_bins.data(), wide_passing.data(), band.data());
      ASSERT_EQ(wide_n, n) << count << " " << least << " " << sure;
      bins.resize(n);
      wide_bins.resize(n);
      EXPECT_EQ(wide_bins, bins) << count << " " << least << " " << sure;
      EXPECT_EQ(wide_passing, passing) << count << " " << least << " " << sure;
      std::vector<std::uint64_t> listed(words, 0);
      for (const int bin : bins) {
        listed[static_cast<std::size_t>(bin) / 64] |= std::uint64_t{1} << (bin % 64);
      }
      EXPECT_EQ(band, listed) << count << " " << least << " " << sure;
    }
  }
}

}  // namespace
}  // namespace radarpr
