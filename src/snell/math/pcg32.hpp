#pragma once
// PCG32 (O'Neill 2014, "PCG: A Family of Simple Fast Space-Efficient Statistically Good Algorithms for
// Random Number Generation"), the XSH RR 64/32 variant. Seeded per pixel and sample so that images do not
// depend on thread count or tile order (DESIGN.md, "Numbers").
#include <cstdint>

namespace snell::math {

class Pcg32 {
 public:
  Pcg32() { seed(0x853c49e6748fea9bULL, 0xda3e39cb94b95bdbULL); }
  Pcg32(uint64_t state, uint64_t stream = 0xda3e39cb94b95bdbULL) { seed(state, stream); }

  void seed(uint64_t init_state, uint64_t stream) {
    state_ = 0;
    inc_ = (stream << 1u) | 1u;
    next_uint();
    state_ += init_state;
    next_uint();
  }

  uint32_t next_uint() {
    const uint64_t old = state_;
    state_ = old * 6364136223846793005ULL + inc_;
    const auto xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
    const auto rot = static_cast<uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((~rot + 1u) & 31));
  }

  /// Uniform in [0, 1).
  double next_double() { return next_uint() * 0x1p-32; }

 private:
  uint64_t state_ = 0;
  uint64_t inc_ = 0;
};

/// Mixes several integers into one well-distributed 64-bit seed (SplitMix64 finaliser).
constexpr uint64_t mix_seed(uint64_t a, uint64_t b = 0, uint64_t c = 0, uint64_t d = 0) {
  uint64_t h = a * 0x9E3779B97F4A7C15ULL;
  for (uint64_t v : {b, c, d}) {
    h ^= v + 0x9E3779B97F4A7C15ULL + (h << 6) + (h >> 2);
    h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ULL;
    h = (h ^ (h >> 27)) * 0x94D049BB133111EBULL;
    h ^= h >> 31;
  }
  return h;
}

}  // namespace snell::math
