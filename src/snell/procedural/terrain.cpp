#include "snell/procedural/terrain.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "snell/math/pcg32.hpp"
#include "snell/texture/perlin_noise.hpp"

namespace snell::procedural {

namespace {

/// Number of halvings from size - 1 down to 1; throws unless size = 2^n + 1 within the limit.
int power_of_two_levels(int size, const char* what) {
  if (size >= 3 && size <= kMaxTerrainSize && ((size - 1) & (size - 2)) == 0) {
    int levels = 0;
    for (int s = size - 1; s > 1; s /= 2) ++levels;
    return levels;
  }
  throw TerrainError(std::string(what) + " size must be 2^n + 1 (3, 5, 9, ..., 513, ..., 4097), not " +
                     std::to_string(size));
}

void check_roughness(double roughness) {
  if (!(roughness >= 0 && roughness <= 1)) throw TerrainError("roughness must lie in [0, 1]");
}

/// Uniform in [-range, range].
double offset(math::Pcg32& random, double range) {
  return (2 * random.next_double() - 1) * range;
}

}  // namespace

std::vector<double> midpoint_profile(int size, double roughness, std::uint64_t seed) {
  power_of_two_levels(size, "midpoint");
  check_roughness(roughness);
  math::Pcg32 random(seed, 0x4d4944504f494e54ULL);
  std::vector<double> h(static_cast<std::size_t>(size), 0.0);
  const double shrink = std::pow(2.0, -roughness);
  double range = 1;
  for (int half = (size - 1) / 2; half >= 1; half /= 2, range *= shrink)
    for (int i = half; i < size; i += 2 * half) {
      const auto u = static_cast<std::size_t>(i);
      const auto d = static_cast<std::size_t>(half);
      h[u] = 0.5 * (h[u - d] + h[u + d]) + offset(random, range);
    }
  return h;
}

HeightMap diamond_square(int size, double roughness, std::uint64_t seed) {
  power_of_two_levels(size, "diamond_square");
  check_roughness(roughness);
  math::Pcg32 random(seed, 0x4449414d4f4e44ULL);
  HeightMap map{size, size,
                std::vector<double>(static_cast<std::size_t>(size) * static_cast<std::size_t>(size), 0.0)};
  const double shrink = std::pow(2.0, -roughness);
  double range = 1;
  for (int step = size - 1; step > 1; step /= 2, range *= shrink) {
    const int half = step / 2;
    // Square step: the centre of each square is the mean of its corners plus an offset.
    for (int k = half; k < size; k += step)
      for (int i = half; i < size; i += step)
        map.at(i, k) = 0.25 * (map.at(i - half, k - half) + map.at(i + half, k - half) +
                               map.at(i - half, k + half) + map.at(i + half, k + half)) +
                       offset(random, range);
    // Diamond step: the centre of each diamond (the squares' edge midpoints) from its 4 or 3 neighbours.
    for (int k = 0; k < size; k += half)
      for (int i = (k / half) % 2 == 0 ? half : 0; i < size; i += step) {
        double sum = 0;
        int count = 0;
        const int di[4] = {-half, half, 0, 0}, dk[4] = {0, 0, -half, half};
        for (int n = 0; n < 4; ++n) {
          const int ni = i + di[n], nk = k + dk[n];
          if (ni < 0 || nk < 0 || ni >= size || nk >= size) continue;
          sum += map.at(ni, nk);
          ++count;
        }
        map.at(i, k) = sum / count + offset(random, range);
      }
  }
  return map;
}

namespace {

void check_noise(const NoiseTerrain& s) {
  if (s.size < 2 || s.size > kMaxTerrainSize) throw TerrainError("size must lie in 2 .. 4097");
  if (s.octaves < 1 || s.octaves > 30) throw TerrainError("octaves must lie in 1 .. 30");
  if (!(s.lacunarity > 1)) throw TerrainError("lacunarity must be greater than 1");
  if (!(s.frequency > 0)) throw TerrainError("frequency must be positive");
  check_roughness(s.roughness);
}

/// Samples f(x, z) on the grid, x and z in [0, frequency], with a seed-chosen shift of the noise domain.
template <class Sample>
HeightMap sample_grid(const NoiseTerrain& s, Sample&& sample) {
  math::Pcg32 random(s.seed, 0x4e4f495345ULL);
  const math::Vec3 shift(random.next_double() * 1000, random.next_double() * 1000,
                         random.next_double() * 1000);
  HeightMap map{s.size, s.size,
                std::vector<double>(static_cast<std::size_t>(s.size) * static_cast<std::size_t>(s.size))};
  for (int k = 0; k < s.size; ++k)
    for (int i = 0; i < s.size; ++i)
      map.at(i, k) = sample(shift + math::Vec3(i, 0, k) * (s.frequency / (s.size - 1)));
  return map;
}

}  // namespace

// fBm: the sum over octaves i of noise(p * lacunarity^i) * lacunarity^(-i H) (Musgrave, ch. 16, "fBm").
HeightMap fbm_terrain(const NoiseTerrain& s) {
  check_noise(s);
  const double amplitude_step = std::pow(s.lacunarity, -s.roughness);
  return sample_grid(s, [&](math::Vec3 p) {
    double sum = 0, amplitude = 1;
    for (int i = 0; i < s.octaves; ++i, p = p * s.lacunarity, amplitude *= amplitude_step)
      sum += amplitude * texture::improved_perlin_noise(p);
    return sum;
  });
}

// Ridged multifractal (Musgrave, ch. 16, "RidgedMultifractal"): each octave's signal is (offset - |noise|)^2,
// weighted by the previous octave's signal times gain (clamped to [0, 1]) so ridges gather detail while
// valleys stay smooth.
HeightMap ridged_terrain(const NoiseTerrain& s) {
  check_noise(s);
  const double amplitude_step = std::pow(s.lacunarity, -s.roughness);
  return sample_grid(s, [&](math::Vec3 p) {
    double signal = s.offset - std::abs(texture::improved_perlin_noise(p));
    signal *= signal;
    double sum = signal, amplitude = 1;
    for (int i = 1; i < s.octaves; ++i) {
      p = p * s.lacunarity;
      amplitude *= amplitude_step;
      const double weight = std::clamp(signal * s.gain, 0.0, 1.0);
      signal = s.offset - std::abs(texture::improved_perlin_noise(p));
      signal *= signal * weight;
      sum += signal * amplitude;
    }
    return sum;
  });
}

void normalize(HeightMap& map) {
  if (map.values.empty()) return;
  const auto [lo, hi] = std::minmax_element(map.values.begin(), map.values.end());
  const double low = *lo, span = *hi - *lo;
  for (double& v : map.values) v = span > 0 ? (v - low) / span : 0;
}

}  // namespace snell::procedural
