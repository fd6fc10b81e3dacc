// normal {} perturbation (POV-Ray 3.7 reference, "Normal"; normal.cpp's finite-difference rule): unit
// normals out, the gradient rule's size for a known gradient, slope maps' Hermite profile, normal maps.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "pattern_point.hpp"
#include "snell/math/pcg32.hpp"
#include "snell/texture/cellular_patterns.hpp"
#include "snell/texture/noise_patterns.hpp"
#include "snell/texture/pattern_normal.hpp"
#include "snell/texture/ripple_patterns.hpp"
#include "snell/texture/value_patterns.hpp"

using namespace snell::texture;
using snell::math::Vec3;
using snell::texture::test::at;

TEST(PatternNormalTest, GradientPatternTiltsAgainstItsDirectionByPovRaysFactor) {
  // gradient x has gradient (1,0,0); POV-Ray adds -5 * 0.02 * 4/3 * bump_size times the gradient.
  NormalSpec spec;
  spec.pattern = std::make_shared<GradientPattern>(Vec3{1, 0, 0});
  spec.bump_size = 1;
  const PatternNormal normal(spec);
  const Vec3 n = normal.perturb({0, 1, 0}, at({0.4, 0.2, 0.7}));
  const Vec3 expected = normalize(Vec3{-0.1 * 4 / 3, 1, 0});
  EXPECT_NEAR(n.x, expected.x, 1e-6);
  EXPECT_NEAR(n.y, expected.y, 1e-6);
  EXPECT_NEAR(n.z, 0, 1e-9);
}

TEST(PatternNormalTest, EveryPatternLeavesNormalsUnitLength) {
  std::shared_ptr<const ValuePattern> patterns[] = {
      std::make_shared<BumpsPattern>(),    std::make_shared<DentsPattern>(),
      std::make_shared<WrinklesPattern>(), std::make_shared<RipplesPattern>(),
      std::make_shared<WavesPattern>(),    std::make_shared<CracklePattern>(),
      std::make_shared<GranitePattern>(),  std::make_shared<LeopardPattern>()};
  snell::math::Pcg32 rng(13);
  for (const auto& pattern : patterns) {
    NormalSpec spec;
    spec.pattern = pattern;
    spec.bump_size = 2;
    const PatternNormal normal(spec);
    for (int i = 0; i < 50; ++i) {
      const Vec3 p{rng.next_double() * 6, rng.next_double() * 6, rng.next_double() * 6};
      const Vec3 n = normal.perturb(normalize(Vec3{0.2, 1, -0.3}), at(p));
      EXPECT_NEAR(length(n), 1.0, 1e-12);
    }
  }
}

TEST(PatternNormalTest, ZeroBumpSizeLeavesTheNormalAlone) {
  NormalSpec spec;
  spec.pattern = std::make_shared<BumpsPattern>();
  spec.bump_size = 0;
  const Vec3 n = PatternNormal(spec).perturb({0, 0, 1}, at({1.3, 2.1, 0.4}));
  EXPECT_NEAR(n.z, 1.0, 1e-12);
}

TEST(SlopeMapTest, HermiteThroughHeightsAndSlopes) {
  // Slopes equal to the chord: a straight line.
  const SlopeMap line({{0, 0, 1}, {1, 1, 1}});
  EXPECT_NEAR(line.height(0.3), 0.3, 1e-12);
  // Flat ends: the smoothstep 3t^2 - 2t^3.
  const SlopeMap smooth({{0, 0, 0}, {1, 1, 0}});
  EXPECT_NEAR(smooth.height(0.25), 3 * 0.0625 - 2 * 0.015625, 1e-12);
  EXPECT_NEAR(smooth.height(-1), 0.0, 1e-12);  // held outside the entries
  EXPECT_NEAR(smooth.height(2), 1.0, 1e-12);
}

TEST(NormalMapTest, EntriesBlendByThePatternValue) {
  NormalSpec tilt_x;
  tilt_x.pattern = std::make_shared<GradientPattern>(Vec3{1, 0, 0});
  NormalSpec map;
  map.pattern = std::make_shared<GradientPattern>(Vec3{0, 0, 1});
  map.normal_map = {{0.0, std::make_shared<FlatNormal>()}, {1.0, std::make_shared<PatternNormal>(tilt_x)}};
  const PatternNormal normal(map);
  // z = 0.001: almost all the flat entry.
  const Vec3 flat = normal.perturb({0, 1, 0}, at({0.5, 0, 0.001}));
  EXPECT_NEAR(flat.y, 1.0, 1e-4);
  // z = 0.999: almost all the tilted entry.
  const Vec3 tilted = normal.perturb({0, 1, 0}, at({0.5, 0, 0.999}));
  EXPECT_LT(tilted.x, -0.05);
}
