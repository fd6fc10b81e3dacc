// Area light sampling: POV-Ray's grid layout (reference "Area Lights") and its adaptive subdivision
// (trace.cpp, TraceAreaLightSubsetShadowRay), checked with shadow functions whose answers are known.
#include "snell/render/area_light.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace snell::render {
namespace {

using math::Color;
using math::Vec3;

scene::Light grid_light(int n1, int n2) {
  scene::Light l;
  l.area = true;
  l.axis1 = {4, 0, 0};
  l.axis2 = {0, 0, 2};
  l.size1 = n1;
  l.size2 = n2;
  return l;
}

TEST(AreaLightTest, GridSpansTheAxesCentredOnTheLight) {
  const scene::Light l = grid_light(5, 3);
  const Vec3 first = area_light_offset(l, l.axis1, l.axis2, 0, 0);
  const Vec3 last = area_light_offset(l, l.axis1, l.axis2, 4, 2);
  const Vec3 middle = area_light_offset(l, l.axis1, l.axis2, 2, 1);
  EXPECT_NEAR(first.x, -2, 1e-12);
  EXPECT_NEAR(first.z, -1, 1e-12);
  EXPECT_NEAR(last.x, 2, 1e-12);
  EXPECT_NEAR(last.z, 1, 1e-12);
  EXPECT_NEAR(length(middle), 0, 1e-12);
  // A single point along an axis sits on the centre line.
  const scene::Light line = grid_light(1, 3);
  EXPECT_NEAR(area_light_offset(line, line.axis1, line.axis2, 0, 2).x, 0, 1e-12);
}

TEST(AreaLightTest, CircularLightPutsTheOuterRingOnACircle) {
  scene::Light l = grid_light(5, 5);
  l.axis2 = {0, 0, 4};
  l.circular = true;
  // Every point of the outer square ring lands on the circle of radius 2 (half the axis), to within the
  // 0.001 shift POV-Ray uses to keep the centre away from 0/0.
  for (int u = 0; u < 5; ++u)
    for (int v : {0, 4}) EXPECT_NEAR(length(area_light_offset(l, l.axis1, l.axis2, u, v)), 2.0, 0.01);
}

TEST(AreaLightTest, OrientTurnsTheLightSquareToTheRay) {
  scene::Light l = grid_light(3, 3);
  l.orient = true;
  const Vec3 to_light = normalize(Vec3(1, 2, -1));
  const auto [a1, a2] = area_light_axes(l, to_light);
  EXPECT_NEAR(dot(a1, to_light), 0, 1e-12);
  EXPECT_NEAR(dot(a2, to_light), 0, 1e-12);
  EXPECT_NEAR(length(a1), 4, 1e-12);
  EXPECT_NEAR(length(a2), 4, 1e-12);
}

TEST(AreaLightTest, UnblockedLightTestsOnlyTheCornersWithoutAdaptive) {
  const scene::Light l = grid_light(17, 17);
  math::Pcg32 rng(1);
  int calls = 0;
  const Color c = area_light_shadow(l, l.axis1, l.axis2, rng, [&](const Vec3&) {
    ++calls;
    return Color(0.5, 0.25, 1);
  });
  EXPECT_EQ(calls, 4);  // corners agree, so POV-Ray's adaptive 0 looks no further
  EXPECT_EQ(c, Color(0.5, 0.25, 1));
}

TEST(AreaLightTest, AdaptiveLevelForcesSubdivisionAndTestsEachPointOnce) {
  scene::Light l = grid_light(5, 5);
  l.adaptive = 5;
  math::Pcg32 rng(1);
  int calls = 0;
  area_light_shadow(l, l.axis1, l.axis2, rng, [&](const Vec3&) {
    ++calls;
    return Color(1);
  });
  EXPECT_EQ(calls, 25);
}

TEST(AreaLightTest, BlockedColumnWeighsAsPovRayAveragesQuarters) {
  // 3x3 grid with the u = 0 column blocked: the four 2x2 quarters average their corners, so the two
  // quarters touching that column give 1/2 and the others 1: mean 3/4 (not the 2/3 of the points).
  const scene::Light l = grid_light(3, 3);
  math::Pcg32 rng(1);
  const Color c = area_light_shadow(l, l.axis1, l.axis2, rng,
                                    [&](const Vec3& o) { return o.x < -1 ? Color(0) : Color(1); });
  EXPECT_NEAR(c.r, 0.75, 1e-12);
}

TEST(AreaLightTest, JitteredPenumbraConvergesToTheUnblockedFraction) {
  // A straight edge hides the part of a square light with x < 0.6 (axis1 spans -2..2): 35% is visible.
  // With jitter and a fine grid, the mean approaches that fraction; the error falls as the grid grows.
  double previous_error = 1;
  for (const int n : {5, 17, 65}) {
    scene::Light l = grid_light(n, n);
    l.jitter = true;
    l.adaptive = 10;
    math::Pcg32 rng(42);
    const Color c = area_light_shadow(l, l.axis1, l.axis2, rng,
                                      [&](const Vec3& o) { return o.x < 0.6 ? Color(0) : Color(1); });
    const double error = std::fabs(c.r - 0.35);
    EXPECT_LT(error, previous_error + 0.01) << n;
    previous_error = error;
  }
  EXPECT_LT(previous_error, 0.02);
}

TEST(AreaLightTest, JitterIsDeterministicForASeed) {
  scene::Light l = grid_light(9, 9);
  l.jitter = true;
  l.adaptive = 3;
  auto run = [&] {
    math::Pcg32 rng(99);
    return area_light_shadow(l, l.axis1, l.axis2, rng,
                             [](const Vec3& o) { return Color(o.x > 0.1 ? 1 : 0); });
  };
  EXPECT_EQ(run(), run());
}

}  // namespace
}  // namespace snell::render
