#pragma once

#include <cstddef>
#include <cstdint>
#include <random>

namespace radarpr {

// The randomness of Open-RadVLAD's training (scan sampling, k-means++ seeding). std::mt19937_64's
// sequence is fixed by the C++ standard, but the standard distributions are not: they are done
// here with integer arithmetic so a seed gives the same codebook with every standard library.
class SeededRandom {
 public:
  // `stream` separates independent uses of one seed (sampling vs. seeding).
  SeededRandom(std::uint64_t seed, std::uint64_t stream)
      : engine_(seed ^ (stream * 0x9E3779B97F4A7C15ULL)) {}

  // Uniform in [0, 1), 53 random bits.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

  // Uniform in [0, count), without modulo bias (rejection of the incomplete top range).
  std::size_t below(std::size_t count) {
    const auto n = static_cast<std::uint64_t>(count);
    const std::uint64_t limit = UINT64_MAX - UINT64_MAX % n;
    std::uint64_t draw = engine_();
    while (draw >= limit) draw = engine_();
    return static_cast<std::size_t>(draw % n);
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace radarpr
