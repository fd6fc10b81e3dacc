// Media along a ray: Beer-Lambert extinction, emission and scattering as POV-Ray 3.7's method 3 samples them
// (against its renders of small scenes), shadow rays through varying density, and spotlight beam intervals.
#include "snell/render/media.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "snell/material/pigment.hpp"
#include "snell/math/constants.hpp"

namespace snell::render {
namespace {

using math::Color;
using math::Ray;
using math::Vec3;

const LightSampler kNoLight = [](const scene::Light&, const Vec3&) { return LightAtPoint{}; };

TEST(MediaTest, AbsorptionFollowsBeerLambert) {
  material::Media m;
  m.absorption = Color(0.1, 0.2, 0.4);
  math::Pcg32 rng(1);
  const MediaEffect e = media_along({&m}, {}, Ray{{0, 0, 0}, {0, 0, 1}}, 5, rng, kNoLight);
  EXPECT_NEAR(e.transmittance.r, std::exp(-0.5), 1e-9);
  EXPECT_NEAR(e.transmittance.b, std::exp(-2.0), 1e-9);
  EXPECT_EQ(e.emitted, Color(0));
  EXPECT_NEAR(media_transmittance({&m}, Ray{{0, 0, 0}, {0, 0, 1}}, 5).g, std::exp(-1.0), 1e-12);
}

TEST(MediaTest, EmissionThroughAbsorptionAsPovRay37SamplesIt) {
  // Emission 0.3 and absorption 0.5 over 4 units, default sampling (method 3, one interval, 10 samples).
  // POV-Ray 3.7.0.10 renders it (a box of that media seen head-on by an orthographic camera, +FH) at
  // 0.609375 (HDR, steps of 1/256 there): brighter than the closed form 0.3 / 0.5 (1 - exp(-2)) = 0.519,
  // as its method 3 thins each sub-interval only by those before it. Method 1's random samples average
  // the closed form's integrand.
  for (const int method : {1, 3}) {
    material::Media m;
    m.method = method;
    m.emission = Color(0.3);
    m.absorption = Color(0.5);
    math::Pcg32 rng(1);
    const MediaEffect e = media_along({&m}, {}, Ray{{0, 0, 0}, {1, 0, 0}}, 4, rng, kNoLight);
    const double closed_form = 0.3 / 0.5 * (1 - std::exp(-2.0));
    if (method == 3)
      EXPECT_NEAR(e.emitted.r, 0.609375, 0.004);
    else
      EXPECT_NEAR(e.emitted.r, closed_form, 0.1 * closed_form);
    EXPECT_NEAR(e.transmittance.r, std::exp(-2.0), 1e-9) << method;
  }
}

TEST(MediaTest, ScatteringOfAConstantLightAsPovRay37SamplesIt) {
  // Isotropic scattering sigma = 0.2 over 5 units lit by L everywhere (POV-Ray's isotropic phase weight is
  // 1): the exact answer is L (1 - exp(-1)). POV-Ray 3.7's method 3 with 10 samples takes 6 sub-intervals
  // of the interval, each seen with the full interval's in-scattering sigma L d and thinned by the optical
  // depth of those before it, 1/6 each: L/6 sum_k exp(-k/6), k = 0..5 (as EmissionThroughAbsorption...,
  // which POV-Ray's render confirms).
  material::Media m;
  m.scattering = Color(0.2);
  scene::Light light;
  light.position = {0, 10, 0};
  const LightSampler constant = [](const scene::Light&, const Vec3&) {
    return LightAtPoint{Color(2, 1, 0.5), Vec3{0, 1, 0}};
  };
  math::Pcg32 rng(1);
  const MediaEffect e = media_along({&m}, {light}, Ray{{0, 0, 0}, {1, 0, 0}}, 5, rng, constant);
  double povray = 0;
  for (int k = 0; k < 6; ++k) povray += std::exp(-k / 6.0) / 6;
  EXPECT_NEAR(e.emitted.r, 2 * povray, 1e-9);
  EXPECT_NEAR(e.emitted.b, 0.5 * povray, 1e-9);
  EXPECT_NEAR(e.transmittance.g, std::exp(-1.0), 1e-9);
}

/// Density rising linearly from 0 at y = -1 to 1 at y = 1 (as `gradient y` scaled 2, translated -y).
class RampInY final : public material::Pigment {
 public:
  material::Rgbft at(const material::PatternPoint& p) const override {
    return material::Rgbft{Color((p.p.y + 1) / 2)};
  }
};

TEST(MediaTest, ShadowRayThroughVaryingDensityAsPovRay37SamplesIt) {
  // Absorption 1.5, density rising 0 -> 1 along a diagonal of 2 sqrt 2 units, method 3 with samples 7,7.
  // POV-Ray 3.7.0.10 lights a floor through such a box (a 4 x 2 x 2 box of that media, light from the
  // upper left at 45 degrees) at 0.129 where it is 0.703 unshadowed (HDR): 0.1835 gets through. Its
  // sub-intervals cover the first 4/5 of the stretch only, where the density averages 0.4:
  // exp(-1.5 x 0.4 x 2 sqrt 2) = 0.1834. The exact answer, exp(-1.5 x 0.5 x 2 sqrt 2) = 0.120, is not it.
  material::Media m;
  m.absorption = Color(1.5);
  m.min_samples = m.max_samples = 7;
  m.densities.push_back({std::make_shared<RampInY>(), math::Transform{}});
  const Ray up{{1, -1, 0}, normalize(Vec3(-1, 1, 0))};
  EXPECT_NEAR(media_transmittance({&m}, up, 2 * std::sqrt(2.0)).r, 0.129 / 0.703, 0.003);
}

TEST(MediaTest, LightsWithoutMediaInteractionOrShadowlessDoNotScatter) {
  // POV-Ray 3.7 renders a scattering box lit only by a shadowless light black: its media gather light from
  // point, spot and cylinder lights, and shadowless makes a fill light.
  for (const bool shadowless : {false, true}) {
    material::Media m;
    m.scattering = Color(0.2);
    scene::Light light;
    light.media_interaction = shadowless;
    light.shadowless = shadowless;
    const LightSampler constant = [](const scene::Light&, const Vec3&) {
      return LightAtPoint{Color(1), Vec3{0, 1, 0}};
    };
    math::Pcg32 rng(1);
    EXPECT_EQ(media_along({&m}, {light}, Ray{{0, 0, 0}, {1, 0, 0}}, 5, rng, constant).emitted, Color(0));
  }
}

TEST(MediaTest, SpotlightBeamIntervalIsWhereTheRayCrossesTheFalloffCone) {
  scene::Light spot;
  spot.kind = scene::Light::Kind::spotlight;
  spot.position = {0, 10, 0};
  spot.point_at = {0, 0, 0};
  spot.falloff = 30;
  // A level ray at y = 4 (6 below the light) crosses the cone where |x| = 6 tan 30.
  const Ray across{{-20, 4, 0}, {1, 0, 0}};
  double t0 = 0, t1 = 0;
  ASSERT_TRUE(light_interval(spot, across, t0, t1));
  const double half = 6 * std::tan(math::radians(30));
  EXPECT_NEAR(t0, 20 - half, 1e-9);
  EXPECT_NEAR(t1, 20 + half, 1e-9);
  // Above the light the ray misses the beam.
  EXPECT_FALSE(light_interval(spot, Ray{{-20, 12, 0}, {1, 0, 0}}, t0, t1));
}

TEST(MediaTest, HenyeyGreensteinFavoursForwardScattering) {
  material::Media m;
  m.phase = material::Media::Phase::henyey_greenstein;
  m.eccentricity = 0.5;
  // Light behind the point as seen along the ray (to_light = view) continues towards the viewer.
  EXPECT_NEAR(m.phase_weight({0, 0, 1}, {0, 0, 1}), (1 - 0.25) / std::pow(0.25, 1.5), 1e-12);
  EXPECT_LT(m.phase_weight({0, 0, -1}, {0, 0, 1}), 1);
}

}  // namespace
}  // namespace snell::render
