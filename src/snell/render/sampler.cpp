#include "snell/render/sampler.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

#include "snell/math/constants.hpp"
#include "snell/math/pcg32.hpp"

namespace snell::render {

namespace {

constexpr double kToUnit = 0x1p-32;
/// Largest double below 1, so that a sample never reaches the far edge of its domain.
constexpr double kOneMinus = 0x1.fffffffffffffp-1;

/// Direction numbers of Sobol dimensions 2..8 from Joe & Kuo, "Constructing Sobol sequences with better
/// two-dimensional projections" (SIAM J. Sci. Comput. 30, 2008), file new-joe-kuo-6.21201: degree s of the
/// primitive polynomial, its inner coefficients a, and the initial m_1..m_s.
struct SobolPolynomial {
  int s;
  uint32_t a;
  std::array<uint32_t, 5> m;
};
constexpr std::array<SobolPolynomial, kSobolDimensions - 1> kJoeKuo{{
    {1, 0, {1}},
    {2, 1, {1, 3}},
    {3, 1, {1, 3, 1}},
    {3, 2, {1, 1, 1}},
    {4, 1, {1, 1, 3, 3}},
    {4, 4, {1, 3, 5, 13}},
    {5, 2, {1, 1, 5, 5, 17}},
}};

/// v_k = m_k / 2^k as 32-bit fixed point, for k = 1..32 (Bratley & Fox, "Algorithm 659", 1988).
using Directions = std::array<uint32_t, 32>;

constexpr Directions directions_for(int dim) {
  Directions v{};
  if (dim == 0) {
    for (int k = 0; k < 32; ++k) v[k] = 1u << (31 - k);
    return v;
  }
  const SobolPolynomial& p = kJoeKuo[dim - 1];
  for (int k = 0; k < p.s; ++k) v[k] = p.m[k] << (31 - k);
  for (int k = p.s; k < 32; ++k) {
    uint32_t x = v[k - p.s] ^ (v[k - p.s] >> p.s);
    for (int l = 1; l < p.s; ++l)
      if ((p.a >> (p.s - 1 - l)) & 1u) x ^= v[k - l];
    v[k] = x;
  }
  return v;
}

constexpr std::array<Directions, kSobolDimensions> make_directions() {
  std::array<Directions, kSobolDimensions> all{};
  for (int d = 0; d < kSobolDimensions; ++d) all[d] = directions_for(d);
  return all;
}
constexpr std::array<Directions, kSobolDimensions> kDirections = make_directions();

uint32_t sobol_bits(uint32_t index, int dim) {
  uint32_t x = 0;
  for (int k = 0; index != 0; index >>= 1, ++k)
    if (index & 1u) x ^= kDirections[dim][k];
  return x;
}

constexpr std::array<uint32_t, kSampleDimensions> kPrimes{2, 3, 5, 7, 11};

uint64_t hash(uint64_t a, uint64_t b) {
  return math::mix_seed(a, b);
}

/// A permutation of [0, n) chosen by `seed`: rounds of bijective mixing on the next power of two (xor with
/// a key, multiplication by an odd key, xor-shift: each invertible modulo 2^k), walked until the value lands
/// inside [0, n) (cycle walking keeps it a bijection of [0, n)).
uint32_t permute(uint32_t i, uint32_t n, uint64_t seed) {
  uint32_t mask = n - 1;
  mask |= mask >> 1;
  mask |= mask >> 2;
  mask |= mask >> 4;
  mask |= mask >> 8;
  mask |= mask >> 16;
  const int bits = std::popcount(mask);
  const int shift = std::max(1, bits / 2);
  do {
    uint64_t key = seed;
    for (int round = 0; round < 4; ++round) {
      key = math::mix_seed(key, static_cast<uint64_t>(round));
      i = (i ^ static_cast<uint32_t>(key)) & mask;
      i = (i * (static_cast<uint32_t>(key >> 32) | 1u)) & mask;
      i ^= i >> shift;
    }
  } while (i >= n);
  return i;
}

class StratifiedSampler final : public Sampler {
 public:
  double get(uint64_t pixel_seed, uint32_t index, uint32_t count, int dim) const override {
    // Each dimension takes the strata in its own shuffled order, so (x, y, time...) are stratified in every
    // one-dimensional projection without the n^d cost of a full grid.
    const uint64_t dim_seed = hash(pixel_seed, static_cast<uint64_t>(dim) + 1);
    const uint32_t stratum = permute(index, count, dim_seed);
    const double jitter = static_cast<double>(static_cast<uint32_t>(hash(dim_seed, index) >> 32)) * kToUnit;
    return std::min((stratum + jitter) / count, kOneMinus);
  }
};

class SobolSampler final : public Sampler {
 public:
  double get(uint64_t pixel_seed, uint32_t index, uint32_t /*count*/, int dim) const override {
    const uint32_t bits =
        owen_scramble(sobol_bits(index, dim), hash(pixel_seed, static_cast<uint64_t>(dim) + 1));
    return bits * kToUnit;
  }
};

class HaltonSampler final : public Sampler {
 public:
  double get(uint64_t pixel_seed, uint32_t index, uint32_t /*count*/, int dim) const override {
    const double shift =
        static_cast<double>(static_cast<uint32_t>(hash(pixel_seed, static_cast<uint64_t>(dim) + 1) >> 32)) *
        kToUnit;
    const double x = halton(index, dim) + shift;
    return std::min(x >= 1 ? x - 1 : x, kOneMinus);
  }
};

}  // namespace

double sobol(uint32_t index, int dim) {
  return sobol_bits(index, dim) * kToUnit;
}

double halton(uint32_t index, int dim) {
  const uint32_t base = kPrimes[static_cast<size_t>(dim) % kPrimes.size()];
  const double inv = 1.0 / base;
  double x = 0, scale = inv;
  for (; index != 0; index /= base, scale *= inv) x += (index % base) * scale;
  return x;
}

uint32_t owen_scramble(uint32_t bits, uint64_t seed) {
  // Nested uniform scrambling (Owen 1995): the flip of bit k depends only on the bits above it, so points
  // that share a leading binary interval stay together and stratification survives the scrambling.
  uint32_t out = bits;
  for (int k = 31; k >= 0; --k) {
    const uint64_t prefix = k == 31 ? 0 : (static_cast<uint64_t>(bits) >> (k + 1)) | (1ull << (31 - k));
    if (hash(seed, prefix) & 1u) out ^= 1u << k;
  }
  return out;
}

math::Vec2 disc_point(double u, double v) {
  const double r = 0.5 * std::sqrt(u);
  const double a = math::kTwoPi * v;
  return {r * std::cos(a), r * std::sin(a)};
}

std::unique_ptr<Sampler> make_sampler(std::string_view name) {
  if (name == "stratified") return std::make_unique<StratifiedSampler>();
  if (name == "sobol") return std::make_unique<SobolSampler>();
  if (name == "halton") return std::make_unique<HaltonSampler>();
  return nullptr;
}

}  // namespace snell::render
