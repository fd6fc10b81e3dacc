// POV-Ray's own noise (texture/povray_noise.hpp) against values POV-Ray 3.7.0 itself printed (Debian 12
// `povray`, 8x8 render of a scene with `global_settings { noise_generator G }` and
// `#debug str(f_noise3d(x, y, z), 0, 12)` from functions.inc; the DNoise values from
// `#debug str(F(x, y, z).red, 0, 12)` where F = function { pigment { gradient x turbulence <1,0,0>
// octaves 1 color_map {[0 rgb 0][1 rgb 1]} } }, i.e. frac(x + DNoise(p).x), stored by POV-Ray in single
// precision).
#include <gtest/gtest.h>

#include <cmath>

#include "snell/texture/povray_noise.hpp"

using snell::math::Vec3;
using snell::texture::NoiseGenerator;
using snell::texture::povray_dnoise;
using snell::texture::povray_noise;

namespace {

struct Sample {
  Vec3 p;
  double original, range_corrected, perlin;
};

const Sample kPovRaySamples[] = {
    {{0.3, 0.7, 1.1}, 0.855310987588, 0.689585217264, 0.573302353883},
    {{1.5, -2.25, 0.125}, 0.670794448753, 0.599198716830, 0.583915791992},
    {{10.1, 20.2, -5.3}, 0.559031820473, 0.544451142909, 0.532315706084},
    {{0, 0, 0}, 0.056580500000, 0.298322439308, 0.511354305373},
};

TEST(PovRayNoise, MatchesPovRayForEveryGenerator) {
  for (const Sample& s : kPovRaySamples) {
    EXPECT_NEAR(povray_noise(s.p, NoiseGenerator::original), s.original, 1e-11) << s.p.x;
    EXPECT_NEAR(povray_noise(s.p, NoiseGenerator::range_corrected), s.range_corrected, 1e-11) << s.p.x;
    EXPECT_NEAR(povray_noise(s.p, NoiseGenerator::perlin), s.perlin, 1e-11) << s.p.x;
  }
}

TEST(PovRayNoise, DefaultIsRangeCorrected) {
  EXPECT_NEAR(povray_noise({0.3, 0.7, 1.1}), 0.689585217264, 1e-11);
}

TEST(PovRayNoise, VectorNoiseMatchesPovRayTurbulenceWarp) {
  const auto warped_gradient = [](const Vec3& p) {
    const double g = p.x + povray_dnoise(p).x;
    return g - std::floor(g);
  };
  EXPECT_NEAR(warped_gradient({0.3, 0.7, 1.1}), 0.655310988426, 1e-8);
  EXPECT_NEAR(warped_gradient({1.5, -2.25, 0.125}), 0.670794427395, 1e-7);
}

TEST(PovRayNoise, StaysInUnitIntervalFarFromOrigin) {
  for (double x = -1e6; x <= 1e6; x += 12345.678) {
    const double n = povray_noise({x, -x / 3, x / 7});
    EXPECT_GE(n, 0.0);
    EXPECT_LE(n, 1.0);
  }
}

}  // namespace
