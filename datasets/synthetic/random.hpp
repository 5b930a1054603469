#pragma once

#include <cstdint>
#include <initializer_list>

namespace radarpr::synthetic {

// Deterministic randomness for the synthetic world. Everything is derived from explicit keys
// (seed, session, block, scan index...) with integer arithmetic only, so a value never depends
// on call order, thread, platform or standard-library distribution implementations.

// splitmix64's finaliser: a bijective 64-bit mixer.
constexpr std::uint64_t mix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

// One 64-bit key from several values (order matters).
constexpr std::uint64_t hash_key(std::initializer_list<std::uint64_t> values) {
  std::uint64_t h = 0x243F6A8885A308D3ULL;
  for (const std::uint64_t v : values) h = mix64(h ^ mix64(v));
  return h;
}

// A small fast generator (splitmix64 stream) with the few distributions the generator needs.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : state_(seed) {}

  std::uint64_t next() {
    state_ += 0x9E3779B97F4A7C15ULL;
    std::uint64_t z = state_;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  // Uniform in [0, 1), 53 random bits.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  // Uniform integer in [lo, hi].
  int uniform_int(int lo, int hi) {
    const auto span = static_cast<std::uint64_t>(hi - lo) + 1;
    return lo + static_cast<int>(next() % span);
  }
  bool chance(double probability) { return uniform() < probability; }
  // Approximately normal (Irwin-Hall of 4 uniforms): enough for jitter, platform independent.
  double normal(double mean, double sigma) {
    const double sum = uniform() + uniform() + uniform() + uniform();
    return mean + sigma * (sum - 2.0) * 1.7320508075688772;  // sqrt(12/4) scales variance to 1
  }

 private:
  std::uint64_t state_;
};

}  // namespace radarpr::synthetic
