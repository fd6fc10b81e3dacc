// Values from ../shared/reference-values.md section 1 (recomputed from Perlin's published algorithm;
// (3.14, 42, 7) is also Rosetta Code's "Perlin noise" task value).
#include "snell/texture/perlin_noise.hpp"

#include <gtest/gtest.h>

using snell::texture::improved_perlin_noise;

TEST(ImprovedPerlinNoiseTest, MatchesReferenceValues) {
  struct Case {
    double x, y, z, expected;
  };
  const Case cases[] = {
      {3.14, 42, 7, 0.13691995878400012},
      {-4.2, 10, 6, 0.14208000000000043},
      {0.1, 0.1, 0.1, 0.1861607143544832},
      {0.5, 0.5, 0.5, -0.25},
      {1.5, 2.5, 3.5, 0.125},
      {0.25, 0.75, 0.5, -0.16791534423828125},
      {10.3, -7.7, 2.2, 0.4300506136647169},
      {123.456, 78.9, 0.001, -0.21285778457971205},
      {3.14, 42, 0, 0.13691995878400012},
      {-4.2, 10, 0, -0.14208000000000043},
  };
  for (const Case& c : cases)
    EXPECT_NEAR(improved_perlin_noise(c.x, c.y, c.z), c.expected, 1e-12) << c.x << "," << c.y << "," << c.z;
}

TEST(ImprovedPerlinNoiseTest, VanishesOnLatticePoints) {
  for (int i = -3; i <= 3; ++i) EXPECT_EQ(improved_perlin_noise(i, 2 * i, -i), 0.0);
}

TEST(ImprovedPerlinNoiseTest, FadeCurveValue) {
  EXPECT_DOUBLE_EQ(snell::texture::perlin_fade(0.75), 0.896484375);
}

TEST(PerlinTurbulenceTest, OneOctaveIsAbsoluteNoise) {
  const snell::math::Vec3 p{0.25, 0.75, 0.5};
  EXPECT_DOUBLE_EQ(snell::texture::perlin_turbulence(p, 1), 0.16791534423828125);
  EXPECT_GT(snell::texture::perlin_turbulence(p, 4), snell::texture::perlin_turbulence(p, 1));
}
