// POV-Ray's own noise (texture/povray_noise.hpp) against values POV-Ray 3.7.0 itself printed (Debian 12
// `povray`, 8x8 render of a scene with `global_settings { noise_generator G }` and
// `#debug str(f_noise3d(x, y, z), 0, 12)` from functions.inc; the DNoise values from
// `#debug str(F(x, y, z).red, 0, 12)` where F = function { pigment { gradient x turbulence <1,0,0>
// octaves 1 color_map {[0 rgb 0][1 rgb 1]} } }, i.e. frac(x + DNoise(p).x), stored by POV-Ray in single
// precision).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

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

namespace {

using snell::texture::kNoiseLanes;
using snell::texture::povray_noise_lanes;

/// Every lane of the multi-point noise equals the one-point noise bit for bit, for every generator, over
/// points near and far from the origin, on both sides of lattice planes (including POV-Ray's 1e-10 rounding
/// of negative coordinates) and the clamped extremes.
TEST(PovRayNoise, LanesEqualOnePointCalls) {
  std::vector<double> coordinates;
  for (int k = 0; k < 400; ++k) coordinates.push_back(std::sin(k * 1.37) * std::pow(10.0, k % 7 - 2));
  for (double c : {0.0, -0.0, 1.0, -1.0, -3.0, -3.0 + 5e-11, -3.0 - 5e-11, 2.5, -1e9, 1e9, 4e9})
    coordinates.push_back(c);
  while (coordinates.size() % kNoiseLanes) coordinates.push_back(0.25);
  for (NoiseGenerator g : {NoiseGenerator::original, NoiseGenerator::range_corrected, NoiseGenerator::perlin})
    for (std::size_t i = 0; i < coordinates.size(); i += kNoiseLanes) {
      double x[kNoiseLanes], y[kNoiseLanes], z[kNoiseLanes], out[kNoiseLanes];
      for (int l = 0; l < kNoiseLanes; ++l) {
        x[l] = coordinates[i + l];
        y[l] = coordinates[(i + 3 * l + 1) % coordinates.size()];
        z[l] = -coordinates[(i + 5 * l + 2) % coordinates.size()];
      }
      povray_noise_lanes(x, y, z, out, g);
      for (int l = 0; l < kNoiseLanes; ++l) {
        const double one = povray_noise({x[l], y[l], z[l]}, g);
        EXPECT_EQ(std::memcmp(&out[l], &one, sizeof one), 0)
            << "generator " << static_cast<int>(g) << " at " << x[l] << ", " << y[l] << ", " << z[l] << ": "
            << out[l] << " against " << one;
      }
    }
}

}  // namespace

namespace {

using snell::texture::povray_dnoise_scaled;
using snell::texture::povray_noise_scaled;

/// The octave batches (used by turbulence, granite and wrinkles) equal one-point calls bit for bit, for
/// counts below, at and above the lane count, points near and far from the origin and on lattice planes.
TEST(PovRayNoise, ScaledBatchesEqualOnePointCalls) {
  const Vec3 points[] = {{0.3, 0.7, 1.1}, {-3.0, 2.0, -5e-11}, {1234.5, -987.25, 0.001}, {-0.2, -0.4, 7.9}};
  double scales[13];
  double f = 1;
  for (double& s : scales) s = f, f *= 2.25;
  for (const Vec3& p : points)
    for (int count : {1, 6, 8, 9, 13}) {
      for (NoiseGenerator g :
           {NoiseGenerator::original, NoiseGenerator::range_corrected, NoiseGenerator::perlin}) {
        double out[13];
        povray_noise_scaled(p, scales, count, out, g);
        for (int i = 0; i < count; ++i) {
          const double one = povray_noise(p * scales[i], g);
          EXPECT_EQ(std::memcmp(&out[i], &one, sizeof one), 0) << "octave " << i << " of " << count;
        }
      }
      Vec3 vout[13];
      povray_dnoise_scaled(p, scales, count, vout);
      for (int i = 0; i < count; ++i) {
        const Vec3 one = povray_dnoise(p * scales[i]);
        EXPECT_EQ(std::memcmp(&vout[i], &one, sizeof one), 0) << "octave " << i << " of " << count;
      }
    }
}

}  // namespace
