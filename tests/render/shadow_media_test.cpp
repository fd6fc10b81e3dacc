// Light reaching a surface through media inside transparent solids (POV-Ray 3.7 trace.cpp,
// ComputeShadowColour), against Beer-Lambert: exp(-absorption x length inside the solid).
#include <gtest/gtest.h>

#include <cmath>

#include "scene_builder.hpp"
#include "snell/accel/accelerator.hpp"
#include "snell/render/whitted.hpp"

namespace snell::render {
namespace {

using math::Color;
using math::Vec3;

/// A white floor at y = 0 (diffuse 1, no ambient) under a clear hollow sphere of radius 5 at height 10
/// holding absorbing media of 0.1 per unit; one light straight above the floor's origin.
scene::Scene floor_under_a_cloud(const Vec3& light, bool media_attenuation) {
  scene::Scene s;
  material::Finish matte;
  matte.ambient = Color(0);
  matte.diffuse = 1;
  s.objects.push_back(
      test::object(std::make_shared<geometry::Plane>(Vec3(0, 1, 0), 0), test::texture({Color(1)}, matte)));
  material::Finish clear;
  clear.ambient = Color(0);
  clear.diffuse = 0;
  auto cloud = test::object(std::make_shared<geometry::Sphere>(Vec3(0, 10, 0), 5.0),
                            test::texture({Color(1), 1.0, 0.0}, clear));
  auto interior = std::make_shared<material::Interior>();
  material::Media absorbing;
  absorbing.absorption = Color(0.1);
  interior->media.push_back(absorbing);
  cloud->interior = interior;
  cloud->flags.hollow = true;
  s.objects.push_back(cloud);
  scene::Light l = test::point_light(light);
  l.media_attenuation = media_attenuation;  // governs the atmosphere only
  s.lights.push_back(l);
  return s;
}

double floor_brightness(const scene::Scene& s) {
  const auto accel = accel::make_accelerator("none", s);
  WhittedIntegrator w(s, *accel);
  TraceContext ctx;
  // Looking down at the floor's origin from the side, clear of the sphere.
  const Vec3 eye(0, 3, -4);
  return w.trace_camera_ray({eye, normalize(Vec3(0, 0, 0) - eye)}, ctx).g;
}

TEST(ShadowMediaTest, LightThroughACloudIsThinnedByItsWholeDiameter) {
  // 10 units inside the sphere: exp(-1), whether or not the light has media_attenuation.
  EXPECT_NEAR(floor_brightness(floor_under_a_cloud({0, 30, 0}, true)), std::exp(-1.0), 1e-6);
  EXPECT_NEAR(floor_brightness(floor_under_a_cloud({0, 30, 0}, false)), std::exp(-1.0), 1e-6);
}

TEST(ShadowMediaTest, LightInsideTheCloudIsThinnedFromWhereTheRayEnters) {
  // The light at the sphere's centre: 5 units of media between it and the floor.
  EXPECT_NEAR(floor_brightness(floor_under_a_cloud({0, 10, 0}, true)), std::exp(-0.5), 1e-6);
}

TEST(ShadowMediaTest, LightBesideTheCloudIsNotThinned) {
  // The shadow ray misses the sphere: N.L times the light, 1 at the floor's origin for a light straight
  // above.
  scene::Scene s = floor_under_a_cloud({0, 30, 0}, true);
  s.objects.pop_back();
  EXPECT_NEAR(floor_brightness(s), 1.0, 1e-6);
}

}  // namespace
}  // namespace snell::render
