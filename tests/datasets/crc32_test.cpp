// datasets/crc32: the folded CRC-32 must be zlib's, bit for bit, from any start, at any length
// and alignment (a wrong folding constant would differ on nearly every input).
#include "datasets/crc32.hpp"

#include <cstdint>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <zlib.h>

namespace radarpr {
namespace {

std::uint32_t zlib_crc(std::uint32_t crc, const std::uint8_t* data, std::size_t size) {
  return static_cast<std::uint32_t>(::crc32_z(crc, data, size));
}

TEST(Crc32, IsZlibsAtEveryLengthAlignmentAndStart) {
  std::mt19937 random(11);
  std::vector<std::uint8_t> bytes(70'000);
  for (auto& byte : bytes) byte = static_cast<std::uint8_t>(random());
  for (std::size_t size = 0; size < 600; ++size) {
    for (const std::size_t offset : {0, 1, 7, 16}) {
      const std::uint32_t start = size % 3 == 0 ? 0u : static_cast<std::uint32_t>(random());
      ASSERT_EQ(crc32(start, bytes.data() + offset, size),
                zlib_crc(start, bytes.data() + offset, size))
          << size << " bytes at " << offset << " from " << start;
    }
  }
  for (const std::size_t size : {8192u, 8196u, 65'536u, 69'999u}) {
    EXPECT_EQ(crc32(0, bytes.data() + 1, size), zlib_crc(0, bytes.data() + 1, size)) << size;
  }
  // Chained, as a chunk is checked piece by piece.
  std::uint32_t chained = 0;
  for (std::size_t at = 0; at < bytes.size(); at += 1000) {
    chained = crc32(chained, bytes.data() + at, std::min<std::size_t>(1000, bytes.size() - at));
  }
  EXPECT_EQ(chained, zlib_crc(0, bytes.data(), bytes.size()));
  // The check value of the standard: "123456789".
  const std::uint8_t digits[] = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};
  EXPECT_EQ(crc32(0, digits, sizeof digits), 0xCBF43926u);
}

}  // namespace
}  // namespace radarpr
