// Fractal terrain against ../shared/reference-values.md section 5 (Martz, "Generating Random Fractal
// Terrain"): the random offsets of each pass shrink by 2^-H in range, so their variance falls by 2^-2H per
// level. The offsets are read back from the finished grid: a square step's centre minus the mean of its
// four corners (which later passes never change) is exactly the offset it received.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "snell/procedural/terrain.hpp"

namespace snell::procedural {
namespace {

/// Variance of the square-step offsets of each level (level 0 = the whole grid's centre), over many seeds.
std::vector<double> square_step_variances(int size, double h, int seeds) {
  std::vector<double> sum_sq;
  std::vector<long> count;
  for (int seed = 0; seed < seeds; ++seed) {
    const HeightMap m = diamond_square(size, h, static_cast<std::uint64_t>(seed));
    int level = 0;
    for (int step = size - 1; step > 1; step /= 2, ++level) {
      if (static_cast<int>(sum_sq.size()) <= level) sum_sq.push_back(0), count.push_back(0);
      const int half = step / 2;
      for (int k = half; k < size; k += step)
        for (int i = half; i < size; i += step) {
          const double mean = 0.25 * (m.at(i - half, k - half) + m.at(i + half, k - half) +
                                      m.at(i - half, k + half) + m.at(i + half, k + half));
          const double offset = m.at(i, k) - mean;
          sum_sq[static_cast<std::size_t>(level)] += offset * offset;
          ++count[static_cast<std::size_t>(level)];
        }
    }
  }
  std::vector<double> variance;
  for (std::size_t l = 0; l < sum_sq.size(); ++l)
    variance.push_back(sum_sq[l] / static_cast<double>(count[l]));
  return variance;
}

TEST(DiamondSquare, OffsetVarianceFallsByTwoToTheMinusTwoHPerLevel) {
  // Reference ratios (section 5): H 0.25 -> 0.707107, 0.5 -> 0.5, 0.75 -> 0.353553, 1 -> 0.25.
  const double h_values[] = {0.0, 0.25, 0.5, 0.75, 1.0}, ratios[] = {1.0, 0.707107, 0.5, 0.353553, 0.25};
  for (int j = 0; j < 5; ++j) {
    const std::vector<double> v = square_step_variances(65, h_values[j], 300);
    ASSERT_EQ(v.size(), 6u);
    // Uniform offsets in [-r, r] with r = 2^(-H level): variance r^2 / 3. Levels 2..5 hold 16 .. 1024
    // offsets per seed; with 300 seeds the estimates from level 2 on are within about 1.3 per cent (one
    // standard error), so 5 and 8 per cent are several standard errors.
    for (int level = 3; level < 6; ++level) {
      const double expected = std::pow(ratios[j], level) / 3;
      EXPECT_NEAR(v[static_cast<std::size_t>(level)] / expected, 1, 0.05)
          << "H " << h_values[j] << " level " << level;
      EXPECT_NEAR(v[static_cast<std::size_t>(level)] / v[static_cast<std::size_t>(level - 1)], ratios[j],
                  0.08 * ratios[j])
          << "H " << h_values[j] << " level " << level;
    }
  }
}

TEST(MidpointDisplacement, OffsetVarianceFallsByTwoToTheMinusTwoHPerLevel) {
  const int size = 1025;
  std::vector<double> sum_sq(10, 0.0);
  std::vector<long> count(10, 0);
  for (int seed = 0; seed < 100; ++seed) {
    const std::vector<double> p = midpoint_profile(size, 0.5, static_cast<std::uint64_t>(seed));
    EXPECT_EQ(p.front(), 0);
    EXPECT_EQ(p.back(), 0);
    int level = 0;
    for (int half = (size - 1) / 2; half >= 1; half /= 2, ++level)
      for (int i = half; i < size; i += 2 * half) {
        const auto u = static_cast<std::size_t>(i), d = static_cast<std::size_t>(half);
        const double offset = p[u] - 0.5 * (p[u - d] + p[u + d]);
        sum_sq[static_cast<std::size_t>(level)] += offset * offset;
        ++count[static_cast<std::size_t>(level)];
      }
  }
  for (int level = 4; level < 10; ++level) {
    const double variance =
        sum_sq[static_cast<std::size_t>(level)] / static_cast<double>(count[static_cast<std::size_t>(level)]);
    EXPECT_NEAR(variance / (std::pow(0.5, level) / 3), 1, 0.06) << level;
  }
}

TEST(DiamondSquare, SizesAndDeterminism) {
  EXPECT_THROW(diamond_square(512, 0.5, 1), TerrainError);
  EXPECT_THROW(diamond_square(8193, 0.5, 1), TerrainError);
  EXPECT_THROW(diamond_square(17, 1.5, 1), TerrainError);
  EXPECT_THROW(midpoint_profile(10, 0.5, 1), TerrainError);
  for (const int size : {3, 5, 9, 17, 33})
    EXPECT_EQ(diamond_square(size, 0.5, 1).values.size(), static_cast<std::size_t>(size * size));
  EXPECT_EQ(diamond_square(33, 0.6, 7).values, diamond_square(33, 0.6, 7).values);
  EXPECT_NE(diamond_square(33, 0.6, 7).values, diamond_square(33, 0.6, 8).values);
}

TEST(NoiseTerrain, NormalisedDeterministicAndRidged) {
  NoiseTerrain s;
  s.size = 65;
  s.seed = 3;
  HeightMap fbm = fbm_terrain(s);
  normalize(fbm);
  EXPECT_EQ(*std::ranges::min_element(fbm.values), 0);
  EXPECT_EQ(*std::ranges::max_element(fbm.values), 1);
  EXPECT_EQ(fbm_terrain(s).values, fbm_terrain(s).values);
  NoiseTerrain other = s;
  other.seed = 4;
  EXPECT_NE(fbm_terrain(other).values, fbm_terrain(s).values);
  // One octave of ridged noise is (offset - |n|)^2 with |n| <= 1: within [0, 1] for offset 1.
  s.octaves = 1;
  const HeightMap ridged = ridged_terrain(s);
  for (const double v : ridged.values) EXPECT_TRUE(v >= 0 && v <= 1);
  NoiseTerrain tiny;
  tiny.size = 1;
  EXPECT_THROW(fbm_terrain(tiny), TerrainError);
}

}  // namespace
}  // namespace snell::procedural
