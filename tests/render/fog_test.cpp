// Fog against the closed forms of POV-Ray 3.7's fog model (reference "Fog"; trace.cpp ComputeFog).
#include "snell/render/fog.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "snell/math/constants.hpp"

namespace snell::render {
namespace {

using math::Color;
using math::Ray;
using math::Vec3;

scene::Fog constant_fog(double distance, const Color& c) {
  scene::Fog f;
  f.distance = distance;
  f.color.rgb = c;
  return f;
}

TEST(FogTest, ConstantFogThinsExponentiallyWithDistance) {
  const scene::Fog f = constant_fog(150, Color(0.3, 0.5, 0.2));
  const Ray ray{{0, 0, 0}, {0, 0, 1}};
  EXPECT_NEAR(fog_transmittance(f, ray, 150), std::exp(-1.0), 1e-12);
  EXPECT_NEAR(fog_transmittance(f, ray, 75), std::exp(-0.5), 1e-12);
  // Seen colour mixed with the fog colour by the transmittance.
  const Color out = apply_fogs({f}, ray, 150, Color(1, 0, 0));
  const double t = std::exp(-1.0);
  EXPECT_NEAR(out.r, t * 1 + (1 - t) * 0.3, 1e-12);
  EXPECT_NEAR(out.g, (1 - t) * 0.5, 1e-12);
}

TEST(FogTest, SkyIsCompletelyFogged) {
  const scene::Fog f = constant_fog(150, Color(0.3, 0.5, 0.2));
  const Color out = apply_fogs({f}, Ray{{0, 0, 0}, {0, 1, 0}}, math::kInfinity, Color(0, 0, 1));
  EXPECT_NEAR(out.r, 0.3, 1e-12);
  EXPECT_NEAR(out.b, 0.2, 1e-12);
}

TEST(FogTest, TransmitLetsThatMuchThroughUnfogged) {
  scene::Fog f = constant_fog(1, Color(1));
  f.color.transmit = 0.4;
  const Color out = apply_fogs({f}, Ray{{0, 0, 0}, {1, 0, 0}}, math::kInfinity, Color(0));
  EXPECT_NEAR(out.r, 0.6, 1e-12);  // transmittance floored at 0.4: 60% fog colour over black
}

TEST(FogTest, FogWithoutDistanceDoesNothing) {
  const scene::Fog f = constant_fog(0, Color(1));
  EXPECT_EQ(apply_fogs({f}, Ray{{0, 0, 0}, {1, 0, 0}}, 100, Color(0.2)), Color(0.2));
}

TEST(FogTest, GroundFogFollowsItsHeightProfile) {
  scene::Fog f = constant_fog(10, Color(1));
  f.type = scene::Fog::Type::ground;
  f.offset = 2;
  f.altitude = 3;
  // Below the offset ground fog is as dense as constant fog.
  EXPECT_NEAR(fog_transmittance(f, Ray{{0, 1, 0}, {1, 0, 0}}, 10), std::exp(-1.0), 1e-12);
  // A level ray at height y above it sees density 1 / (1 + ((y - offset) / alt)^2).
  const double h = (8.0 - 2.0) / 3.0;
  EXPECT_NEAR(fog_transmittance(f, Ray{{0, 8, 0}, {1, 0, 0}}, 10), std::exp(-1.0 / (1 + h * h)), 1e-12);
  // A vertical ray from the offset up to height alt above it: mean density atan(1) / 1.
  EXPECT_NEAR(fog_transmittance(f, Ray{{0, 2, 0}, {0, 1, 0}}, 3), std::exp(-3 * std::atan(1.0) / 10), 1e-12);
}

}  // namespace
}  // namespace snell::render
