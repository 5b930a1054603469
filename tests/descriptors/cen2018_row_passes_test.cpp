// The float sums of the Cen 2018 row passes run in four lanes (SSE2, or plain code elsewhere) and
// add the lanes in a fixed order, so a sum rounds the same on every processor. These tests spell
// that order out in scalar code and hold the passes to it bit for bit.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "descriptors/features/cen2018_row_passes.hpp"

namespace radarpr {
namespace {

// Values spread over several orders of magnitude, so that the order of the additions shows in the
// rounded sums.
std::vector<float> spread_values(std::size_t count, std::uint32_t seed) {
  std::vector<float> values;
  for (std::size_t i = 0; i < count; ++i) {
    seed = seed * 1664525u + 1013904223u;
    const float mantissa = static_cast<float>(seed >> 8) / 16777216.0f - 0.5f;
    values.push_back(std::ldexp(mantissa, static_cast<int>(seed % 23) - 8));
  }
  return values;
}

// Product k of each whole step of eight in lane k % 4 of one of two sums, the sums added lane by
// lane, the lanes as (0 + 2) + (1 + 3), then the rest one by one.
float dot_product_in_order(const float* a, const float* b, std::size_t length) {
  float first[4] = {};
  float second[4] = {};
  std::size_t k = 0;
  for (; k + 8 <= length; k += 8) {
    for (std::size_t lane = 0; lane < 4; ++lane) {
      first[lane] += a[k + lane] * b[k + lane];
      second[lane] += a[k + 4 + lane] * b[k + 4 + lane];
    }
  }
  float lanes[4];
  for (std::size_t lane = 0; lane < 4; ++lane) lanes[lane] = first[lane] + second[lane];
  float sum = (lanes[0] + lanes[2]) + (lanes[1] + lanes[3]);
  for (; k < length; ++k) sum += a[k] * b[k];
  return sum;
}

TEST(Cen2018RowPasses, DotProductAddsInTheStatedOrder) {
  int differs_from_a_plain_loop = 0;
  for (std::size_t length = 0; length <= 120; ++length) {
    const std::vector<float> a = spread_values(length, 11u + static_cast<std::uint32_t>(length));
    const std::vector<float> b = spread_values(length, 97u + static_cast<std::uint32_t>(length));
    const float sum = cen2018_detail::dot_product(a.data(), b.data(), length);
    ASSERT_EQ(sum, dot_product_in_order(a.data(), b.data(), length)) << length;
    float plain = 0.0f;
    for (std::size_t k = 0; k < length; ++k) plain += a[k] * b[k];
    differs_from_a_plain_loop += sum != plain ? 1 : 0;
  }
  // The order matters for these values: a test that a plain loop would pass could not fail.
  EXPECT_GT(differs_from_a_plain_loop, 10);
}

TEST(Cen2018RowPasses, NegativePartAddsInTheStatedOrder) {
  for (int count = 0; count <= 70; ++count) {
    const std::vector<float> q =
        spread_values(static_cast<std::size_t>(count), 5u + static_cast<std::uint32_t>(count));
    // Whole steps of four: bin r in lane r % 4, the lanes added as (0 + 2) + (1 + 3); the rest in
    // order.
    double lanes[4] = {};
    int r = 0;
    for (; r + 4 <= count; r += 4) {
      for (int lane = 0; lane < 4; ++lane) {
        const double negative = std::min(q[static_cast<std::size_t>(r + lane)], 0.0f);
        lanes[lane] += negative * negative;
      }
    }
    double squares = (lanes[0] + lanes[2]) + (lanes[1] + lanes[3]);
    int negatives = 0;
    float largest = 0.0f;
    for (const float v : q) {
      negatives += v < 0.0f ? 1 : 0;
      largest = std::max(largest, std::abs(v));
    }
    for (; r < count; ++r) {
      const double negative = std::min(q[static_cast<std::size_t>(r)], 0.0f);
      squares += negative * negative;
    }
    const cen2018_detail::NegativePart part = cen2018_detail::negative_part(q.data(), count);
    ASSERT_EQ(part.sum_of_squares, squares) << count;
    ASSERT_EQ(part.count, negatives) << count;
    ASSERT_EQ(part.largest_magnitude, largest) << count;
  }
}

}  // namespace
}  // namespace radarpr
