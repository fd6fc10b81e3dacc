// Media along a ray against closed forms: Beer-Lambert extinction, emission through absorption
// e/a (1 - exp(-a d)), single scattering of a constant light, and spotlight beam intervals.
#include "snell/render/media.hpp"

#include <gtest/gtest.h>

#include <cmath>

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

TEST(MediaTest, EmissionThroughAbsorptionMatchesTheClosedForm) {
  for (const int method : {1, 3}) {
    material::Media m;
    m.method = method;
    m.emission = Color(0.3);
    m.absorption = Color(0.5);
    math::Pcg32 rng(1);
    const MediaEffect e = media_along({&m}, {}, Ray{{0, 0, 0}, {1, 0, 0}}, 4, rng, kNoLight);
    // Method 3 integrates exactly for constant media; method 1 averages random samples of the same form.
    const double expected = 0.3 / 0.5 * (1 - std::exp(-2.0));
    EXPECT_NEAR(e.emitted.r, expected, method == 3 ? 1e-9 : 0.1 * expected) << method;
  }
}

TEST(MediaTest, ScatteringOfAConstantLightSaturatesToTheLight) {
  // Isotropic scattering sigma lit by light L everywhere: in-scattered sigma L per unit length, thinned by
  // extinction sigma, gives L (1 - exp(-sigma d)) (POV-Ray's isotropic phase weight is 1).
  material::Media m;
  m.scattering = Color(0.2);
  scene::Light light;
  light.position = {0, 10, 0};
  const LightSampler constant = [](const scene::Light&, const Vec3&) {
    return LightAtPoint{Color(2, 1, 0.5), Vec3{0, 1, 0}};
  };
  math::Pcg32 rng(1);
  const MediaEffect e = media_along({&m}, {light}, Ray{{0, 0, 0}, {1, 0, 0}}, 5, rng, constant);
  EXPECT_NEAR(e.emitted.r, 2 * (1 - std::exp(-1.0)), 1e-9);
  EXPECT_NEAR(e.emitted.b, 0.5 * (1 - std::exp(-1.0)), 1e-9);
  EXPECT_NEAR(e.transmittance.g, std::exp(-1.0), 1e-9);
}

TEST(MediaTest, LightsWithoutMediaInteractionDoNotScatter) {
  material::Media m;
  m.scattering = Color(0.2);
  scene::Light light;
  light.media_interaction = false;
  const LightSampler constant = [](const scene::Light&, const Vec3&) {
    return LightAtPoint{Color(1), Vec3{0, 1, 0}};
  };
  math::Pcg32 rng(1);
  EXPECT_EQ(media_along({&m}, {light}, Ray{{0, 0, 0}, {1, 0, 0}}, 5, rng, constant).emitted, Color(0));
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
