#include "datasets/sha256.hpp"

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

namespace radarpr {
namespace {

std::string sha256_of(std::string_view text) {
  return sha256_hex(std::as_bytes(std::span(text.data(), text.size())));
}

// (i * 7 + 3) mod 256 for i < count: crosses block boundaries without repeating a block.
std::string sha256_of_pattern(std::size_t count) {
  std::vector<std::byte> bytes(count);
  for (std::size_t i = 0; i < count; ++i) bytes[i] = static_cast<std::byte>((i * 7 + 3) % 256);
  return sha256_hex(bytes);
}

// FIPS 180-4's published examples (the NIST example values for SHA-256).
TEST(Sha256, MatchesThePublishedExamples) {
  EXPECT_EQ(sha256_of(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_of("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  // 56 bytes: the length no longer fits the first block, so padding takes a second one.
  EXPECT_EQ(sha256_of("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(sha256_of(std::string(1000000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

// Expected values from Python's hashlib.sha256 over the same bytes.
TEST(Sha256, MatchesHashlibAcrossBlockBoundaries) {
  EXPECT_EQ(sha256_of_pattern(1000),
            "1e9bc38cbf860b9ec31918b065f9b52476c549a782e0e7990bed8ce3868d2371");
  EXPECT_EQ(sha256_of_pattern(119),
            "9ce7368e4daf32341631b492e80359dc9f594b48453cd0dd5bf0b19279cc177e");
}

}  // namespace
}  // namespace radarpr
