#pragma once

#include <cstddef>
#include <span>
#include <string>

namespace radarpr {

// SHA-256 (FIPS 180-4) of `bytes` as 64 lowercase hex digits: the identity results record for a
// learnt codebook, so that anyone can check it with standard tools (sha256sum, Python's hashlib).
std::string sha256_hex(std::span<const std::byte> bytes);

}  // namespace radarpr
