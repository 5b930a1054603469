#include "datasets/crc32.hpp"

#include <zlib.h>

#if defined(__x86_64__)
#include <immintrin.h>

#include "datasets/cpu_features.hpp"
#endif

namespace radarpr {
namespace {

#if defined(__x86_64__)
// Folding: a 128-bit block A that stands N bits before the end of what is folded is replaced by
// lo(A) * (x^(N+32) mod P) + hi(A) * (x^(N-32) mod P), carry-less and bit-reflected, which leaves
// the message's remainder mod P unchanged. The constants are those powers of x for N = 512 (four
// blocks in flight) and N = 128 (one block), shifted left by one for the reflection.
constexpr long long kFold512Low = 0x154442bd4;
constexpr long long kFold512High = 0x1c6e41596;
constexpr long long kFold128Low = 0x1751997d0;
constexpr long long kFold128High = 0x0ccaa009e;

__attribute__((target("pclmul,sse4.1"))) inline __m128i fold(__m128i block, __m128i constants,
                                                             __m128i next) {
  const __m128i low = _mm_clmulepi64_si128(block, constants, 0x00);
  const __m128i high = _mm_clmulepi64_si128(block, constants, 0x11);
  return _mm_xor_si128(_mm_xor_si128(low, high), next);
}

inline __m128i load(const std::uint8_t* bytes) {
  return _mm_loadu_si128(reinterpret_cast<const __m128i*>(bytes));
}

// At least 64 bytes. The register's starting value (zlib's crc inverted) is XORed into the first
// four bytes, which is what starting from it means; the folds then reduce the message to 16
// bytes with the same remainder, whose CRC (from a zero register) zlib finishes with the tail.
__attribute__((target("pclmul,sse4.1"))) std::uint32_t crc32_folded(std::uint32_t crc,
                                                                    const std::uint8_t* data,
                                                                    std::size_t size) {
  __m128i x0 = _mm_xor_si128(load(data), _mm_cvtsi32_si128(static_cast<int>(~crc)));
  __m128i x1 = load(data + 16);
  __m128i x2 = load(data + 32);
  __m128i x3 = load(data + 48);
  data += 64;
  size -= 64;
  const __m128i by512 = _mm_set_epi64x(kFold512High, kFold512Low);
  while (size >= 64) {
    x0 = fold(x0, by512, load(data));
    x1 = fold(x1, by512, load(data + 16));
    x2 = fold(x2, by512, load(data + 32));
    x3 = fold(x3, by512, load(data + 48));
    data += 64;
    size -= 64;
  }
  const __m128i by128 = _mm_set_epi64x(kFold128High, kFold128Low);
  __m128i x = fold(fold(fold(x0, by128, x1), by128, x2), by128, x3);
  while (size >= 16) {
    x = fold(x, by128, load(data));
    data += 16;
    size -= 16;
  }
  alignas(16) std::uint8_t folded[16];
  _mm_store_si128(reinterpret_cast<__m128i*>(folded), x);
  // zlib's crc32_z starts its register at the inverse of what it is given: ~0 gives zero.
  const auto register_zero = static_cast<uLong>(0xFFFFFFFFu);
  const uLong partial = ::crc32_z(register_zero, folded, sizeof folded);
  return static_cast<std::uint32_t>(::crc32_z(partial, data, size));
}
#endif

}  // namespace

std::uint32_t crc32(std::uint32_t crc, const std::uint8_t* data, std::size_t size) {
#if defined(__x86_64__)
  if (size >= 64 && cpu_features().pclmul) return crc32_folded(crc, data, size);
#endif
  return static_cast<std::uint32_t>(::crc32_z(crc, data, size));
}

}  // namespace radarpr
